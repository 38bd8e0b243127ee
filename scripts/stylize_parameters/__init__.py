"""Parameter reference of the VTK Stylize passes, generated from the wrapped classes.

    /usr/bin/python3 scripts/parameters.py           # writes docs/PARAMETERS.md, the tables
                                                     # between markers in README.md and docs/,
                                                     # and the ParaView XML in Plugin/View/
    /usr/bin/python3 scripts/parameters.py --check   # verifies them, prints a diff, exit 1 on drift

The one source is the classes, read through VTK's Python wrapping (the build's vtkstylize
package); no header is parsed:

- the parameters: every Set<Name>/Get<Name> pair of the class and its bases below VTK's
  render-pass plumbing, in declaration order (the wrapping keeps the header's order);
- their meaning: the setter's docstring, which VTK's wrapping makes from the header comment (in a
  ///@{ group only the first method gets it: the others share it);
- defaults: Get<Name>() of a new instance;
- ranges: Get<Name>MinValue()/Get<Name>MaxValue() (vtkSetClampMacro); for other setters, found by
  setting out-of-range values and reading them back, else the range the comment states;
- enumerations: the class's enum named after the setting in the plural (Anchor -> Anchors, the
  project's convention; Channels -> ChannelBits is a bit mask), its constants the values;
- the per-actor settings: the static SetActor*() helpers, probed on an actor's property keys.

The comments' own statements of ranges and defaults are compared with the code: a contradiction is
an error, like a parameter without a comment. A missing unit, range or default in a comment is a
warning. Parameter tables in Markdown are generated copies between marker comments
(<!-- parameters:CLASS begin --> ... <!-- parameters:CLASS end -->) in README.md and docs/*.md;
--check also fails on a hand-written parameter table outside them.

The ParaView plugin's server-manager XML is generated from the same description:
Plugin/View/StylizePasses.xml (a proxy per pass, a property per parameter: kind, default, range
domain, documentation), the blocks of Plugin/View/StylizeView.xml between its
<!-- generated:exposed:PROXY begin/end --> markers (the view's <ExposedProperties>), and between
<!-- generated:representation begin/end --> the Stylized Surface representation's per-actor
lighting properties (those of vtkStylizeLightingPass that a SetActor*() helper overrides), and
between <!-- generated:volume-displays begin/end --> the StylizeVolume property of ParaView's
representations with a Volume type (XML_VOLUME_DISPLAYS).
Object-valued parameters are not exposed, nor those in XML_SKIP (set by the view).

Needs the build's python folder on PYTHONPATH (build/python and build/lib are tried when the
import fails). Only instantiates the classes: no display, no OpenGL context.

The package, by job (scripts/parameters.py is the entry point; `python3 -m stylize_parameters`
with scripts/ as the working folder does the same):

- config.py: the tables (classes, output paths, units, XML proxies and skips, CLI spellings);
- values.py: numbers, and the values, ranges, defaults and units a comment states;
- model.py: the classes read through the wrapping into Param and ClassDoc;
- checks.py: each setting's default, unit and range, and the comment against the code;
- markdown.py: docs/PARAMETERS.md and the README/docs blocks;
- paraview_xml.py: StylizePasses.xml, StylizeFilters.xml and StylizeView.xml's blocks;
- cli_table.py: vtkstylize's option table (vtkstylizeSettings.inc);
- main.py: the command line: generate every output, then write it or --check it.
"""
