#!/usr/bin/python3
"""paraview.client_server: pvserver-stylize on localhost, pvpython-stylize connected to it.

    test_client_server.py WRAPPER_DIR OUTPUT_DIR RANKS_DIR

WRAPPER_DIR holds pvbatch-stylize, pvserver-stylize and pvpython-stylize. The scene and styles
of render_styles.py as pvbatch renders them on 1 rank are the reference (paraview.ranks' run,
test_ranks.py, in RANKS_DIR: the renders paraview.mpi compares too); they are rendered by a client
connected to a server of 1 rank with remote rendering (the server renders and sends the image)
and with local rendering (the client renders the delivered geometry), and to a server of 2
ranks (mpiexec) with remote rendering. Against pvbatch, pixels more than 16 levels apart, at
most: 0.05% on 1 rank (measured: 0, but for 5 pixels of the sketch with remote rendering),
0.5% on 2 ranks (measured: 0.03% at most). client_checks.py then checks what a client sees
with the plugin on both sides, on the server only and on the client only (an error, no abort).
"""
import os
import socket
import subprocess
import sys
import threading
import time

from vtkstylize_testing import vtkStylizeImageMetrics as M
from vtkmodules.vtkIOImage import vtkPNGReader

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from pvbatch_script import ranks_run  # noqa: E402

bindir, out, ranks_dir = sys.argv[1], sys.argv[2], sys.argv[3]
os.makedirs(out, exist_ok=True)
here = os.path.dirname(os.path.abspath(__file__))
render = os.path.join(here, "render_styles.py")
checks = os.path.join(here, "client_checks.py")
env = dict(os.environ)
if os.getuid() == 0:  # OpenMPI refuses root without these (CI runs as root)
    env.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
failures = []
SIZE = ["400", "300"]


def free_port():
    with socket.socket() as s:
        s.bind(("localhost", 0))
        return s.getsockname()[1]


def run(command, timeout=300):
    result = subprocess.run(command, env=env, capture_output=True, text=True, timeout=timeout)
    return result.returncode, result.stdout + result.stderr


class Server:
    """A pvserver started on a free port; ready once it accepts connections."""

    def __init__(self, program, ranks=1):
        self.port = free_port()
        command = [program, "--server-port=%d" % self.port]
        if ranks > 1:
            command = ["mpiexec", "-n", str(ranks), "--oversubscribe"] + command
        self.process = subprocess.Popen(command, env=env, stdout=subprocess.PIPE,
                                        stderr=subprocess.STDOUT, text=True)
        self.lines = []
        self.ready = threading.Event()
        threading.Thread(target=self._read, daemon=True).start()
        if not self.ready.wait(120):
            self.stop()
            sys.exit("FAIL: %s did not accept connections:\n%s" % (program, "".join(self.lines)))

    def _read(self):
        for line in self.process.stdout:
            self.lines.append(line)
            if "Accepting connection" in line:
                self.ready.set()

    def stop(self):
        try:
            self.process.wait(60)  # a pvserver exits when its client disconnects
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()
        return self.process.returncode


def read(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


pvbatch = os.path.join(bindir, "pvbatch-stylize")
pvserver = os.path.join(bindir, "pvserver-stylize")
pvpython = os.path.join(bindir, "pvpython-stylize")

reference, _ = ranks_run(ranks_dir, 1, "contour")  # (render_styles.py's size: 400x300)

print("| client-server run | style | pixels > 16 levels vs pvbatch | SSIM |")
print("|---|---|---:|---:|")
for ranks, mode, limit in [(1, "remote", 0.0005), (1, "local", 0.0005), (2, "remote", 0.005)]:
    name = "server%d-%s" % (ranks, mode)
    prefix = os.path.join(out, name)
    server = Server(pvserver, ranks)
    start = time.time()
    rc, log = run([pvpython, render, prefix] + SIZE + ["localhost:%d" % server.port, mode])
    server.stop()
    if rc != 0 or "rendered" not in log:
        failures.append("%s: pvpython exited with %d:\n%s" % (name, rc, log[-3000:]))
        continue
    pieces = [line.split() for line in log.splitlines() if line.startswith("ranks")]
    if ranks > 1 and (not pieces or pieces[-1][3] != str(ranks)):
        failures.append("%s: the data is not split across the ranks: %s" % (name, pieces))
    for style in ["none", "comic", "pixel", "sketch", "comic-subject"]:
        a = read("%s-%s.png" % (reference, style))
        b = read("%s-%s.png" % (prefix, style))
        if a.GetDimensions() != b.GetDimensions():
            failures.append("%s %s: size %s, pvbatch %s" % (name, style, b.GetDimensions(),
                                                          a.GetDimensions()))
            continue
        pixels = a.GetDimensions()[0] * a.GetDimensions()[1]
        far = M.CountDifferences(a, b, 16.0)
        ssim = M.SSIM(a, b, 255.0)
        print("| %d rank%s, %s rendering | %s | %d (%.3f%%) | %.4f |" % (
            ranks, "s" if ranks > 1 else "", mode, style, far, 100.0 * far / pixels, ssim))
        if far > limit * pixels:
            failures.append("%s %s: %d pixels beyond 16 levels (at most %.2f%%)"
                            % (name, style, far, 100 * limit))
    print("(%s: %.0f s)" % (name, time.time() - start))

plain_pvserver = "/usr/bin/pvserver"
plain_pvpython = None
with open(pvpython) as wrapper:  # the pvpython the wrapper runs, without the plugin
    for line in wrapper:
        if line.startswith("program="):
            plain_pvpython = line.split("=", 1)[1].strip().strip('"')
for mode, server_program, client in [("both", pvserver, [pvpython]),
                                     ("server-only", pvserver, ["env", "-u", "PV_PLUGIN_PATH",
                                      "-u", "PV_PLUGIN_CONFIG_FILE", "-u", "PYTHONPATH",
                                      plain_pvpython]),
                                     ("client-only", plain_pvserver, [pvpython])]:
    if server_program == plain_pvserver:
        # ParaView's Python for the plain server: the same as the wrappers give pvbatch
        with open(pvbatch) as wrapper:
            for line in wrapper:
                if line.startswith("pv_python="):
                    path = line.split("=", 1)[1].strip().strip('"')
                    if path:
                        env["PYTHONPATH"] = path + os.pathsep + env.get("PYTHONPATH", "")
    server = Server(server_program)
    rc, log = run(client + [checks, "localhost:%d" % server.port, mode])
    server.stop()
    lines = [line for line in log.splitlines() if line.startswith((
        "plugin on", "CreateView", "rendered", "a render", "the checked reader"))]
    print("%s: %s" % (mode, "; ".join(lines)))
    if rc != 0 or "checks passed" not in log:
        failures.append("%s: pvpython exited with %d (134 is an abort):\n%s"
                        % (mode, rc, log[-3000:]))

for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
