#!/usr/bin/env python3
"""Makes Debian's ParaView 5.11 CMake package usable without installing python3-paraview.

Debian's paraview-dev CMake files name files that only python3-paraview ships (ParaView's
Python modules, its VTK's wrapping hierarchy files), and python3-paraview conflicts with
python3-vtk9, which the VTK build needs. This script copies the CMake package into a folder of
the build tree and points every path that does not exist on the system at a python3-paraview
package extracted (dpkg-deb -x) into the build tree; every other path keeps pointing at the
system. Nothing outside the build tree is touched.

usage: stylize_paraview_overlay.py SOURCE_CMAKE_DIR DEST_CMAKE_DIR EXTRACTED_ROOT SYSTEM_PREFIX
  SOURCE_CMAKE_DIR  e.g. /usr/lib/x86_64-linux-gnu/cmake/paraview-5.11
  DEST_CMAKE_DIR    the copy, to use as ParaView_DIR
  EXTRACTED_ROOT    the folder python3-paraview was extracted into (holds usr/...)
  SYSTEM_PREFIX     the prefix the package was installed to, e.g. /usr
"""
import os
import re
import shutil
import sys

# The variables Debian's exported CMake files compute from their own location.
PREFIX_VARIABLES = ("${_IMPORT_PREFIX}", "${_vtk_module_import_prefix}")


def resolve(rest, prefix, extracted):
    """The system path prefix+rest if it exists (or is a pattern), else the extracted one."""
    system = prefix + rest
    extra = os.path.join(extracted, prefix.lstrip("/"), rest.lstrip("/"))
    if not os.path.exists(system) and os.path.exists(extra):
        return extra
    return system


def rewrite(text, prefix, extracted):
    pattern = re.compile(r'(\$\{_IMPORT_PREFIX\}|\$\{_vtk_module_import_prefix\})([^";\s)]*)')
    text = pattern.sub(lambda m: resolve(m.group(2), prefix, extracted), text)
    # configure_package_config_file() packages compute their prefix from their own location.
    return re.sub(r'get_filename_component\(PACKAGE_PREFIX_DIR "[^"]*" ABSOLUTE\)',
                  'set(PACKAGE_PREFIX_DIR "%s")' % prefix, text)


def main(argv):
    if len(argv) != 5:
        sys.stderr.write(__doc__)
        return 2
    source, dest, extracted, prefix = argv[1:]
    if os.path.isdir(dest):
        shutil.rmtree(dest)
    shutil.copytree(source, dest, symlinks=False)
    count = 0
    for root, _, files in os.walk(dest):
        for name in files:
            if not name.endswith(".cmake"):
                continue
            path = os.path.join(root, name)
            with open(path, encoding="utf-8") as f:
                text = f.read()
            if not any(v in text for v in PREFIX_VARIABLES + ("PACKAGE_PREFIX_DIR",)):
                continue
            new = rewrite(text, prefix.rstrip("/"), extracted)
            if new != text:
                count += 1
                with open(path, "w", encoding="utf-8") as f:
                    f.write(new)
    print("rewrote %d CMake files of %s into %s" % (count, source, dest))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
