"""The ParaView tests' renders on N ranks, in one pvbatch: the scenes that paraview.mpi,
paraview.realdata_mpi, paraview.translucent, paraview.volumes and paraview.client_server
compare share one run per rank count (test_ranks.py starts it under mpiexec -n 1 and -n 2).

    mpiexec -n N pvbatch-stylize render_ranks.py OUTPUT_DIR DATA_DIR

Runs, in this order and each into its own prefix of OUTPUT_DIR:
  contour-...      render_styles.py: the Wavelet contour in every style (paraview.mpi, and the
                   reference of paraview.client_server)
  realdata-...     render_realdata.py: the bunny scan and the Exodus vessel, split by Redistribute
                   DataSet (paraview.realdata_mpi)
  translucent-...  render_translucent.py split: the translucent bunny around the gear, both split
                   (paraview.translucent's ranks part)
  volume-...       render_volume.py: a CT volume (ParaView's Volume representation) in every
                   style, read in pieces (paraview.volumes)
Each script's output follows a line "== NAME" (NAME: contour, realdata, translucent, volume), so
that a test reads its own "ranks ..." or "pieces ..." lines and its "rendered".
"""
import os
import runpy
import sys

out, data = sys.argv[1], sys.argv[2]
here = os.path.dirname(os.path.abspath(__file__))
for name, script, arguments in (("contour", "render_styles.py", []),
                                ("realdata", "render_realdata.py", [data]),
                                ("translucent", "render_translucent.py", [data, "split"]),
                                ("volume", "render_volume.py", [data])):
    print("== " + name, flush=True)
    sys.argv = [script, os.path.join(out, name)] + arguments
    runpy.run_path(os.path.join(here, script), run_name="__main__")
    sys.stdout.flush()
