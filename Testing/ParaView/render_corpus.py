"""Reads the hostile-input corpus in pvbatch with the plugin, for hostile_corpus.py --runner paraview.

    pvbatch-stylize render_corpus.py CASES_JSON PROGRESS_FILE FIRST

CASES_JSON lists [path, folder] per case. From case FIRST on, each case is read with the plugin's
Stylize Checked Reader (vtkStylizeReader) with the case's folder as the working directory. A file
the reader refuses must give a one-line error message (a "refusal"); one it reads goes through
Extract Surface and the Principal Curvatures filter into the Stylize view, rendered in every
style and in the sketch along the filter's directions (a "render"). The progress file gets
"start N" before case N and "done N KIND SECONDS MAXRSS_KB MESSAGE" after it, written at once,
so that the driver can tell which case a crash or a hang happened in.
"""
import json
import os
import resource
import sys
import time

import paraview.simple as simple
from paraview.simple import CreateView, Delete, ExtractSurface, Hide, Render, Show

listing, progress, first = sys.argv[1], sys.argv[2], int(sys.argv[3])
cases = json.load(open(listing))
view = CreateView("StylizeView")
view.ViewSize = [64, 48]
view.OrientationAxesVisibility = 0
log = open(progress, "a")


def record(line):
    log.write(line + "\n")
    log.flush()
    os.fsync(log.fileno())


for index in range(first, len(cases)):
    path, folder = cases[index]
    record("start %d" % index)
    start = time.monotonic()
    os.chdir(folder)
    reader = simple.StylizeCheckedReader(FileName=path)
    reader.UpdatePipeline()
    reader.UpdatePropertyInformation()
    message = reader.GetPropertyValue("ErrorMessage") or ""
    if message:
        kind = "refusal" if "\n" not in message and message.strip() else "bad refusal"
    else:
        surface = ExtractSurface(Input=reader)
        curvatures = simple.PrincipalCurvatures(Input=surface)
        Show(curvatures, view)
        view.ResetCamera()
        for style in (0, 1, 2, 3):
            view.Style = style
            Render(view)
        view.SketchDirectionSource = 1
        Render(view)
        view.SketchDirectionSource = 0
        view.Style = 0
        Hide(curvatures, view)
        Delete(curvatures)
        Delete(surface)
        kind = "render"
    Delete(reader)
    record("done %d %s %.3f %d %s" % (index, kind, time.monotonic() - start,
                                      resource.getrusage(resource.RUSAGE_SELF).ru_maxrss,
                                      " ".join(message.split())))
record("finished")
