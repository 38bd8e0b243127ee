#!/usr/bin/python3
"""paraview.ranks: the ParaView tests' scenes on 1 and on 2 ranks, rendered once for every test
that compares them (the fixture paraview_ranks: paraview.mpi, paraview.realdata_mpi,
paraview.translucent, paraview.volumes, paraview.client_server).

    test_ranks.py PVBATCH_WRAPPER DATA_DIR OUTPUT_DIR

Runs render_ranks.py (the Wavelet contour, the real-data bunny and vessel, the translucent bunny
around the gear, the skull CT as a volume) under `mpiexec -n 1` and `mpiexec -n 2`, one pvbatch per rank count, into
OUTPUT_DIR/ranks1/ and ranks2/ with pvbatch's output in ranks1.log and ranks2.log. Fails unless
every script ran to its end on both (the comparisons are the other tests').

The checked reader's helper (vtkstylize-read) is started through a wrapper that logs who started
it (VTKSTYLIZE_READ_HELPER): render_realdata.py reads the bunny with it, and on either rank count
exactly one process, rank 0, may read it (the other ranks do not need the data).
"""
import os
import subprocess
import sys
import time

pvbatch, data, out = sys.argv[1], sys.argv[2], sys.argv[3]
script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "render_ranks.py")
env = dict(os.environ)
if os.getuid() == 0:  # OpenMPI refuses root without these (CI runs as root)
    env.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
failures = []
helper = os.path.join(os.path.dirname(os.path.abspath(pvbatch)), "..", "lib", "paraview-5.11",
                      "plugins", "VTKStylize", "vtkstylize-read")
os.makedirs(out, exist_ok=True)
for ranks in (1, 2):
    folder = os.path.join(out, "ranks%d" % ranks)
    os.makedirs(folder, exist_ok=True)
    log = os.path.join(out, "ranks%d.log" % ranks)
    if os.path.exists(log):
        os.remove(log)  # (a failed run leaves no log of an earlier one behind)
    command = ["mpiexec", "-n", str(ranks), "--oversubscribe", pvbatch, script, folder, data]
    reads = os.path.join(out, "reads%d.log" % ranks)
    wrapper = os.path.join(out, "read-helper%d.sh" % ranks)
    with open(wrapper, "w") as f:
        f.write('#!/bin/sh\necho "$PPID" >> "%s"\nexec "%s" "$@"\n' % (reads, helper))
    os.chmod(wrapper, 0o755)
    if os.path.exists(reads):
        os.remove(reads)
    env["VTKSTYLIZE_READ_HELPER"] = wrapper
    start = time.monotonic()
    result = subprocess.run(command, env=env, capture_output=True, text=True, timeout=900)
    readers = open(reads).read().split() if os.path.exists(reads) else []
    print("%d rank(s): the checked reader's helper started %d time(s), by %d process(es)"
          % (ranks, len(readers), len(set(readers))))
    if len(readers) != 1:
        failures.append("%d rank(s): the helper read %d times (%s), not once on rank 0"
                        % (ranks, len(readers), readers))
    sections = [line[3:] for line in result.stdout.splitlines() if line.startswith("== ")]
    finished = result.stdout.count("\nrendered")
    print("%d rank(s): %s in %.0f s, exit %d" % (ranks, ", ".join(sections),
                                                time.monotonic() - start, result.returncode))
    if result.returncode != 0 or finished != 4:
        failures.append("%d rank(s): %s exited with %d after %d of 4 scripts:\n%s" % (
            ranks, " ".join(command[:5]), result.returncode, finished,
            (result.stdout + result.stderr)[-3000:]))
        continue
    with open(log, "w") as f:
        f.write(result.stdout)
for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
