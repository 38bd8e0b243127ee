#!/usr/bin/python3
"""The cost of reading in an isolated process (vtkStylizeReader's Isolated, issue 39).

    read_isolation.py VTKSTYLIZE OUTPUT.md FILE... [--repeats N] [--size WxH]

For every FILE, alternating in one run, each in a fresh process: vtkStylizeReader with Isolated
on and off (the read alone: median seconds; the largest resident size of the calling process
and, isolated, of the reading child), and the whole `vtkstylize --style comic --size WxH` run
(read plus render). The isolation's cost is the difference of the read medians, as a share of
the program's median run less that difference (the read plus render without isolation).
Needs the build's Python package on PYTHONPATH (the reader) and a display for vtkstylize.
"""
import os
import resource
import statistics
import subprocess
import sys
import time

MEASURE = r"""
import resource, sys, time
from vtkstylize import vtkStylizeReader
reader = vtkStylizeReader()
reader.SetFileName(sys.argv[1])
reader.SetIsolated(sys.argv[2] == "on")
start = time.perf_counter()
reader.Update()
seconds = time.perf_counter() - start
assert not reader.GetErrorMessage(), reader.GetErrorMessage()
own = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
child = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss
print(seconds, own, child)
"""


def read_once(path, isolated):
    out = subprocess.run([sys.executable, "-c", MEASURE, path, "on" if isolated else "off"],
                         check=True, capture_output=True, text=True).stdout.split()
    return float(out[0]), int(out[1]) / 1024.0, int(out[2]) / 1024.0


def program_once(exe, path, size, output):
    start = time.perf_counter()
    subprocess.run([exe, "--style", "comic", "--size", size, "--output", output, path],
                   check=True, capture_output=True)
    return time.perf_counter() - start


def main():
    args = sys.argv[1:]
    repeats, size = 5, "800x600"
    for flag in ("--repeats", "--size"):
        if flag in args:
            i = args.index(flag)
            value = args[i + 1]
            del args[i:i + 2]
            if flag == "--repeats":
                repeats = int(value)
            else:
                size = value
    if len(args) < 3:
        sys.exit(__doc__)
    exe, report, files = args[0], args[1], args[2:]
    rows = []
    for path in files:
        on, off, runs = [], [], []
        for _ in range(repeats):
            on.append(read_once(path, True))
            off.append(read_once(path, False))
            runs.append(program_once(exe, path, size, report + ".png"))
        t_on = statistics.median(r[0] for r in on)
        t_off = statistics.median(r[0] for r in off)
        run = statistics.median(runs)
        cost = t_on - t_off
        rows.append((os.path.basename(path), os.path.getsize(path) / 2**20, t_off, t_on,
                     run, 100.0 * cost / max(run - cost, 1e-9),
                     max(r[1] for r in off), max(r[1] for r in on), max(r[2] for r in on)))
        print(rows[-1], flush=True)
    if os.path.exists(report + ".png"):
        os.remove(report + ".png")
    with open(report, "w") as f:
        f.write("| file | MiB | read in process (s) | read isolated (s) | vtkstylize run (s) "
                "| isolation's cost (% of read + render) | peak RSS in process (MiB) "
                "| peak RSS isolated: caller / child (MiB) |\n")
        f.write("|---|---:|---:|---:|---:|---:|---:|---:|\n")
        for r in rows:
            f.write(f"| {r[0]} | {r[1]:.1f} | {r[2]:.3f} | {r[3]:.3f} | {r[4]:.2f} | {r[5]:+.1f} "
                    f"| {r[6]:.0f} | {r[7]:.0f} / {r[8]:.0f} |\n")
        f.write(f"\nMedians of {repeats} runs (alternating), vtkstylize --style comic --size "
                f"{size}; {resource.getpagesize()} B pages.\n")


if __name__ == "__main__":
    main()
