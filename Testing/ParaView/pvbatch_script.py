"""Runs one of the ParaView tests' render scripts under pvbatch, for the test drivers."""
import os
import subprocess
import sys


def run_render_script(pvbatch, name, out, stem, *arguments):
    """Runs render script `name` (beside this file) with the output prefix out/stem (and further
    `arguments`); exits with the log unless it ran to its "rendered" line. Returns the prefix."""
    os.makedirs(out, exist_ok=True)
    script = os.path.join(os.path.dirname(os.path.abspath(__file__)), name)
    prefix = os.path.join(out, stem)
    result = subprocess.run([pvbatch, script, prefix] + list(arguments), capture_output=True,
                            text=True, timeout=600)
    if result.returncode != 0 or "rendered" not in result.stdout:
        sys.exit("FAIL: pvbatch exited with %d:\n%s" % (
            result.returncode, (result.stdout + result.stderr)[-3000:]))
    return prefix
