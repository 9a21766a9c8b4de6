# ament_robotfix([TESTNAME name] [CONFIG_FILE file] [TIMEOUT seconds] [STRICT]
#                [EXCLUDE pattern ...] [MSG_PATHS dir ...] [path ...])
#
# Adds a test that runs RobotFix (the `ament_robotfix` program) on the given files and
# folders (default: the package's source folder) and writes its results as xUnit XML to
# ${AMENT_TEST_RESULTS_DIR}/${PROJECT_NAME}/<name>.xunit.xml, where `colcon test-result`
# reads them. The test is labelled "robotfix" and "linter", so `ctest -L linter` (or
# `colcon test --ctest-args -LE linter`) selects or skips it with the other linters.
#
#   TESTNAME     the test's name (default: robotfix)
#   CONFIG_FILE  a TOML file with a [tool.robotfix] table (default: the nearest
#                pyproject.toml above each path)
#   TIMEOUT      seconds before ctest stops it (default: 120)
#   STRICT       warnings fail the test too
#   EXCLUDE      file names or gitignore-style patterns to skip
#   MSG_PATHS    more folders of .msg/.srv/.action files
#
# The per-file cache is kept in the build folder, never in the package's sources.

function(ament_robotfix)
  cmake_parse_arguments(ARG "STRICT" "CONFIG_FILE;TESTNAME;TIMEOUT"
    "EXCLUDE;MSG_PATHS" ${ARGN})
  if(NOT ARG_TESTNAME)
    set(ARG_TESTNAME "robotfix")
  endif()
  if(NOT ARG_TIMEOUT)
    set(ARG_TIMEOUT 120)
  endif()

  find_program(ament_robotfix_BIN NAMES "ament_robotfix")
  if(NOT ament_robotfix_BIN)
    message(FATAL_ERROR "ament_robotfix() could not find the program "
      "'ament_robotfix': install RobotFix (pip install from a checkout or a wheel)")
  endif()

  set(result_file
    "${AMENT_TEST_RESULTS_DIR}/${PROJECT_NAME}/${ARG_TESTNAME}.xunit.xml")
  set(cache_dir "${CMAKE_BINARY_DIR}/ament_robotfix/${ARG_TESTNAME}_cache")
  set(cmd "${ament_robotfix_BIN}" "--xunit-file" "${result_file}"
    "--cache-dir" "${cache_dir}")
  if(ARG_CONFIG_FILE)
    list(APPEND cmd "--config" "${ARG_CONFIG_FILE}")
  endif()
  if(ARG_STRICT)
    list(APPEND cmd "--strict")
  endif()
  foreach(msg_path ${ARG_MSG_PATHS})
    list(APPEND cmd "--msg-path" "${msg_path}")
  endforeach()
  if(ARG_EXCLUDE)
    list(APPEND cmd "--exclude" ${ARG_EXCLUDE})
  endif()
  if(ARG_UNPARSED_ARGUMENTS)
    # `--` ends the options: the rest are paths, even after EXCLUDE's patterns
    list(APPEND cmd "--" ${ARG_UNPARSED_ARGUMENTS})
  endif()

  file(MAKE_DIRECTORY "${CMAKE_BINARY_DIR}/ament_robotfix")
  ament_add_test(
    "${ARG_TESTNAME}"
    COMMAND ${cmd}
    OUTPUT_FILE "${CMAKE_BINARY_DIR}/ament_robotfix/${ARG_TESTNAME}.txt"
    RESULT_FILE "${result_file}"
    TIMEOUT "${ARG_TIMEOUT}"
    WORKING_DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}"
  )
  set_tests_properties(
    "${ARG_TESTNAME}"
    PROPERTIES
    LABELS "robotfix;linter"
  )
endfunction()
