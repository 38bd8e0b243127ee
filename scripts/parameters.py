#!/usr/bin/python3
"""Parameter reference of the VTK Stylize passes, generated from the wrapped classes.

    /usr/bin/python3 scripts/parameters.py           # writes docs/PARAMETERS.md, the tables
                                                     # between markers in README.md and docs/,
                                                     # the ParaView XML in Plugin/View/ and
                                                     # vtkstylize's option table
    /usr/bin/python3 scripts/parameters.py --check   # verifies them, prints a diff, exit 1 on drift

The entry point: the generator is the package scripts/stylize_parameters/ (its __init__.py
describes what it reads and writes; one module per job). Needs the build's python folder on
PYTHONPATH (build/python and build/lib are tried when the import fails).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from stylize_parameters.main import main  # noqa: E402

if __name__ == "__main__":
    sys.exit(main())
