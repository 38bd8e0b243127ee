#!/usr/bin/env python3
"""Vector figures against the PNG: the real-data set drawn as SVG and PDF, rasterized back.

For each mesh and style it renders, with the vtkstylize program at the given size, the PNG and
the .svg and .pdf figures (vtkStylizeFigureWriter), rasterizes the figures back at the image's
size with Debian's rasterizers (rsvg-convert for SVG, pdftocairo for PDF) and compares them with
the PNG. It prints one row per figure: file size, the time vtkstylize took, the rasterizer's
time (a viewer opening it), SSIM and the pixels that differ. With --check it fails (exit 1)
unless comic, sketch and line art reach SSIM >= 0.95 and pixel art is identical (0 pixels differ), and
unless the figures hold vector content (dots, hatch lines, traced outlines, rectangles) rather
than one image (line art: its strokes as stroked paths from the geometry).

"pencil" is the sketch with --vector-pencil: its strokes are vector polylines traced anew, so
they cannot match the PNG's pixel for pixel; its figure must embed no image and follow the light
as the PNG does: the tone correlation with the Standard-lit image (realdata.py's measure) at
least 0.85 and at most 0.03 below the PNG's.

usage: figures.py VTKSTYLIZE DATADIR OUTDIR [--check] [--meshes a,b] [--size WxH]
                  [--styles comic,pixel,sketch,lines,pencil] [--annotations]
"""
import os
import re
import subprocess
import sys
import time

from vtkstylize_testing import vtkStylizeImageMetrics as M

import realdata

SSIM_MIN = 0.95
PENCIL_TONE_MIN, PENCIL_TONE_DROP = 0.85, 0.03
# what vtkstylize draws each style with
STYLE_OPTIONS = {"pencil": ["--style", "sketch", "--vector-pencil"]}


def read_png(path):
    """The PNG's RGB channels (an alpha channel left out), so that every image compares alike."""
    return realdata.read_png(path, rgb=True)


def run(cmd):
    start = time.perf_counter()
    result = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if result.returncode != 0:
        sys.exit("figures.py: %s failed: %s" % (" ".join(cmd), result.stderr.strip()))
    return time.perf_counter() - start, result.stderr


def rasterize(figure, png, width, height):
    if figure.endswith(".svg"):
        cmd = ["rsvg-convert", "-w", str(width), "-h", str(height), "-b", "white", figure, "-o", png]
    else:
        cmd = ["pdftocairo", "-png", "-singlefile", "-r", "72", figure, png[:-4]]
    seconds, _ = run(cmd)
    return seconds


def vector_content(figure):
    """Counts of the SVG's elements: paths, images (cairo writes an embedded image as <image>)."""
    text = open(figure, encoding="utf-8", errors="replace").read()
    return len(re.findall(r"<path", text)), len(re.findall(r"<image", text))


def main():
    parser = realdata.argument_parser(__doc__)
    parser.add_argument("--meshes", default="bunny,fandisk,rotor,vessel")
    parser.add_argument("--styles", default="comic,pixel,sketch,lines,pencil")
    parser.add_argument("--size", default="800x600")
    parser.add_argument("--annotations", action="store_true",
                        help="keep the title (vector text; compared like the rest)")
    args = parser.parse_args()
    os.makedirs(args.outdir, exist_ok=True)
    width, height = (int(v) for v in args.size.split("x"))
    failures = []
    print("%-8s %-6s %-4s %10s %8s %8s %7s %9s %6s %6s" % (
        "mesh", "style", "fmt", "bytes", "write s", "open s", "SSIM", "differ", "paths", "images"))
    for mesh in args.meshes.split(","):
        path = os.path.join(args.datadir, mesh + (".ex2" if mesh == "vessel" else ".ply"))
        mask = None
        for style in args.styles.split(","):
            common = [args.exe, "--quiet", "--size", args.size] + STYLE_OPTIONS.get(
                style, ["--style", style])
            if not args.annotations:
                common.append("--no-annotations")
            base = os.path.join(args.outdir, "%s-%s" % (mesh, style))
            run(common + ["--output", base + ".png", path])
            reference = read_png(base + ".png")
            if style == "pencil" and mask is None:
                masked = os.path.join(args.outdir, "%s-plain.png" % mesh)
                run(common[:4] + ["--no-annotations", "--style", "none", "--background", "1,0,1",
                                  "--output", masked, path])
                mask = realdata.read_png(masked)
                tone_png = M.ToneCorrelation(reference, mask, mask, realdata.KEY,
                                             realdata.BLUR_SIGMA)
            for fmt in ("svg", "pdf"):
                figure = base + "." + fmt
                seconds, _ = run(common + ["--output", figure, path])
                back = base + "-" + fmt + ".png"
                opening = rasterize(figure, back, width, height)
                image = read_png(back)
                ssim = M.SSIM(reference, image, 255.0)
                differ = M.CountDifferences(reference, image, 0.0)
                paths, images = vector_content(figure) if fmt == "svg" else (-1, -1)
                print("%-8s %-6s %-4s %10d %8.2f %8.2f %7.4f %9d %6s %6s" % (
                    mesh, style, fmt, os.path.getsize(figure), seconds, opening, ssim, differ,
                    paths if paths >= 0 else "-", images if images >= 0 else "-"))
                sys.stdout.flush()
                name = "%s %s .%s" % (mesh, style, fmt)
                if style == "pixel" and not args.annotations and differ != 0:
                    failures.append("%s: %d pixels differ from the PNG (must be identical)" % (name, differ))
                if style == "pencil":
                    tone = M.ToneCorrelation(image, mask, mask, realdata.KEY, realdata.BLUR_SIGMA)
                    print("         pencil tone correlation: figure %.3f, PNG %.3f" % (tone, tone_png))
                    if tone < PENCIL_TONE_MIN or tone < tone_png - PENCIL_TONE_DROP:
                        failures.append("%s: tone correlation %.3f (PNG %.3f; at least %.2f and "
                                        "%.2f below the PNG)" % (name, tone, tone_png,
                                                                 PENCIL_TONE_MIN, PENCIL_TONE_DROP))
                elif style != "pixel" and ssim < SSIM_MIN:
                    failures.append("%s: SSIM %.4f < %.2f" % (name, ssim, SSIM_MIN))
                if fmt == "svg":
                    need = {"comic": 50, "pixel": 2, "sketch": 1, "lines": 10, "pencil": 4}[style]
                    if paths < need:
                        failures.append("%s: %d vector paths (at least %d expected)" % (name, paths, need))
                    if style != "sketch" and images > 0:
                        failures.append("%s: embeds %d images (expected vector only)" % (name, images))
    return realdata.exit_status(failures, args.check)


if __name__ == "__main__":
    sys.exit(main())
