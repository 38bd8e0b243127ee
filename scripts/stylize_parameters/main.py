"""The command line: read the classes, generate every output, then write the stale ones or, with
--check, print their diffs and fail."""
import argparse
import difflib
import glob
import os
import sys

from .cli_table import render_cli_table
from .config import (CLASSES, CLI_TABLE, DESCRIPTION, DIFF_LINES, OUTPUT, README, ROOT,
                     XML_FILTERS, XML_PASSES, XML_VIEW)
from .markdown import BLOCK, render_parameters, render_readme
from .model import describe_class, import_vtkstylize
from .paraview_xml import (render_xml_filters, render_xml_passes, render_xml_representation,
                          render_xml_volume_displays,
                           render_xml_view, xml_exposed)


def parse_args(argv=None):
    parser = argparse.ArgumentParser(description=DESCRIPTION)
    parser.add_argument("--check", action="store_true",
                        help="verify docs/PARAMETERS.md, the README tables and the ParaView XML "
                             "in Plugin/View/; write nothing")
    parser.add_argument("--build", default=os.path.join(ROOT, "build"),
                        help="build folder whose python/ and lib/ hold vtkstylize (used when the "
                             "import fails)")
    parser.add_argument("--quiet", action="store_true", help="do not print warnings")
    return parser.parse_args(argv)


def markdown_outputs(docs, errors, warnings):
    """[(path, text)] of PARAMETERS.md and of README.md and docs/*.md with their blocks."""
    outputs = [(OUTPUT, render_parameters(docs))]
    blocks = 0
    for path in [README] + sorted(os.path.relpath(f, ROOT) for f in
                                  glob.glob(os.path.join(ROOT, "docs", "*.md"))):
        if path == OUTPUT:
            continue
        with open(os.path.join(ROOT, path)) as f:
            text = f.read()
        blocks += len(BLOCK.findall(text))
        outputs.append((path, render_readme(path, text, docs, errors)))
    if not blocks:
        warnings.append("no <!-- parameters:CLASS begin --> blocks in %s or docs/" % README)
    return outputs


def view_outputs(by_class, errors):
    """[(path, text)] of StylizePasses.xml and StylizeView.xml."""
    exposed, skipped = xml_exposed(by_class, errors)
    xml_passes = render_xml_passes(by_class, exposed, skipped)
    with open(os.path.join(ROOT, XML_VIEW)) as f:
        xml_view = render_xml_view(f.read(), exposed, errors)
    xml_view = render_xml_representation(xml_view, by_class["vtkStylizeLightingPass"], errors)
    xml_view = render_xml_volume_displays(xml_view, errors)
    return [(XML_PASSES, xml_passes), (XML_VIEW, xml_view)]


def update(outputs, check):
    """Write the outputs that differ from the files (with check: print their diffs instead);
    the paths of those that differ."""
    stale = []
    for path, new in outputs:
        full = os.path.join(ROOT, path)
        old = open(full).read() if os.path.exists(full) else None
        if old == new:
            continue
        stale.append(path)
        if check:
            if old is None:
                print("error: %s is missing" % path)
                continue
            diff = list(difflib.unified_diff(old.splitlines(True), new.splitlines(True),
                                             "a/" + path, "b/" + path))
            sys.stdout.writelines(diff[:DIFF_LINES])
            if len(diff) > DIFF_LINES:
                print("... (%d more lines of diff in %s)" % (len(diff) - DIFF_LINES, path))
        else:
            os.makedirs(os.path.dirname(full), exist_ok=True)
            with open(full, "w") as f:
                f.write(new)
            print("wrote %s" % path)
    return stale


def summary(docs, stale, errors, warnings, check):
    """Print the errors and the outcome; the exit status."""
    for e in errors:
        print("error: " + e)
    count = sum(len(d.params) for d in docs)
    if check:
        if stale:
            print("error: %s out of date: run /usr/bin/python3 scripts/parameters.py"
                  % ", ".join(stale))
        if stale or errors:
            return 1
        print("parameters: %d parameters of %d classes agree with the code (%d warnings)"
              % (count, len(docs), len(warnings)))
        return 0
    print("parameters: %d parameters of %d classes, %d warnings, %d errors"
          % (count, len(docs), len(warnings), len(errors)))
    return 1 if errors else 0


def main(argv=None):
    args = parse_args(argv)
    mod = import_vtkstylize(args.build)
    from vtkmodules.vtkCommonCore import vtkObject
    vtkObject.GlobalWarningDisplayOff()  # probing out-of-range values makes setters warn
    errors, warnings = [], []
    docs = [describe_class(mod, cls, errors, warnings) for cls in CLASSES]
    by_class = {d.cls: d for d in docs}
    outputs = markdown_outputs(docs, errors, warnings)
    outputs += view_outputs(by_class, errors)
    if not args.quiet:
        for w in warnings:
            print("warning: " + w)
    outputs += [(XML_FILTERS, render_xml_filters(by_class, errors)),
                (CLI_TABLE, render_cli_table(by_class, errors))]
    stale = update(outputs, args.check)
    return summary(docs, stale, errors, warnings, args.check)
