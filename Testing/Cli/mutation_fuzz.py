#!/usr/bin/python3
"""A deterministic mutation fuzzer of vtkstylize's readers (issue 39).

    mutation_fuzz.py [--seed S] [--cases N] [--jobs J] [--time-limit SECONDS] [--style NAME]
                     [--size WxH] [--rss-kill MB] [--only K,K...] [--formats L,L...] [--gdb]
                     PROGRAM DATA_DIR WORK_DIR

PROGRAM is vtkstylize; DATA_DIR the command-line tests' data (cli.setup.data). WORK_DIR is
emptied, then holds seeds/ (the valid files mutated), out/ and failures/.

Seeds: small valid files of every format vtkstylize reads: from DATA_DIR (the .vtm, .pvtu and
.pvd with the files they name, legacy polydata ascii and binary, unstructured and structured
points binary, Exodus as .ex2 .exo .e .g, EnSight, OpenFOAM, STL ascii and binary, OBJ, PLY
ascii and binary) and written here with VTK's writers (Debian's python3-vtk9): .vtp .vtu .vts
.vtr .vti appended raw, inline base64 and zlib-compressed appended (and a .vtu in ascii), the
parallel .pvtp .pvti .pvts .pvtr with their pieces, and legacy files (version 4.2 polydata and
unstructured grids; structured and rectilinear grids and structured points, ascii and binary).

Case K (deterministic: its choices come from a generator seeded by "S:K" alone, so a case is the
same whatever --cases, --jobs or --only) copies seed file K mod (number of seed files; --formats
keeps those of the labels given, as the table names them) with the files it names into a
folder, picks the file to mutate (the named one, or for a file naming others sometimes one of
those) and applies 1 to 3 mutations: flip 1-16 bytes; insert a random chunk;
delete a chunk; duplicate a chunk (its copy inserted after it); replace a number by an extreme
(0, -1, 2^31-1, 2^31, 2^32-1, 2^63-1, 1e308, nan, inf, a huge one): a decimal token in text, or
in a binary file a header's token or a 4- or 8-byte integer or float at an aligned offset of its
binary part; truncate. It runs `PROGRAM --style comic --size 160x120 --output OUT FILE` in that
folder, two at a time, with a time bound (30 s) and no address-space bound: its peak resident
size comes from wait4 (ru_maxrss). A run whose resident size passes --rss-kill (4096 MB; 0: no
bound) is killed (this machine's memory is shared). A case is:
- render: exit 0 and the PNG; refusal: exit 1 or 2, exactly one stderr line starting with
  "vtkstylize: ", no output and no temporary file left;
- crash: a signal, "internal error", or an exit status other than 0, 1 or 2;
- hang: the time bound; memory: a peak resident size over 1 GiB (3 GiB under AddressSanitizer;
  the input is under 1 MB);
- partial file: an output or a temporary file left after a failure; bad refusal: a failure
  whose message is not one "vtkstylize: " line (lines as Python's splitlines counts them: a
  message quoting the file's bytes 0x1c-0x1e is more than one); bad render: exit 0, no PNG.
Each but render and refusal fails: its folder is kept as WORK_DIR/failures/caseK-KIND-SEED with
REPRO.txt (the seed, the mutations, the command line, stderr) and repro.sh; with --gdb, a
crash's backtrace (gdb -batch) in backtrace.txt. A refusal of the reader's isolation (VTK's
reader crashed in the child process, or passed its memory or time limit) passes, and is kept
likewise in WORK_DIR/contained/. The script prints the counts per kind and per seed, the largest
peak resident size, the cases per second and the failures; its exit status is 1 if any failed.
"""
import argparse
import os
import re
import shlex
import shutil
import struct
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from corpus_common import (SANITIZED, bounded_child, classify, is_png, leftovers,  # noqa: E402
                           remove, rng, run_bounded, write_parallel)

parser = argparse.ArgumentParser(usage=__doc__.split("\n\n")[1])
parser.add_argument("--seed", default="39")
parser.add_argument("--cases", type=int, default=1000)
parser.add_argument("--jobs", type=int, default=2)
parser.add_argument("--time-limit", type=float, default=30.0)
parser.add_argument("--style", default="comic")
parser.add_argument("--size", default="160x120")
parser.add_argument("--rss-kill", type=int, default=4096, help="MB; 0: none")
parser.add_argument("--only", help="case numbers, comma-separated")
parser.add_argument("--formats", help="seed files' labels (ply-binary,vtp-zlib...)")
parser.add_argument("--gdb", action="store_true", help="save each crash's backtrace")
parser.add_argument("program")
parser.add_argument("data")
parser.add_argument("work")
args = parser.parse_args()
sys.stdout.reconfigure(errors="backslashreplace")  # (messages quote mutated bytes)
exe, data, work = (os.path.abspath(a) for a in (args.program, args.data, args.work))
MEMORY_KB = (3 if SANITIZED else 1) << 20  # 1 GiB (AddressSanitizer's shadow memory: 3)
PASSING = ("render", "refusal")
# A refusal of the reader's isolation (a child process that crashed or passed its limits): it
# passes, and its folder is kept in WORK_DIR/contained/ all the same.
CAUGHT = re.compile(r"VTK's reader crashed|the reader's (time )?limit")
KINDS = ("render", "refusal", "crash", "hang", "memory", "partial file", "bad refusal",
         "bad render")

shutil.rmtree(work, ignore_errors=True)
seeds_root, cases_root, outputs, failures, contained = (
    os.path.join(work, d) for d in ("seeds", "cases", "out", "failures", "contained"))
for d in (seeds_root, cases_root, outputs, failures, contained):
    os.makedirs(d)


# ---- seeds --------------------------------------------------------------------------------------
FROM_DATA = (  # label, file or folder in DATA_DIR, name given, files it names
    ("vtm", "blocks.vtm", "blocks.vtm", ["blocks"]),
    ("pvtu", "pieces.pvtu", "pieces.pvtu", ["pieces_0.vtu", "pieces_1.vtu"]),
    ("pvd", "series.pvd", "series.pvd", ["series_0.vtu", "series_1.vtu", "series_2.vtp"]),
    ("vtk-polydata-ascii", "sphere_ascii.vtk", "sphere_ascii.vtk", []),
    ("vtk-polydata-binary", "sphere_binary.vtk", "sphere_binary.vtk", []),
    ("vtk-unstructured-binary", "hexes.vtk", "hexes.vtk", []),
    ("vtk-points-binary", "wavelet.vtk", "wavelet.vtk", []),
    ("ex2", "mesh.ex2", "mesh.ex2", []), ("exo", "mesh.ex2", "mesh.exo", []),
    ("e", "mesh.ex2", "mesh.e", []), ("g", "mesh.ex2", "mesh.g", []),
    ("case", "ensight.case", "ensight.case", ["ensight.geo", "ensight.Temperature"]),
    ("foam", "foam", "case.foam", []),
    ("stl-ascii", "sphere_ascii.stl", "sphere_ascii.stl", []),
    ("stl-binary", "sphere_binary.stl", "sphere_binary.stl", []),
    ("obj", "sphere.obj", "sphere.obj", []),
    ("ply-ascii", "colored.ply", "colored.ply", []),
    ("ply-binary", "sphere.ply", "sphere.ply", []),
    ("ply-binary-strips", "strips_binary.ply", "strips_binary.ply", []))
XML_SOURCES = ("sphere.vtp", "hexes.vtu", "sheet.vts", "grid.vtr", "wavelet.vti")
LEGACY = (  # label, XML source, binary, file version
    ("vtk-polydata-ascii-4.2", "sphere.vtp", False, 42),
    ("vtk-polydata-binary-4.2", "sphere.vtp", True, 42),
    ("vtk-unstructured-ascii", "hexes.vtu", False, 51),
    ("vtk-unstructured-binary-4.2", "hexes.vtu", True, 42),
    ("vtk-structured-ascii", "sheet.vts", False, 51),
    ("vtk-structured-binary", "sheet.vts", True, 51),
    ("vtk-rectilinear-ascii", "grid.vtr", False, 51),
    ("vtk-rectilinear-binary", "grid.vtr", True, 51),
    ("vtk-points-ascii", "wavelet.vti", False, 51))


def write_seeds():
    """[(label, folder, file)] in a fixed order."""
    import vtk  # Debian's python3-vtk9
    seeds = []

    def folder(label, main):
        seeds.append((label, os.path.join(seeds_root, label), main))
        os.makedirs(seeds[-1][1])
        return seeds[-1][1]

    for label, source, name, named in FROM_DATA:
        d = folder(label, name)
        if os.path.isdir(os.path.join(data, source)):  # (OpenFOAM: the case folder)
            shutil.copytree(os.path.join(data, source), d, dirs_exist_ok=True)
        else:
            shutil.copyfile(os.path.join(data, source), os.path.join(d, name))
        for n in named:
            (shutil.copytree if os.path.isdir(os.path.join(data, n)) else shutil.copyfile)(
                os.path.join(data, n), os.path.join(d, n))
    read = {}
    for source in XML_SOURCES:
        reader = vtk.vtkXMLGenericDataObjectReader()
        reader.SetFileName(os.path.join(data, source))
        reader.Update()
        read[source] = reader.GetOutput()
        stem, ext = os.path.splitext(source)
        for encoding in ("raw", "base64", "zlib") + (("ascii",) if ext == ".vtu" else ()):
            d = folder("%s-%s" % (ext[1:], encoding), stem + ext)
            writer = vtk.vtkXMLDataSetWriter()
            writer.SetInputData(read[source])
            writer.SetFileName(os.path.join(d, stem + ext))
            {"raw": writer.SetDataModeToAppended, "zlib": writer.SetDataModeToAppended,
             "base64": writer.SetDataModeToBinary, "ascii": writer.SetDataModeToAscii}[encoding]()
            writer.SetEncodeAppendedData(False)
            (writer.SetCompressorTypeToZLib if encoding == "zlib" else
             writer.SetCompressorTypeToNone)()
            writer.Write()
    parallel = os.path.join(work, "parallel")
    os.makedirs(parallel)
    write_parallel(parallel)
    for ext in (".pvtp", ".pvti", ".pvts", ".pvtr"):
        d = folder(ext[1:], "parallel" + ext)
        for f in os.listdir(parallel):
            if f == "parallel" + ext or f.endswith("." + ext[2:]):
                shutil.copyfile(os.path.join(parallel, f), os.path.join(d, f))
    shutil.rmtree(parallel)
    for label, source, binary, version in LEGACY:
        d = folder(label, label + ".vtk")
        writer = vtk.vtkDataSetWriter()
        writer.SetInputData(read[source])
        writer.SetFileName(os.path.join(d, label + ".vtk"))
        writer.SetFileType(2 if binary else 1)  # VTK_BINARY, VTK_ASCII
        writer.SetFileVersion(version)
        writer.Write()
    return seeds


# ---- mutations ----------------------------------------------------------------------------------
TOKEN = re.compile(rb"(?<![\w.+-])-?\d+(?:\.\d+)?(?:[eE][-+]?\d+)?(?![\w.])")
TEXT_EXTREMES = (b"0", b"-1", b"2147483647", b"2147483648", b"4294967295", b"9223372036854775807",
                 b"-2147483648", b"18446744073709551616", b"1e308", b"1e400", b"nan", b"inf",
                 b"-inf")
INT_EXTREMES = (0, -1, 2 ** 31 - 1, 2 ** 31, 2 ** 32 - 1, 2 ** 63 - 1)
FLOAT_EXTREMES = {4: (3.4e38, float("nan"), float("inf"), -float("inf")),
                  8: (1e308, float("nan"), float("inf"), -float("inf"))}


def binary_start(content):
    """Where a file's binary part begins: after a PLY header, an XML file's appended-data mark,
    a legacy file's POINTS line; else 0."""
    for mark, then in ((b"end_header\n", b""), (b"<AppendedData", b"_"), (b"\nPOINTS ", b"\n")):
        at = content.find(mark)
        if at >= 0:
            at += len(mark)
            return at if not then else content.find(then, at) + 1
    return 0


def replace_number(r, c):
    binary = b"\0" in c
    start = binary_start(c) if binary else len(c)
    tokens = list(TOKEN.finditer(c[:start] if start else c[:1024]))
    if tokens and (not binary or r.random() < 0.5):
        m = r.choice(tokens)
        value = r.choice(TEXT_EXTREMES)
        return (c[:m.start()] + value + c[m.end():],
                "number %r at %d replaced by %s" % (m.group().decode(), m.start(), value.decode()))
    width, order = r.choice((4, 8)), r.choice("<>")
    slots = (len(c) - start) // width
    if slots <= 0:
        return c, "no number to replace"
    at = start + width * r.randrange(slots)
    if r.random() < 0.5:
        value = r.choice(INT_EXTREMES)
        packed = (value & ((1 << 8 * width) - 1)).to_bytes(
            width, "little" if order == "<" else "big")
    else:
        value = r.choice(FLOAT_EXTREMES[width])
        packed = struct.pack(order + ("f" if width == 4 else "d"), value)
    return (c[:at] + packed + c[at + width:], "%d-byte %s-endian value at %d replaced by %r" % (
        width, "little" if order == "<" else "big", at, value))


def mutate(r, c):
    """One mutation of the bytes c: (new bytes, its description)."""
    n = len(c)
    kind = "insert"
    if n:
        kind = r.choice(("flip", "insert", "delete", "duplicate", "number", "truncate"))
    if kind == "flip":
        b = bytearray(c)
        at = sorted(r.randrange(n) for _ in range(r.randint(1, 16)))
        for i in at:
            b[i] ^= r.randint(1, 255)
        return bytes(b), "flip %d bytes at %s" % (len(at), ",".join(map(str, at)))
    if kind == "insert":
        at, length = r.randrange(n + 1), r.randint(1, r.choice((16, 256, 4096)))
        return c[:at] + r.randbytes(length) + c[at:], "insert %d random bytes at %d" % (length, at)
    if kind == "number":
        return replace_number(r, c)
    at = r.randrange(n)
    if kind == "truncate":
        return c[:at], "truncate to %d bytes (of %d)" % (at, n)
    length = r.randint(1, max(1, min(n - at, r.choice((16, 256, n // 4)))))
    if kind == "delete":
        return c[:at] + c[at + length:], "delete bytes [%d, %d)" % (at, at + length)
    return c[:at + length] + c[at:], "duplicate bytes [%d, %d) after themselves" % (at, at + length)


def make_case(index, seeds):
    """The case's folder, file to run, seed label and mutations' description."""
    r = rng("%s:%d" % (args.seed, index))
    label, source, main = seeds[index % len(seeds)]
    folder = os.path.join(cases_root, "case%04d" % index)
    shutil.copytree(source, folder)
    files = sorted(os.path.relpath(os.path.join(d, f), folder)
                   for d, _, fs in os.walk(folder) for f in fs)
    others = [f for f in files if f != main and os.path.getsize(os.path.join(folder, f))]
    target = main
    if others and (os.path.getsize(os.path.join(folder, main)) == 0 or r.random() < 1 / 3):
        target = r.choice(others)
    with open(os.path.join(folder, target), "rb") as f:
        content = f.read()
    steps = []
    for _ in range(r.randint(1, 3)):
        content, step = mutate(r, content)
        steps.append(step)
    with open(os.path.join(folder, target), "wb") as f:
        f.write(content)
    return folder, main, label, "%s: %s" % (target, "; ".join(steps))


# ---- running ------------------------------------------------------------------------------------
def command_line(out, main):
    return [exe, "--style", args.style, "--size", args.size, "--output", out, main]


def save_failure(index, kind, label, folder, main, mutation, rc, lines, rss, root):
    target = os.path.join(root, "case%04d-%s-%s" % (index, kind.replace(" ", "-"), label))
    shutil.move(folder, target)
    options = " ".join(shlex.quote(a) for a in command_line("/tmp/repro.png", main)[1:])
    command = shlex.quote(exe) + " " + options
    with open(os.path.join(target, "REPRO.txt"), "w", encoding="utf-8",
              errors="replace") as f:
        f.write("case %d, seed file %s, %s (made again by mutation_fuzz.py --seed %s --only %d%s)\n"
                "mutations of %s\nexit status %d, peak resident size %d kB\n"
                "command (in this folder): %s\nstderr:\n%s\n" % (
                    index, label, kind, args.seed, index,
                    " --formats " + args.formats if args.formats else "", mutation, rc, rss,
                    command, "\n".join(lines[-20:])))
    with open(os.path.join(target, "repro.sh"), "w") as f:
        f.write('#!/bin/sh\n# VTKSTYLIZE=PROGRAM repro.sh runs another build\n'
                'cd "$(dirname "$0")" && exec "${VTKSTYLIZE:-%s}" %s\n' % (exe, options))
    os.chmod(os.path.join(target, "repro.sh"), 0o755)
    if args.gdb and kind == "crash" and shutil.which("gdb"):
        try:
            bt = subprocess.run(["gdb", "-batch", "-ex", "run", "-ex", "bt", "--args"] +
                                command_line("/tmp/repro-gdb.png", main), cwd=target,
                                capture_output=True, text=True, timeout=300).stdout
        except subprocess.TimeoutExpired:
            bt = "(gdb timed out)"
        with open(os.path.join(target, "backtrace.txt"), "w") as f:
            f.write(bt)
    return target


def run(index):
    folder, main, label, mutation = make_case(index, seeds)
    size = sum(os.path.getsize(os.path.join(d, f)) for d, _, fs in os.walk(folder) for f in fs)
    out = os.path.join(outputs, "case%04d.png" % index)
    log = os.path.join(outputs, "case%04d.log" % index)
    rc, err, usage, hung, over, seconds = run_bounded(
        command_line(out, main), folder, log, args.time_limit, bounded_child(),
        args.rss_kill << 10)
    left = leftovers(outputs, out)
    kind, lines = classify(rc, err, hung, is_png(out), left, "vtkstylize: ")
    remove(left)
    if over or (usage.ru_maxrss > MEMORY_KB and size < 1 << 20 and kind not in ("hang", "crash")):
        kind = "memory"
    elif kind == "bad refusal" and rc not in (1, 2):
        kind = "crash"
    caught = kind == "refusal" and CAUGHT.search(lines[0])
    repro = ""
    if kind in PASSING and not caught:
        shutil.rmtree(folder)
    else:
        repro = save_failure(index, kind, label, folder, main, mutation, rc, lines,
                             usage.ru_maxrss, contained if caught else failures)
        print("%s case %d: %s (exit %d, %.0f MB, %.1f s) %s: %s | %s" % (
            "CAUGHT" if caught else "FAIL", index, kind, rc, usage.ru_maxrss / 1024, seconds,
            label, mutation, lines[-1] if lines else ""), flush=True)
    return index, label, kind, rc, seconds, usage.ru_maxrss, mutation, repro, bool(caught)


seeds = write_seeds()
if args.formats:
    seeds = [s for s in seeds if s[0] in args.formats.split(",")]
too_big = [(label, f) for label, d, f in seeds if os.path.getsize(os.path.join(d, f)) > 200 << 10]
assert not too_big, too_big
indices = [int(k) for k in args.only.split(",")] if args.only else range(args.cases)
print("mutation fuzz: --seed %s, %d cases over %d seed files, %d at a time, %s" % (
    args.seed, len(indices), len(seeds), args.jobs, exe), flush=True)
start = time.monotonic()
with ThreadPoolExecutor(max_workers=args.jobs) as pool:
    results = list(pool.map(run, indices))
elapsed = time.monotonic() - start

# ---- report -------------------------------------------------------------------------------------
columns = [k for k in KINDS if k in PASSING or any(r[2] == k for r in results)]
print("| seed file | cases | %s | caught by the reader's isolation |" % " | ".join(columns))
print("|---|---:|%s---:|" % ("---:|" * len(columns)))
for label in [s[0] for s in seeds] + ["all"]:
    mine = [r for r in results if label in (r[1], "all")]
    if mine:
        print("| %s | %d | %s | %d |" % (label, len(mine), " | ".join(
            str(sum(r[2] == k for r in mine)) for k in columns), sum(r[8] for r in mine)))
peak = max(results, key=lambda r: r[5])
print("largest peak resident size: %.0f MB (case %d, %s: %s, %s)" % (
    peak[5] / 1024, peak[0], peak[1], peak[6], peak[2]))
print("%d cases in %.0f s: %.2f cases/s; slowest: %s" % (
    len(results), elapsed, len(results) / elapsed,
    ", ".join("case %d %.1f s" % (r[0], r[4]) for r in sorted(results, key=lambda r: -r[4])[:3])))
bad = [r for r in results if r[2] not in PASSING]
for index, label, kind, rc, seconds, rss, mutation, repro, _ in bad:
    print("FAIL: case %d %s: %s (exit %d, %.0f MB) %s -> %s" % (
        index, label, kind, rc, rss / 1024, mutation, repro))
sys.exit(1 if bad else 0)
