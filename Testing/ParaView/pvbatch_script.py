"""Runs one of the ParaView tests' render scripts under pvbatch, for the test drivers."""
import os
import subprocess
import sys


def run_render_script(pvbatch, name, out, stem, *arguments, ranks=0):
    """Runs render script `name` (beside this file) with the output prefix out/stem (and further
    `arguments`), on `ranks` MPI ranks (mpiexec) when ranks > 0; exits with the log unless it ran
    to its "rendered" line. Returns the prefix and pvbatch's standard output."""
    os.makedirs(out, exist_ok=True)
    script = os.path.join(os.path.dirname(os.path.abspath(__file__)), name)
    prefix = os.path.join(out, stem)
    command = [pvbatch, script, prefix] + list(arguments)
    env = dict(os.environ)
    if ranks > 0:
        command = ["mpiexec", "-n", str(ranks), "--oversubscribe"] + command
        if os.getuid() == 0:  # OpenMPI refuses root without these (CI runs as root)
            env.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    result = subprocess.run(command, capture_output=True, text=True, timeout=600, env=env)
    if result.returncode != 0 or "rendered" not in result.stdout:
        sys.exit("FAIL: %s exited with %d:\n%s" % (" ".join(command[:4]), result.returncode,
                                                   (result.stdout + result.stderr)[-3000:]))
    return prefix, result.stdout


def ranks_run(ranks_dir, ranks, name):
    """What render_ranks.py rendered on `ranks` ranks (test_ranks.py, the fixture paraview_ranks)
    for its script `name` (contour, realdata, translucent): the images' prefix and that script's
    lines of pvbatch's output. Exits naming the fixture when the run is not there."""
    log = os.path.join(ranks_dir, "ranks%d.log" % ranks)
    if not os.path.exists(log):
        sys.exit("FAIL: no %s: run paraview.ranks (test_ranks.py) first" % log)
    section, lines = None, []
    for line in open(log).read().splitlines():
        if line.startswith("== "):
            section = line[3:].strip()
        elif section == name:
            lines.append(line)
    if "rendered" not in lines:
        sys.exit("FAIL: %s holds no finished run of %s" % (log, name))
    return os.path.join(ranks_dir, "ranks%d" % ranks, name), "\n".join(lines)
