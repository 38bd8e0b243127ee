"""The measures of a volume drawn in a style (realdata.volumes in VTK, paraview.volumes in
ParaView's Volume representation): the share of the volume's region left as VTK draws it, the
comic's share of plain gradient, pixel art's palette, the sketch's tone against VTK's and the
line art's recall of the volume's outline.
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


def gradient_share(pixels, region):
    """The share of `region`'s pixels in a plain gradient: where the value (the largest channel)
    varies over the pixel's 7x7 neighbourhood by more than 3 levels (not a flat paper, tint or
    ink) and at most 48 (not a dot, a hatch line, an edge or an outline)."""
    value = pixels.max(axis=2).astype(np.float64)
    low, high = value.copy(), value.copy()
    for dy in range(-3, 4):
        for dx in range(-3, 4):
            shifted = np.roll(np.roll(value, dy, axis=0), dx, axis=1)
            low, high = np.minimum(low, shifted), np.maximum(high, shifted)
    spread = high - low
    return float(((spread > 3) & (spread <= 48))[region].mean()) if region.any() else 0.0


def measure(style, styled, plain, region, solid, background=None):
    """The style's measures in the volume's region; `solid`: where the volume's own opacity is
    at least 0.5; `background`: the view's background colour (0-255 RGB) when not white."""
    m = {"plain": float(np.mean(np.all(styled[region] == plain[region], axis=1)))}
    if style == "pixel":
        m["palette"] = in_palette(styled[region], background)
    if style == "comic":
        m["gradient"] = gradient_share(styled, region)
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
