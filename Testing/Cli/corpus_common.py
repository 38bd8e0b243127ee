"""What hostile_corpus.py and mutation_fuzz.py share: the formats vtkstylize reads, a seeded
random generator, the parallel XML files written with VTK's writers, running a case under a time
bound (and an optional resident-size bound) with its peak resident size from wait4, and the
classification of its outcome:
- render: exit 0 and the PNG(s) ("bad render": exit 0 without them);
- refusal: exit 1 or 2, exactly one stderr line starting with the program's name, no output and
  no temporary file left ("partial file" if one is left, "bad refusal" if the message is not one
  such line);
- crash: a signal (or an exit status of 128 and up), "internal error" or a Python traceback;
- hang: the time bound.
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
import time

SUPPORTED = (".vtp .vtu .vts .vtr .vti .vtm .pvtp .pvtu .pvts .pvtr .pvti .pvd .vtk .ex2 .exo .e "
             ".g .case .foam .stl .obj .ply").split()
REFERRING = (".vtm", ".pvtp", ".pvtu", ".pvts", ".pvtr", ".pvti", ".pvd", ".case")
PNG = b"\x89PNG\r\n\x1a\n"
SANITIZED = "ASAN_OPTIONS" in os.environ  # (AddressSanitizer reserves terabytes of address space)


def rng(name):
    """A generator seeded by a name: the same choices for the same name, whatever ran before."""
    return random.Random(int(hashlib.sha256(name.encode()).hexdigest()[:16], 16))


def extension(name):
    base = os.path.basename(name).lower()
    return os.path.splitext(base)[1]


def copy_entry(source, target):
    """Copies a file, keeps a link, and makes a FIFO anew (copytree would read it forever)."""
    if stat.S_ISFIFO(os.lstat(source).st_mode):
        os.mkfifo(target)
    else:
        shutil.copy2(source, target, follow_symlinks=False)


def write_parallel(folder):
    """parallel.pvtp, .pvti, .pvts and .pvtr in folder, two pieces each (parallel_0.vtp...)."""
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


def bounded_child(address_space=None):
    """The function a child runs before exec: its own process group (killed as a whole on a
    hang), no core file, and an address-space bound if one is given (not under
    AddressSanitizer)."""
    def limits():
        if address_space and not SANITIZED:
            resource.setrlimit(resource.RLIMIT_AS, (address_space, address_space))
        resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
        os.setsid()
    return limits


def resident_kb(group):
    """The resident size of the processes of a process group (a reader run in a child counts),
    in kB."""
    total = 0
    for entry in os.listdir("/proc"):
        try:
            with open("/proc/%s/stat" % entry) as f:
                fields = f.read().rsplit(")", 1)[1].split()
            if int(fields[2]) == group:  # (pgrp)
                total += int(fields[21]) * (resource.getpagesize() // 1024)  # (rss)
        except (OSError, IndexError, ValueError):
            pass
    return total


def wait_bounded(process, start, time_limit, rss_limit_kb=None):
    """Waits for the process with wait4 (its own peak resident size), killing its process group
    after time_limit seconds, or once its resident size passes rss_limit_kb if given:
    (status, usage, hung, over_memory)."""
    polls = 0
    while True:
        pid, status, usage = os.wait4(process.pid, os.WNOHANG)
        if pid:
            return status, usage, False, False
        hung = time.monotonic() - start > time_limit
        polls += 1
        over = bool(rss_limit_kb) and polls % 5 == 0 and resident_kb(process.pid) > rss_limit_kb
        if hung or over:
            os.killpg(process.pid, signal.SIGKILL)
            pid, status, usage = os.wait4(process.pid, 0)
            return status, usage, hung, over
        time.sleep(0.01)


def run_bounded(command, cwd, log, time_limit, preexec, rss_limit_kb=None):
    """Runs command in cwd (stdout discarded, stderr through the file log, removed after):
    (exit code, stderr text, usage, hung, over_memory, seconds)."""
    start = time.monotonic()
    with open(log, "wb") as err_file:
        process = subprocess.Popen(command, cwd=cwd, stdout=subprocess.DEVNULL,
                                   stderr=err_file, preexec_fn=preexec)
    status, usage, hung, over = wait_bounded(process, start, time_limit, rss_limit_kb)
    with open(log, "rb") as f:
        stderr = f.read()
    os.remove(log)
    return (os.waitstatus_to_exitcode(status), stderr.decode(errors="replace"), usage, hung, over,
            time.monotonic() - start)


def leftovers(outputs, out):
    """Files a run left in the folder outputs: its output out, a temporary file .NAME.XXXXXX."""
    found = []
    if os.path.exists(out):
        found.append(out)
    stem = "." + os.path.basename(out) + "."
    found += [os.path.join(outputs, f) for f in os.listdir(outputs) if f.startswith(stem)]
    return found


def remove(paths):
    for f in paths:
        shutil.rmtree(f) if os.path.isdir(f) else os.remove(f)


def is_png(path):
    if not os.path.isfile(path):
        return False
    with open(path, "rb") as f:
        return f.read(8) == PNG


def classify(rc, err, hung, rendered, left, program):
    """The case's kind (see the module's docstring) and its stderr lines. rendered: the run's
    images are there; left: what leftovers() found; program: its messages' prefix."""
    # (under AddressSanitizer with allocator_may_return_null, an allocation too large is refused
    # as without it, with a warning of its own: not a line of the program's)
    lines = [line for line in err.splitlines() if line.strip() and
             not (SANITIZED and "WARNING: AddressSanitizer failed to allocate" in line)]
    if hung:
        kind = "hang"
    elif rc < 0 or rc >= 128 or "internal error" in err or "Traceback" in err:
        kind = "crash"
    elif rc == 0:
        kind = "render" if rendered else "bad render"
    elif left:
        kind = "partial file"
    elif len(lines) == 1 and lines[0].startswith(program) and rc in (1, 2):
        kind = "refusal"
    else:
        kind = "bad refusal"
    return kind, lines


QUOTED = re.compile(r"(?<!\w)'[^'\n]*'(?!\w)|\"[^\"\n]*\"")
PATH = re.compile(r"(?<![\w.])/[^\s:'\"]+")
GARBLED = re.compile(r"\S*[^\x20-\x7e\s]\S*|\S*\?\?\S*")
FILE_NAME = re.compile(r"(?<![\w.])[A-Za-z_][\w+-]*(?:\.[A-Za-z][\w+-]*)+\b")
NUMBERS = re.compile(r"(?<![A-Za-z_])[-+]?(?:0x[0-9a-fA-F]+|\d+(?:\.\d*)?(?:[eE][-+]?\d+)?)"
                     r"|\b(?:nan|inf)\b")


def message_kind(lines, program, name=None):
    """The kind of a case's messages: its stderr lines without the program's name, with the
    case's file name (name), paths, words of garbled bytes, quoted text, other file names and
    numbers taken out ("cannot read '...': line N: ..."), in order, joined by " | " (a refusal's
    one line; a render's warnings; nothing for a silent render)."""
    kinds = []
    for line in lines:
        if line.startswith(program):
            line = line[len(program):]
        if name:
            line = re.sub(r"(?<![\w.])%s(?!\w)" % re.escape(name), "F", line)
        # (a reader's message may quote the file's bytes: a word of them is "X")
        line = GARBLED.sub("X", PATH.sub("PATH", line))
        line = NUMBERS.sub("N", FILE_NAME.sub("F", QUOTED.sub("'...'", line))).strip()
        if line and line not in kinds:
            kinds.append(line)
    return " | ".join(kinds)
