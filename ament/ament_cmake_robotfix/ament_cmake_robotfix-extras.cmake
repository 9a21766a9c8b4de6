# Loaded by find_package(ament_cmake_robotfix): defines ament_robotfix() and lets
# ament_lint_auto call it through the hook.

find_package(ament_cmake_test QUIET REQUIRED)

include("${ament_cmake_robotfix_DIR}/ament_robotfix.cmake")

ament_register_extension("ament_lint_auto" "ament_cmake_robotfix"
  "ament_cmake_robotfix_lint_hook.cmake")
