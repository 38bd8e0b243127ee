#!/usr/bin/python3
"""cli.hostile_corpus: vtkstylize against a corpus of hostile input, generated at test time.

    hostile_corpus.py VTKSTYLIZE DATA_DIR WORK_DIR

The corpus (deterministic: every random choice is seeded by the case's name):
- the command-line tests' data (DATA_DIR: valid files of every format, and the broken files of
  the cli.bad tests: polyhedra that lie, legacy headers claiming a billion cells, non-finite
  values, multiblock files naming a FIFO or themselves, a compression bomb...), as they are;
- the parallel XML formats (.pvtp, .pvti, .pvts, .pvtr), written here with VTK's writers;
- for every file of a supported format up to 2 MB: truncations at 1 byte, 1/4, 1/2, 3/4 and all
  but the last byte; random bytes of the same length; 16 random bytes flipped; the first
  integers of its first 512 bytes replaced by huge ones (header lies); number tokens replaced by
  nan, inf and 1e400 (text files); 1 MB of random bytes appended. A file that names others
  (.vtm, .pvt*, .pvd, .case) is mutated beside the files it names (a folder of links);
- special files: a FIFO, a directory, /dev/zero and /dev/null behind a link, a link loop, a
  file that is a link to itself through another.

Each case runs `vtkstylize --size 64x48 --output OUT CASE` with a time bound (60 s) and an
address-space bound (RLIMIT_AS, 6 GiB; not under AddressSanitizer, which reserves terabytes),
two at a time. A case is:
- a render: exit 0, a PNG at OUT, nothing else written beside it;
- a clean refusal: exit 1 or 2, exactly one stderr line starting "vtkstylize: ", no OUT and
  no temporary file left;
- a crash (a signal, or "internal error"), a hang (the time bound), or a partial file (an
  output or a temporary file after a failure): each fails the test, as does a refusal that is
  not one line.
It prints the counts, the largest resident size (ru_maxrss) of any case, and the worst cases.
"""
import hashlib
import os
import random
import re
import resource
import shutil
import signal
import stat
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor

exe, data, work = (os.path.abspath(a) for a in sys.argv[1:4])
TIME_LIMIT = 60.0
ADDRESS_SPACE = 6 << 30
MAX_MUTATED = 2 << 20
SUPPORTED = (".vtp .vtu .vts .vtr .vti .vtm .pvtp .pvtu .pvts .pvtr .pvti .pvd .vtk .ex2 .exo .e "
             ".g .case .foam .stl .obj .ply").split()
REFERRING = (".vtm", ".pvtp", ".pvtu", ".pvts", ".pvtr", ".pvti", ".pvd", ".case")

shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
outputs = os.path.join(work, "out")
os.makedirs(outputs)


def rng(name):
    return random.Random(int(hashlib.sha256(name.encode()).hexdigest()[:16], 16))


def extension(name):
    base = os.path.basename(name).lower()
    return os.path.splitext(base)[1]


# ---- the parallel XML formats ---------------------------------------------------------------
def write_parallel(folder):
    import vtk  # Debian's python3-vtk9
    sphere = vtk.vtkSphereSource()
    sphere.SetThetaResolution(24)
    sphere.SetPhiResolution(16)
    wavelet = vtk.vtkRTAnalyticSource()
    wavelet.SetWholeExtent(-6, 6, -6, 6, -6, 6)
    grid = vtk.vtkStructuredGrid()
    grid.SetDimensions(6, 5, 4)
    points = vtk.vtkPoints()
    for k in range(4):
        for j in range(5):
            for i in range(6):
                points.InsertNextPoint(i, j + 0.2 * i, k + 0.1 * j * j)
    grid.SetPoints(points)
    rect = vtk.vtkRectilinearGrid()
    rect.SetDimensions(5, 4, 3)
    for axis, n in zip("XYZ", (5, 4, 3)):
        coords = vtk.vtkDoubleArray()
        for i in range(n):
            coords.InsertNextValue(i * 0.7 + 0.05 * i * i)
        getattr(rect, "Set%sCoordinates" % axis)(coords)
    for writer, source, name in ((vtk.vtkXMLPPolyDataWriter(), sphere, "parallel.pvtp"),
                                 (vtk.vtkXMLPImageDataWriter(), wavelet, "parallel.pvti"),
                                 (vtk.vtkXMLPStructuredGridWriter(), grid, "parallel.pvts"),
                                 (vtk.vtkXMLPRectilinearGridWriter(), rect, "parallel.pvtr")):
        if isinstance(source, vtk.vtkAlgorithm):
            writer.SetInputConnection(source.GetOutputPort())
        else:
            writer.SetInputData(source)
        writer.SetNumberOfPieces(2)
        writer.SetStartPiece(0)
        writer.SetEndPiece(1)
        writer.SetFileName(os.path.join(folder, name))
        writer.Write()


bases = os.path.join(work, "base")

def copy_entry(source, target):
    """Copies a file, keeps a link, and makes a FIFO anew (copytree would read it forever)."""
    if stat.S_ISFIFO(os.lstat(source).st_mode):
        os.mkfifo(target)
    else:
        shutil.copy2(source, target, follow_symlinks=False)


shutil.copytree(data, bases, symlinks=True, copy_function=copy_entry,
                ignore=lambda d, names: [n for n in names if n == "out"])
write_parallel(bases)

cases = []  # (name, folder, file)


def add(name, folder, file):
    cases.append((name, folder, file))


for entry in sorted(os.listdir(bases)):
    add("as is: " + entry, bases, entry)

# ---- mutations ----------------------------------------------------------------------------------
NUMBER = re.compile(rb"-?\d+\.\d+(?:[eE][-+]?\d+)?")
INTEGER = re.compile(rb"\d+")


def mutations(name, content):
    r = rng(name)
    n = len(content)
    out = []
    for label, length in (("1 byte", 1), ("1/4", n // 4), ("1/2", n // 2), ("3/4", 3 * n // 4),
                          ("all but 1 byte", n - 1)):
        if 0 < length < n:
            out.append(("truncated to " + label, content[:length]))
    out.append(("random bytes", bytes(r.getrandbits(8) for _ in range(n))))
    flipped = bytearray(content)
    for _ in range(16):
        if flipped:
            flipped[r.randrange(len(flipped))] ^= 1 << r.randrange(8)
    out.append(("16 bits flipped", bytes(flipped)))
    head = content[:512]
    lies = bytearray(content)
    shift = 0
    for m in list(INTEGER.finditer(head))[:6]:
        huge = str(r.choice([2 ** 31 - 1, 2 ** 32 + 7, 10 ** 12, 9 * 10 ** 18])).encode()
        lies[m.start() + shift:m.end() + shift] = huge
        shift += len(huge) - (m.end() - m.start())
    out.append(("header lies", bytes(lies)))
    if b"\0" not in content[:4096]:
        for token in (b"nan", b"inf", b"1e400"):
            numbers = list(NUMBER.finditer(content))
            if numbers:
                m = numbers[r.randrange(len(numbers))]
                out.append(("a number made " + token.decode(),
                            content[:m.start()] + token + content[m.end():]))
    out.append(("1 MB of random bytes appended",
                content + bytes(r.getrandbits(8) for _ in range(1 << 20))))
    return out


mutated_root = os.path.join(work, "mutated")
os.makedirs(mutated_root)
for entry in sorted(os.listdir(bases)):
    path = os.path.join(bases, entry)
    if (extension(entry) not in SUPPORTED or os.path.islink(path) or not os.path.isfile(path)
            or os.path.getsize(path) > MAX_MUTATED or os.path.getsize(path) == 0):
        continue
    content = open(path, "rb").read()
    for k, (label, bytes_) in enumerate(mutations(entry, content)):
        folder = os.path.join(mutated_root, "%s.%d" % (entry, k))
        os.makedirs(folder)
        if extension(entry) in REFERRING:
            # beside the files it names: links to every other base file
            for other in os.listdir(bases):
                if other != entry:
                    os.symlink(os.path.join(bases, other), os.path.join(folder, other))
        with open(os.path.join(folder, entry), "wb") as f:
            f.write(bytes_)
        add("%s: %s" % (entry, label), folder, entry)

# ---- special files ------------------------------------------------------------------------------
special = os.path.join(work, "special")
os.makedirs(special)
os.mkfifo(os.path.join(special, "fifo.vtp"))
os.mkdir(os.path.join(special, "folder.stl"))
os.symlink("/dev/zero", os.path.join(special, "zero.stl"))
os.symlink("/dev/null", os.path.join(special, "null.obj"))
os.symlink("loop_b.ply", os.path.join(special, "loop_a.ply"))
os.symlink("loop_a.ply", os.path.join(special, "loop_b.ply"))
os.symlink("missing_target.vtk", os.path.join(special, "dangling.vtk"))
for entry in sorted(os.listdir(special)):
    add("special: " + entry, special, entry)


# ---- running ------------------------------------------------------------------------------------
SANITIZED = "ASAN_OPTIONS" in os.environ  # (AddressSanitizer reserves terabytes of address space)


def limits():
    if not SANITIZED:
        resource.setrlimit(resource.RLIMIT_AS, (ADDRESS_SPACE, ADDRESS_SPACE))
    resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
    os.setsid()


def leftovers(folder, out):
    """Files a run left beside its output or its input: an output, a temporary file."""
    found = []
    if os.path.exists(out):
        found.append(out)
    stem = "." + os.path.basename(out) + "."
    found += [os.path.join(outputs, f) for f in os.listdir(outputs) if f.startswith(stem)]
    return found


def run(index_case):
    index, (name, folder, file) = index_case
    out = os.path.join(outputs, "case%04d.png" % index)
    command = [exe, "--size", "64x48", "--output", out, file]
    start = time.monotonic()
    log = os.path.join(outputs, "case%04d.log" % index)
    with open(log, "wb") as err_file:
        process = subprocess.Popen(command, cwd=folder, stdout=subprocess.DEVNULL,
                                   stderr=err_file, preexec_fn=limits)
    # waited for with wait4: the case's own peak resident size
    hung = False
    while True:
        pid, status, usage = os.wait4(process.pid, os.WNOHANG)
        if pid:
            break
        if time.monotonic() - start > TIME_LIMIT:
            hung = True
            os.killpg(process.pid, signal.SIGKILL)
            pid, status, usage = os.wait4(process.pid, 0)
            break
        time.sleep(0.01)
    process.returncode = os.waitstatus_to_exitcode(status)
    stderr = open(log, "rb").read()
    os.remove(log)
    seconds = time.monotonic() - start
    rc = process.returncode
    err = stderr.decode(errors="replace")
    # (under AddressSanitizer with allocator_may_return_null, an allocation too large is refused
    # as without it, with a warning of its own: not a line of the program's)
    lines = [line for line in err.splitlines() if line.strip() and
             not (SANITIZED and "WARNING: AddressSanitizer failed to allocate" in line)]
    if hung:
        kind = "hang"
    elif rc < 0 or rc >= 128 or "internal error" in err:
        kind = "crash"
    elif rc == 0:
        kind = "render" if os.path.isfile(out) and open(out, "rb").read(8) == b"\x89PNG\r\n\x1a\n" \
            else "bad render"
    else:
        left = leftovers(folder, out)
        if left:
            kind = "partial file"
        elif len(lines) == 1 and lines[0].startswith("vtkstylize: ") and rc in (1, 2):
            kind = "refusal"
        else:
            kind = "bad refusal"
    for f in leftovers(folder, out):
        os.remove(f)
    return name, kind, rc, seconds, (lines[-1] if lines else ""), usage.ru_maxrss


start = time.monotonic()
with ThreadPoolExecutor(max_workers=2) as pool:
    results = list(pool.map(run, enumerate(cases)))
peak_kb, peak_case = max((r[5], r[0]) for r in results)
elapsed = time.monotonic() - start

counts = {}
for name, kind, rc, seconds, message, rss in results:
    counts[kind] = counts.get(kind, 0) + 1
print("| cases | clean refusals | renders | crashes | hangs | partial files | bad refusals or "
      "renders |")
print("|---:|---:|---:|---:|---:|---:|---:|")
print("| %d | %d | %d | %d | %d | %d | %d |" % (
    len(results), counts.get("refusal", 0), counts.get("render", 0), counts.get("crash", 0),
    counts.get("hang", 0), counts.get("partial file", 0),
    counts.get("bad refusal", 0) + counts.get("bad render", 0)))
print("largest resident size of any case: %.0f MB (%s); %.0f s in all; slowest cases:" % (
    peak_kb / 1024.0, peak_case, elapsed))
for name, kind, rc, seconds, message, rss in sorted(results, key=lambda r: -r[3])[:5]:
    print("  %.1f s  %s (%s)" % (seconds, name, kind))
bad = [r for r in results if r[1] not in ("render", "refusal")]
for name, kind, rc, seconds, message, rss in bad:
    print("FAIL: %s: %s (exit %d) %s" % (name, kind, rc, message))
sys.exit(1 if bad else 0)
