"""The measures of a volume drawn in a style (realdata.volumes in VTK, paraview.volumes in
ParaView's Volume representation): the share of the volume's region left as VTK draws it, pixel
art's palette, the sketch's tone against VTK's and the line art's recall of the volume's outline.
"""
import numpy as np

from stylize_png import luminance, near


def blur(a, radius):
    """A box blur of `radius` pixels, applied twice (about a Gaussian)."""
    out = a.astype(np.float64)
    for _ in range(2):
        for axis in (0, 1):
            c = np.cumsum(np.pad(out, [(radius + 1, radius) if i == axis else (0, 0)
                                       for i in range(2)], mode="edge"), axis=axis)
            n = out.shape[axis]
            hi = np.take(c, np.arange(2 * radius + 1, 2 * radius + 1 + n), axis=axis)
            lo = np.take(c, np.arange(0, n), axis=axis)
            out = (hi - lo) / (2 * radius + 1)
    return out


def in_palette(pixels, background=None):
    """The share of `pixels` (N x 3) in PALETTE16, its black outline ink, the white paper or the
    view's `background` (0-255 RGB, where the scene's background shows)."""
    from vtkstylize import vtkPixelArtPass
    extra = [[0, 0, 0], [255, 255, 255]] + ([list(background)] if background is not None else [])
    palette = np.vstack([np.array(vtkPixelArtPass.GetPalette16()).reshape(16, 3) * 255,
                         extra]).round()
    px = pixels.astype(np.float64)
    dist = np.min(np.abs(px[:, None, :] - palette[None, :, :]).max(axis=2), axis=1)
    return float(np.mean(dist <= 1.0)) if len(px) else 1.0


def measure(style, styled, plain, region, solid, background=None):
    """The style's measures in the volume's region; `solid`: where the volume's own opacity is
    at least 0.5; `background`: the view's background colour (0-255 RGB) when not white."""
    m = {"plain": float(np.mean(np.all(styled[region] == plain[region], axis=1)))}
    if style == "pixel":
        m["palette"] = in_palette(styled[region], background)
    if style == "sketch":
        a = blur(luminance(styled), 4)[region]
        b = blur(luminance(plain), 4)[region]
        m["tone"] = float(np.corrcoef(a, b)[0, 1])
    if style == "lines":
        outline = solid & ~(np.roll(solid, 1, 0) & np.roll(solid, -1, 0) &
                            np.roll(solid, 1, 1) & np.roll(solid, -1, 1))
        ink = luminance(styled) < 128
        m["recall"] = float(np.mean(near(ink, 2)[outline])) if outline.any() else 0.0
    return m
