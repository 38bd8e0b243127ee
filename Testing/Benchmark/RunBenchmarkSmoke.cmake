# Runs vtkStylizeBenchmark --quick (then ARGS, more options separated by spaces) and checks that
# it exits 0, writes a non-empty CSV and Markdown file and prints no VTK error. Usage:
#   cmake -DBENCHMARK=<exe> -DCSV=<file> -DMARKDOWN=<file> [-DARGS="<option> <value> ..."]
#     -P RunBenchmarkSmoke.cmake
foreach (var IN ITEMS BENCHMARK CSV MARKDOWN)
  if (NOT DEFINED ${var})
    message(FATAL_ERROR "${var} is not set")
  endif ()
endforeach ()
file(REMOVE "${CSV}" "${MARKDOWN}")
separate_arguments(args UNIX_COMMAND "${ARGS}")
execute_process(
  COMMAND "${BENCHMARK}" --quick ${args} --csv "${CSV}" --markdown "${MARKDOWN}"
  RESULT_VARIABLE result
  OUTPUT_VARIABLE out
  ERROR_VARIABLE err)
message("${out}")
if (err)
  message("stderr:\n${err}")
endif ()
if (NOT result EQUAL 0)
  message(FATAL_ERROR "vtkStylizeBenchmark exited with '${result}'")
endif ()
foreach (file IN ITEMS "${CSV}" "${MARKDOWN}")
  if (NOT EXISTS "${file}")
    message(FATAL_ERROR "vtkStylizeBenchmark did not write ${file}")
  endif ()
  file(SIZE "${file}" size)
  if (size EQUAL 0)
    message(FATAL_ERROR "vtkStylizeBenchmark wrote an empty ${file}")
  endif ()
endforeach ()
file(STRINGS "${CSV}" rows)
list(LENGTH rows nrows)
if (nrows LESS 2)
  message(FATAL_ERROR "${CSV} has no result row")
endif ()
if ("${out}${err}" MATCHES "ERROR:|should have been deleted")
  message(FATAL_ERROR "vtkStylizeBenchmark printed VTK errors")
endif ()
