# The ParaView plugin build: this project configured a second time (by the ExternalProject in
# the top-level CMakeLists.txt, with VTKSTYLIZE_PARAVIEW_MODE=ON) against ParaView 5.11 and its
# own VTK (9.2-based), which cannot share a configure with the VTK 9.1 build.
#
# Debian's paraview-dev names files that only python3-paraview ships, and python3-paraview
# conflicts with python3-vtk9 (the VTK build's Python). Unless python3-paraview is installed,
# its .deb is downloaded (apt-get download, no root needed) and unpacked into this build tree,
# and a copy of ParaView's CMake package is pointed at it (cmake/stylize_paraview_overlay.py).
# Nothing outside the build tree changes; pvbatch and paraview then run with PYTHONPATH at
# the unpacked package (the wrappers bin/pvbatch-stylize, paraview-stylize, pvserver-stylize
# and pvpython-stylize do that).

set(VTKSTYLIZE_PARAVIEW_SYSTEM_DIR
  "/usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/cmake/paraview-5.11"
  CACHE PATH "Debian's ParaView 5.11 CMake package")
set(VTKSTYLIZE_PARAVIEW_PYTHON_ROOT "${CMAKE_BINARY_DIR}/python3-paraview"
  CACHE PATH "Where python3-paraview is unpacked when it is not installed")

if (EXISTS "/usr/lib/python3/dist-packages/paraview/__init__.py")
  set(_pv_python_path "")
  set(_pv_dir "${VTKSTYLIZE_PARAVIEW_SYSTEM_DIR}")
else ()
  set(_root "${VTKSTYLIZE_PARAVIEW_PYTHON_ROOT}")
  set(_pv_python_path "${_root}/usr/lib/python3/dist-packages")
  if (NOT EXISTS "${_pv_python_path}/paraview/__init__.py")
    file(GLOB _debs "${CMAKE_BINARY_DIR}/python3-paraview_*.deb")
    if (NOT _debs)
      message(STATUS "Downloading python3-paraview (apt-get download) into ${CMAKE_BINARY_DIR}")
      execute_process(COMMAND apt-get download python3-paraview
        WORKING_DIRECTORY "${CMAKE_BINARY_DIR}" RESULT_VARIABLE _rc OUTPUT_QUIET ERROR_QUIET)
      file(GLOB _debs "${CMAKE_BINARY_DIR}/python3-paraview_*.deb")
      if (NOT _debs)
        message(FATAL_ERROR "apt-get download python3-paraview failed (${_rc}): put the .deb "
          "into ${CMAKE_BINARY_DIR} or install python3-paraview")
      endif ()
    endif ()
    list(GET _debs 0 _deb)
    execute_process(COMMAND dpkg-deb -x "${_deb}" "${_root}" RESULT_VARIABLE _rc)
    if (NOT _rc EQUAL 0)
      message(FATAL_ERROR "dpkg-deb -x ${_deb} failed (${_rc})")
    endif ()
  endif ()
  set(_pv_dir "${CMAKE_BINARY_DIR}/paraview-cmake/paraview-5.11")
  if (NOT EXISTS "${_pv_dir}/paraview-config.cmake")
    execute_process(
      COMMAND "${Python3_EXECUTABLE}" "${CMAKE_SOURCE_DIR}/cmake/stylize_paraview_overlay.py"
        "${VTKSTYLIZE_PARAVIEW_SYSTEM_DIR}" "${_pv_dir}" "${_root}" /usr
      RESULT_VARIABLE _rc)
    if (NOT _rc EQUAL 0)
      message(FATAL_ERROR "Could not prepare ParaView's CMake package (${_rc})")
    endif ()
  endif ()
endif ()
set(ParaView_DIR "${_pv_dir}" CACHE PATH "ParaView's CMake package (prepared)" FORCE)
set(VTKSTYLIZE_PARAVIEW_PYTHONPATH "${_pv_python_path}")

find_package(Python3 3.9 REQUIRED COMPONENTS Interpreter Development)
# pqApplicationComponents: the GUI's File menu entries (Qt; qtbase5-dev, libqt5svg5-dev and
# qttools5-dev give the Qt CMake packages ParaView's GUI modules ask for)
find_package(ParaView 5.11 REQUIRED COMPONENTS RemotingViews pqApplicationComponents)
# The readers VTKStylize::Filters uses (vtkStylizeReader): requested from ParaView's VTK so that
# their own dependencies (NetCDF, HDF5) are found too; VTKStylize::Figures draws scalar bars.
# The File menu entries call Python (Python, PythonInterpreter, WrappingPythonCore); ParaView's
# GUI modules link VTK's Xdmf libraries, whose LibXml2 and Boost targets are only imported when
# libxml2, xdmf2 and xdmf3 are asked for.
find_package(VTK REQUIRED COMPONENTS
  Python PythonInterpreter WrappingPythonCore libxml2 xdmf2 xdmf3
  RenderingAnnotation FiltersExtraction IOCore IOLegacy IOXML IOXMLParser IOGeometry IOExodus
  IOEnSight IOPLY RenderingVolume CommonMisc)
include("${VTK_DIR}/vtkEncodeString.cmake")

paraview_plugin_scan(
  PLUGIN_FILES      "${CMAKE_SOURCE_DIR}/Plugin/paraview.plugin"
  ENABLE_BY_DEFAULT ON
  PROVIDES_PLUGINS  _stylize_plugins)
paraview_plugin_build(
  PLUGINS              ${_stylize_plugins}
  RUNTIME_DESTINATION  "${CMAKE_INSTALL_BINDIR}"
  LIBRARY_DESTINATION  "${CMAKE_INSTALL_LIBDIR}"
  LIBRARY_SUBDIRECTORY "paraview-5.11/plugins"
  PLUGINS_FILE_NAME    "vtkstylize.paraview.plugins.xml"
  AUTOLOAD             ${_stylize_plugins}
  TARGET               VTKStylize::paraview_plugins
  INSTALL_HEADERS      OFF)

# Wrappers that run ParaView's programs with the plugin available and ParaView's Python found,
# from the build tree and from the install tree (Plugin/paraview-wrapper.sh.in says how).
set(_plugin_dir_build "${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_LIBDIR}/paraview-5.11/plugins")
set(_pv_python_install "${CMAKE_INSTALL_LIBDIR}/vtkstylize/python3-paraview")
foreach (_pv_program pvbatch paraview pvserver pvpython)
  set(_system_program "/usr/bin/${_pv_program}")
  set(_build_program "${_system_program}")
  set(_install_program "${_system_program}")
  if (_pv_program STREQUAL "pvpython" AND VTKSTYLIZE_PARAVIEW_PYTHONPATH)
    # pvpython ships in python3-paraview: the unpacked copy (it finds its modules beside itself)
    set(_build_program "${VTKSTYLIZE_PARAVIEW_PYTHON_ROOT}/usr/bin/pvpython")
    set(_install_program "\${prefix}/${_pv_python_install}/bin/pvpython")
  endif ()
  set(VTKSTYLIZE_PLUGIN_DIR "${_plugin_dir_build}")
  set(VTKSTYLIZE_WRAPPER_PYTHONPATH "${VTKSTYLIZE_PARAVIEW_PYTHONPATH}")
  set(VTKSTYLIZE_WRAPPER_EXECUTABLE "${_build_program}")
  configure_file("${CMAKE_SOURCE_DIR}/Plugin/paraview-wrapper.sh.in"
    "${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_BINDIR}/${_pv_program}-stylize" @ONLY
    FILE_PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE WORLD_READ
    WORLD_EXECUTE)
  set(VTKSTYLIZE_PLUGIN_DIR "\${prefix}/${CMAKE_INSTALL_LIBDIR}/paraview-5.11/plugins")
  set(VTKSTYLIZE_WRAPPER_PYTHONPATH "")
  if (VTKSTYLIZE_PARAVIEW_PYTHONPATH)
    set(VTKSTYLIZE_WRAPPER_PYTHONPATH "\${prefix}/${_pv_python_install}/lib/python3/dist-packages")
  endif ()
  set(VTKSTYLIZE_WRAPPER_EXECUTABLE "${_install_program}")
  configure_file("${CMAKE_SOURCE_DIR}/Plugin/paraview-wrapper.sh.in"
    "${CMAKE_BINARY_DIR}/install-wrappers/${_pv_program}-stylize" @ONLY)
  install(PROGRAMS "${CMAKE_BINARY_DIR}/install-wrappers/${_pv_program}-stylize"
    DESTINATION "${CMAKE_INSTALL_BINDIR}")
endforeach ()
if (VTKSTYLIZE_PARAVIEW_PYTHONPATH)
  # The unpacked python3-paraview (its modules and pvpython) travels with the install.
  install(DIRECTORY "${VTKSTYLIZE_PARAVIEW_PYTHONPATH}/"
    DESTINATION "${_pv_python_install}/lib/python3/dist-packages" USE_SOURCE_PERMISSIONS)
  install(DIRECTORY "${VTKSTYLIZE_PARAVIEW_PYTHON_ROOT}/usr/bin/"
    DESTINATION "${_pv_python_install}/bin" USE_SOURCE_PERMISSIONS)
endif ()
