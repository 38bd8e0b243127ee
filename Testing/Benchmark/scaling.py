#!/usr/bin/python3
"""How the line art, the sketch's model directions and figures scale with the triangle count
(issue 54): whole `vtkstylize` runs on a scan refined and tiled to about 75k, 300k, 1.2M, 4.8M
and 9.7M triangles.

    scaling.py VTKSTYLIZE SCAN.ply WORK_DIR OUTPUT.md [--sizes 0,1,2,3,3x2] [--size WxH]
               [--repeat N]
    scaling.py --from-log LOG WORK_DIR OUTPUT.md     (the table of a run cut short)

The meshes are made here (not committed): the scan Loop-subdivided 0 to 3 times (x4 triangles
each), and "3x2" two copies of the 3-times one side by side, written to WORK_DIR as binary PLY.
Per size, N rounds (default 3; medians reported: single runs here vary by a second or more at
1.2M triangles) of one run each at WxH (default 1280x720), in this order: `--style comic` (the
reference), `--style lines`, `--style lines --orbit 2` (the second frame: after a camera
change), `--style sketch --direction-source model`, and `--style lines` to an SVG figure. The
seconds and the peak resident size (wait4) of each run; the line art's first frame and its figure
as the extra time over the comic run; the frame after a camera change as the 2-frame orbit's
time less the 1-frame run's. Writes OUTPUT.md (the table and the log-log slopes from 300k up)
and OUTPUT.png (a log-log plot, matplotlib). Needs a display or Xvfb (vtkstylize starts one).
"""
import argparse
import math
import os
import resource
import subprocess
import sys
import time


def make_meshes(scan, work, sizes):
    """The meshes, made in a child process: the peak resident size a child reports (wait4)
    starts from its parent's at the fork, so this process stays small."""
    paths = {size: os.path.join(work, "scan-%s.ply" % size) for size in sizes}
    if not all(os.path.exists(p) for p in paths.values()):
        subprocess.run([sys.executable, __file__, "--make", scan, work, ",".join(sizes)],
                       check=True)
    return paths


def make_meshes_here(scan, work, sizes):
    from vtkmodules.vtkFiltersCore import (vtkAppendPolyData, vtkCleanPolyData,
                                           vtkTriangleFilter)
    from vtkmodules.vtkFiltersGeneral import vtkTransformPolyDataFilter
    from vtkmodules.vtkFiltersModeling import vtkLoopSubdivisionFilter
    from vtkmodules.vtkIOPLY import vtkPLYReader, vtkPLYWriter
    from vtkmodules.vtkCommonTransforms import vtkTransform
    reader = vtkPLYReader()
    reader.SetFileName(scan)
    triangles = vtkTriangleFilter()
    triangles.SetInputConnection(reader.GetOutputPort())
    clean = vtkCleanPolyData()
    clean.SetInputConnection(triangles.GetOutputPort())
    clean.Update()
    paths = {}
    for size in sizes:
        path = os.path.join(work, "scan-%s.ply" % size)
        paths[size] = path
        if os.path.exists(path):
            continue
        levels, copies = (size.split("x") + ["1"])[:2]
        mesh = clean.GetOutput()
        if int(levels):
            loop = vtkLoopSubdivisionFilter()
            loop.SetNumberOfSubdivisions(int(levels))
            loop.SetInputData(mesh)
            loop.Update()
            mesh = loop.GetOutput()
        if int(copies) > 1:
            append = vtkAppendPolyData()
            width = mesh.GetBounds()[1] - mesh.GetBounds()[0]
            for c in range(int(copies)):
                move = vtkTransform()
                move.Translate(1.1 * width * c, 0.0, 0.0)
                place = vtkTransformPolyDataFilter()
                place.SetTransform(move)
                place.SetInputData(mesh)
                place.Update()
                append.AddInputData(place.GetOutput())
            append.Update()
            mesh = append.GetOutput()
        writer = vtkPLYWriter()
        writer.SetFileName(path)
        writer.SetFileTypeToBinary()
        writer.SetInputData(mesh)
        writer.Write()
        print("made %s: %d triangles" % (path, mesh.GetNumberOfCells()), flush=True)
    return paths


def triangles_of(path):
    with open(path, "rb") as f:
        for line in f.read(4096).split(b"\n"):
            if line.startswith(b"element face"):
                return int(line.split()[2])
    return 0


def run(command):
    """Seconds and peak resident MiB of one run."""
    start = time.perf_counter()
    process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    _, status, usage = os.wait4(process.pid, 0)
    seconds = time.perf_counter() - start
    error = process.stderr.read().decode(errors="replace").strip()
    if os.waitstatus_to_exitcode(status) != 0:
        sys.exit("scaling.py: %s failed: %s" % (" ".join(command), error[-500:]))
    return seconds, usage.ru_maxrss / 1024.0


def median(values):
    values = sorted(values)
    n = len(values)
    return values[n // 2] if n % 2 else 0.5 * (values[n // 2 - 1] + values[n // 2])


def row(triangles, measures):
    """A table row from one size's runs: {name: [(seconds, peak MiB), one per repeat]}; the
    medians of the repeats, and the line art's first frame of each repeat (its runs against the
    comic run of the same round)."""
    def seconds(name):
        return median([m[0] for m in measures[name]])
    comic = seconds("comic")
    return {
        "triangles": triangles,
        "comic": comic,
        "lines first frame": seconds("lines") - comic,
        "lines first frame runs": [l[0] - c[0] for l, c in zip(measures["lines"],
                                                              measures["comic"])],
        "lines next frame": seconds("lines orbit 2") - seconds("lines"),
        "sketch model first frame": seconds("sketch model") - comic,
        "lines svg": seconds("lines svg") - comic,
        "peak MiB": max(m[1] for runs in measures.values() for m in runs),
    }


def report(rows, output, image, repeats):
    curves = ["comic", "lines first frame", "lines next frame", "sketch model first frame",
              "lines svg", "peak MiB"]

    def slope(curve):
        points = [(math.log(r["triangles"]), math.log(max(r[curve], 1e-3))) for r in rows
                  if r["triangles"] >= 250000]
        if len(points) < 2:
            return float("nan")
        n = len(points)
        mx = sum(p[0] for p in points) / n
        my = sum(p[1] for p in points) / n
        return sum((p[0] - mx) * (p[1] - my) for p in points) / \
            sum((p[0] - mx) ** 2 for p in points)
    with open(output, "w") as f:
        f.write("| triangles | comic run (s) | line art first frame (s, over comic) | per round "
                "(s) | line art after a camera change (s) | sketch, model directions (s, over "
                "comic) | line-art SVG (s, over comic) | peak resident (MiB) |\n")
        f.write("|---:|---:|---:|---:|---:|---:|---:|---:|\n")
        for r in rows:
            f.write("| {:,} | {:.1f} | {:.1f} | {} | {:.1f} | {:.1f} | {:.1f} | {:,.0f} |\n".format(
                r["triangles"], r["comic"], r["lines first frame"],
                ", ".join("%.1f" % v for v in r["lines first frame runs"]),
                r["lines next frame"], r["sketch model first frame"], r["lines svg"],
                r["peak MiB"]))
        f.write("\nLog-log slopes from 300k triangles up: " + ", ".join(
            "%s %.2f" % (c, slope(c)) for c in curves) + ".\n")
        f.write("\n%s, the median of %d rounds per cell (each round runs every configuration "
                "once), vtkstylize --size %s.\n" % (time.strftime("%Y-%m-%d"), repeats, image))
    print(open(output).read())
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        figure, axes = plt.subplots(figsize=(7, 4.5))
        for c in curves[:-1]:
            axes.loglog([r["triangles"] for r in rows], [max(r[c], 1e-2) for r in rows],
                        marker="o", label="%s (slope %.2f)" % (c, slope(c)))
        axes.set_xlabel("triangles")
        axes.set_ylabel("seconds")
        axes.grid(True, which="both", alpha=0.3)
        axes.legend(fontsize=8)
        figure.tight_layout()
        figure.savefig(output[:-3] + ".png" if output.endswith(".md") else output + ".png",
                       dpi=110)
    except ImportError:
        print("(matplotlib is not installed: no plot)")



def main():
    if sys.argv[1:2] == ["--make"]:
        make_meshes_here(sys.argv[2], sys.argv[3], sys.argv[4].split(","))
        return
    parser = argparse.ArgumentParser(description="Scaling of the line art, the sketch's model "
                                     "directions and figures (issue 54).")
    parser.add_argument("--sizes", default="0,1,2,3,3x2",
                        help="Loop subdivision levels, LxN for N copies (default 0,1,2,3,3x2)")
    parser.add_argument("--size", default="1280x720", help="image size (default 1280x720)")
    parser.add_argument("--repeat", type=int, default=3,
                        help="rounds per size, medians reported (default 3)")
    parser.add_argument("--from-log", metavar="LOG",
                        help="the table of a run cut short: LOG WORK_DIR OUTPUT.md")
    parser.add_argument("paths", nargs="+",
                        help="VTKSTYLIZE SCAN.ply WORK_DIR OUTPUT.md (or, with --from-log, "
                        "WORK_DIR OUTPUT.md)")
    options = parser.parse_args()
    sizes, image, args = options.sizes.split(","), options.size, options.paths
    if options.from_log:
        # (the table of a run cut short: its printed lines, the sizes it finished)
        work, output = args
        found = {}
        for line in open(options.from_log):
            parts = line.split(":")
            if len(parts) == 2 and line.strip().endswith("MiB"):
                size, name = parts[0].split(" ", 1)
                seconds, mib = parts[1].replace("s,", "").replace("MiB", "").split()
                found.setdefault(size, {}).setdefault(name, []).append(
                    (float(seconds), float(mib)))
        rows = [row(triangles_of(os.path.join(work, "scan-%s.ply" % size)), m)
                for size, m in found.items() if len(m) == 5]
        report(rows, output, image, max(len(r) for m in found.values() for r in m.values()))
        return
    program, scan, work, output = args
    os.makedirs(work, exist_ok=True)
    paths = make_meshes(scan, work, sizes)
    rows = []
    for size in sizes:
        path = paths[size]
        out = os.path.join(work, "out-" + size)
        base = [program, "--size", image]
        measures = {}
        for _ in range(max(1, options.repeat)):
            for name, extra, target in (
                    ("comic", ["--style", "comic"], out + "-comic.png"),
                    ("lines", ["--style", "lines"], out + "-lines.png"),
                    ("lines orbit 2", ["--style", "lines", "--orbit", "2"], out + "-orbit.png"),
                    ("sketch model", ["--style", "sketch", "--direction-source", "model"],
                     out + "-sketch.png"),
                    ("lines svg", ["--style", "lines"], out + "-lines.svg")):
                measured = run(base + extra + ["--output", target, path])
                measures.setdefault(name, []).append(measured)
                print("%s %s: %.1f s, %.0f MiB" % (size, name, *measured), flush=True)
        rows.append(row(triangles_of(path), measures))
    report(rows, output, image, max(1, options.repeat))


if __name__ == "__main__":
    main()
