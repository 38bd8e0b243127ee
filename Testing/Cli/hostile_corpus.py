#!/usr/bin/python3
"""The hostile-input corpus, generated at test time, against the project's three entry points.

    hostile_corpus.py [--runner cli|python|paraview] PROGRAM DATA_DIR WORK_DIR
    hostile_corpus.py --runner python|paraview --sample PROGRAM CLI_WORK_DIR WORK_DIR

cli.hostile_corpus (--runner cli, the default; PROGRAM is vtkstylize), python.hostile_corpus
(--runner python; PROGRAM is Examples/Python/stylize_dataset.py, run by this interpreter with the
build's package on PYTHONPATH) and paraview.hostile_corpus (--runner paraview; PROGRAM is
pvbatch-stylize, which runs Testing/ParaView/render_corpus.py: the plugin's Stylize Checked
Reader, Extract Surface, the Principal Curvatures filter and the Stylize view in every style).

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

cli and python: each case runs `vtkstylize --size 64x48 --output OUT CASE` (or
`stylize_dataset.py CASE -o OUTDIR --size 64x48`: four PNGs) with a time bound (60 s) and an
address-space bound (RLIMIT_AS, 6 GiB; not under AddressSanitizer, which reserves terabytes),
two at a time. A case is:
- a render: exit 0, the PNG(s), nothing else written beside them;
- a clean refusal: exit 1 or 2, exactly one stderr line starting with the program's name
  ("vtkstylize: ", "stylize_dataset.py: "), no output and no temporary file left;
- a crash (a signal, or "internal error"), a hang (the time bound), or a partial file (an
  output or a temporary file after a failure): each fails the test, as does a refusal that is
  not one line.
paraview: one pvbatch reads every case in turn (the same bounds, per case, on the whole
process); a case is a refusal when the reader's error message is one line, a render when the
view rendered it in every style; a crash or hang fails the test (pvbatch is restarted after
the case to go on with the rest).
It prints the counts, the largest resident size (ru_maxrss) of any case, and the worst cases, and
writes WORK_DIR/results.json: each case's name, folder (relative to WORK_DIR), file, outcome,
exit status and stderr lines.

--sample (python and paraview runners): the corpus is the one a cli run generated in CLI_WORK_DIR
(used as it is, not generated again), and the runner reads a stratified sample of it: one case per
stratum of the cli run's results, a stratum being the file's extension (which picks the reader),
the outcome and the kind of its message (corpus_common.message_kind: a refusal's line or a
render's warnings with names, paths and numbers taken out). Every reader and every kind of
refusal and of warning that the program meets then goes through the Python package and through
ParaView too, in a seventh of the cases. cli.hostile_corpus is the fixture that makes CLI_WORK_DIR;
docs/testing.md gives the coverage per kind against full runs. The strata whose outcome differs
from the program's are printed (a difference is not a failure: ParaView renders a file whose
picture vtkstylize refuses as empty, for example).
"""
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from corpus_common import (REFERRING, SUPPORTED, bounded_child, classify, copy_entry,  # noqa: E402
                           extension, is_png, leftovers, message_kind, remove, rng, run_bounded,
                           write_parallel)

arguments = sys.argv[1:]
RUNNER = "cli"
if arguments[:1] == ["--runner"]:
    RUNNER, arguments = arguments[1], arguments[2:]
SAMPLE = arguments[:1] == ["--sample"]
if SAMPLE:
    arguments = arguments[1:]
if (RUNNER not in ("cli", "python", "paraview") or len(arguments) != 3
        or (SAMPLE and RUNNER == "cli")):
    sys.exit(__doc__)
exe, data, work = (os.path.abspath(a) for a in arguments)
TIME_LIMIT = 60.0
ADDRESS_SPACE = 6 << 30
MAX_MUTATED = 2 << 20
shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
outputs = os.path.join(work, "out")
os.makedirs(outputs)

cases = []  # (name, folder, file)


def add(name, folder, file):
    cases.append((name, folder, file))


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


def generate():
    """The corpus in work: base/ (the data as it is, and the parallel formats), mutated/ and
    special/ (see the module's docstring); each case added in order."""
    bases = os.path.join(work, "base")
    shutil.copytree(data, bases, symlinks=True, copy_function=copy_entry,
                    ignore=lambda d, names: [n for n in names if n == "out"])
    write_parallel(bases)

    for entry in sorted(os.listdir(bases)):
        add("as is: " + entry, bases, entry)

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

    # special files
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


def stratified_sample(cli_work):
    """One case per stratum of the cli run's results in cli_work (see the module's docstring),
    in corpus order: the cases, and the cli's outcome per case name."""
    listing = os.path.join(cli_work, "results.json")
    if not os.path.exists(listing):
        sys.exit("hostile_corpus.py: no %s: run the cli runner (cli.hostile_corpus) first"
                 % listing)
    strata = {}
    for case in json.load(open(listing)):
        key = (extension(case["file"]), case["kind"],
               message_kind(case["lines"], "vtkstylize: ", case["file"]))
        strata.setdefault(key, case)
    chosen = sorted(strata.items(), key=lambda item: item[1]["index"])
    return ([(c["name"], os.path.join(cli_work, c["folder"]), c["file"]) for _, c in chosen],
            {c["name"]: key for key, c in chosen})


if SAMPLE:
    sampled, program_outcome = stratified_sample(data)
    for case in sampled:
        add(*case)
    print("a stratified sample of the corpus in %s: %d cases" % (data, len(cases)))
else:
    generate()


# ---- running ------------------------------------------------------------------------------------
limits = bounded_child(ADDRESS_SPACE)


def run(index_case):
    index, (name, folder, file) = index_case
    if RUNNER == "cli":
        out = os.path.join(outputs, "case%04d.png" % index)
        command = [exe, "--size", "64x48", "--output", out, file]
        program = "vtkstylize: "
    else:
        out = os.path.join(outputs, "case%04d" % index)
        command = [sys.executable, exe, file, "-o", out, "--size", "64x48"]
        program = "stylize_dataset.py: "
    log = os.path.join(outputs, "case%04d.log" % index)
    rc, err, usage, hung, _, seconds = run_bounded(command, folder, log, TIME_LIMIT, limits)
    left = leftovers(outputs, out)
    kind, lines = classify(rc, err, hung, rendered(out), left, program)
    remove(left)
    return name, kind, rc, seconds, lines, usage.ru_maxrss


def rendered(out):
    """The run's images are there: the PNG (cli) or the four of the example's styles."""
    files = [out] if RUNNER == "cli" else [os.path.join(out, s + ".png")
                                           for s in ("none", "comic", "pixel", "sketch")]
    return all(is_png(f) for f in files)


def run_paraview():
    """Every case through one pvbatch (render_corpus.py), restarted after a crash or a hang:
    the results in case order."""
    script = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
                          "ParaView", "render_corpus.py")
    listing = os.path.join(work, "cases.json")
    with open(listing, "w") as f:
        json.dump([[os.path.join(folder, file), folder] for _, folder, file in cases], f)
    progress = os.path.join(work, "progress.txt")
    results = {}
    first = 0
    while first < len(cases):
        open(progress, "w").close()
        log = open(os.path.join(work, "pvbatch-%04d.log" % first), "wb")
        process = subprocess.Popen([exe, script, listing, progress, str(first)],
                                   stdout=log, stderr=subprocess.STDOUT, preexec_fn=limits)
        current, started, hung = first, time.monotonic(), False
        while True:
            pid, status, usage = os.wait4(process.pid, os.WNOHANG)
            if pid:
                break
            lines = open(progress).read().splitlines()
            begun = [l for l in lines if l.startswith("start ")]
            if begun and int(begun[-1].split()[1]) != current:
                current, started = int(begun[-1].split()[1]), time.monotonic()
            if time.monotonic() - started > TIME_LIMIT:
                hung = True
                os.killpg(process.pid, signal.SIGKILL)
                pid, status, usage = os.wait4(process.pid, 0)
                break
            time.sleep(0.05)
        log.close()
        done = {}
        for line in open(progress).read().splitlines():
            if line.startswith("done "):
                _, index, kind, seconds, rss, message = (line.split(" ", 5) + [""])[:6]
                done[int(index)] = (kind, float(seconds), int(rss), message)
        for index, (kind, seconds, rss, message) in done.items():
            results[index] = (cases[index][0], kind, 0, seconds, [message] if message else [], rss)
        last = max(done) if done else first - 1
        if last + 1 >= len(cases):
            break
        # the process ended (or was killed) during case last + 1
        failed = last + 1
        rc = os.waitstatus_to_exitcode(status)
        kind = "hang" if hung else "crash"
        if not hung and rc == 0:
            kind = "crash"  # (it stopped without finishing the list)
        results[failed] = (cases[failed][0], kind, rc, 0.0, ["pvbatch exit %d" % rc],
                           usage.ru_maxrss)
        first = failed + 1
    return [results[i] for i in range(len(cases))]


start = time.monotonic()
if RUNNER == "paraview":
    results = run_paraview()
else:
    with ThreadPoolExecutor(max_workers=2) as pool:
        results = list(pool.map(run, enumerate(cases)))
peak_kb, peak_case = max((r[5], r[0]) for r in results)
elapsed = time.monotonic() - start
with open(os.path.join(work, "results.json"), "w") as f:
    json.dump([{"index": i, "name": name, "folder": os.path.relpath(folder, work), "file": file,
                "kind": r[1], "rc": r[2], "seconds": round(r[3], 3), "lines": r[4], "rss_kb": r[5]}
               for i, ((name, folder, file), r) in enumerate(zip(cases, results))], f, indent=0)

counts = {}
for name, kind, rc, seconds, lines, rss in results:
    counts[kind] = counts.get(kind, 0) + 1
print("| cases | clean refusals | renders | crashes | hangs | partial files | bad refusals or "
      "renders |")
print("|---:|---:|---:|---:|---:|---:|---:|")
print("| %d | %d | %d | %d | %d | %d | %d |" % (
    len(results), counts.get("refusal", 0), counts.get("render", 0), counts.get("crash", 0),
    counts.get("hang", 0), counts.get("partial file", 0),
    counts.get("bad refusal", 0) + counts.get("bad render", 0)))
print("largest resident size %s: %.0f MB (%s); %.0f s in all; slowest cases:" % (
    "of the pvbatch process (its peak up to the case)" if RUNNER == "paraview" else "of any case",
    peak_kb / 1024.0, peak_case, elapsed))
for name, kind, rc, seconds, lines, rss in sorted(results, key=lambda r: -r[3])[:5]:
    print("  %.1f s  %s (%s)" % (seconds, name, kind))
if SAMPLE:
    # the strata whose outcome here is not the program's (information, not a failure)
    other = [(name, program_outcome[name][1], kind) for name, kind, rc, seconds, lines, rss
             in results if kind != program_outcome[name][1]]
    print("%d of %d strata end as vtkstylize's do%s" % (len(results) - len(other), len(results),
                                                      "; not these:" if other else ""))
    for name, theirs, kind in other:
        print("  %s: vtkstylize %s, here %s" % (name, theirs, kind))
bad = [r for r in results if r[1] not in ("render", "refusal")]
for name, kind, rc, seconds, lines, rss in bad:
    print("FAIL: %s: %s (exit %d) %s" % (name, kind, rc, lines[-1] if lines else ""))
sys.exit(1 if bad else 0)
