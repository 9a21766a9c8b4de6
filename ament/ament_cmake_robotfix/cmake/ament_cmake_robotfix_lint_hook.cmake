# Run by ament_lint_auto_find_test_dependencies() in a package that lists
# ament_cmake_robotfix as a <test_depend>: adds the robotfix test when the package has
# Python files.

file(GLOB_RECURSE _robotfix_python_files FOLLOW_SYMLINKS "*.py")
if(_robotfix_python_files)
  message(STATUS "Added test 'robotfix' to check units, frames and refinements "
    "of the Python code")
  ament_robotfix()
endif()
