# The test tiers: every CTest test carries exactly one of these labels, and `slow` besides when it
# takes more than about 20 s on CI's 2 cores (docs/testing.md says what each tier holds, what CI
# runs where, and why). `ctest -L unit` is the quick loop after a change, `ctest -LE slow` skips
# the long measures, `ctest -L paraview` runs the plugin's tests. The test source.tiers
# (scripts/check_tiers.py) fails on a test without a tier or with two.
#   unit      C++ and Python tests of one class or function, and the source and doc rules
#   render    regression images (VTK's harness) and the benchmark's smoke run
#   realdata  the real-data set's measures (Testing/RealData)
#   paraview  the plugin in pvbatch, pvserver, mpiexec and the GUI
#   cli       the vtkstylize program: renders, options, refusals, warnings
#   corpus    hostile input read through the program, Python and ParaView, and mutation fuzzing
#   fuzz      the libFuzzer targets' committed corpus replayed
#   install   the install tree, a moved prefix and a downstream project
set(VTKSTYLIZE_TEST_TIERS unit render realdata paraview cli corpus fuzz install)

# stylize_test_tier(TIER TEST...): puts the tests (of this directory) into TIER.
function (stylize_test_tier tier)
  if (NOT tier IN_LIST VTKSTYLIZE_TEST_TIERS)
    message(FATAL_ERROR "stylize_test_tier: '${tier}' is not a tier (${VTKSTYLIZE_TEST_TIERS})")
  endif ()
  set_property(TEST ${ARGN} APPEND PROPERTY LABELS ${tier})
endfunction ()

# stylize_test_tiers(DEFAULT [REGEX TIER]... [SLOW TEST...]): every test of this directory that is
# not in a tier yet goes into the TIER of the first REGEX its name matches, else into DEFAULT; the
# tests after SLOW are labelled slow too. Called once at the end of a directory's tests.
function (stylize_test_tiers default)
  cmake_parse_arguments(PARSE_ARGV 1 _arg "" "" "SLOW")
  get_property(_tests DIRECTORY PROPERTY TESTS)
  foreach (_test IN LISTS _tests)
    get_test_property(${_test} LABELS _labels)
    set(_has_tier OFF)
    foreach (_label IN LISTS _labels)
      if (_label IN_LIST VTKSTYLIZE_TEST_TIERS)
        set(_has_tier ON)
      endif ()
    endforeach ()
    if (_has_tier)
      continue ()
    endif ()
    set(_tier "${default}")
    set(_rules ${_arg_UNPARSED_ARGUMENTS})
    while (_rules)
      list(POP_FRONT _rules _regex _rule_tier)
      if (_test MATCHES "${_regex}")
        set(_tier "${_rule_tier}")
        break ()
      endif ()
    endwhile ()
    stylize_test_tier(${_tier} ${_test})
  endforeach ()
  foreach (_test IN LISTS _arg_SLOW)
    if (_test IN_LIST _tests)
      set_property(TEST ${_test} APPEND PROPERTY LABELS slow)
    endif ()
  endforeach ()
endfunction ()
