# RobotFix for `colcon test`, beside test_flake8.py and test_pep257.py: copy this file into
# your ament_python package's test/ folder (`ament_robotfix --template > test/test_robotfix.py`,
# and your copyright header if ament_copyright checks it); setup.py lists pytest in
# extras_require={'test': ['pytest']} (recent setuptools ignore tests_require).
#
# colcon runs the tests in the package's source folder, so this checks the package's Python
# files against its msg/, srv/ and action/ interfaces: units, frames and refinements. Settings
# come from [tool.robotfix] in the package's pyproject.toml, or from arguments, e.g.
# main_with_errors(argv=['--exclude', 'test', '--strict']). The cache goes to the user cache
# folder, never into the package. The file follows ament_flake8's style (single quotes).

import pytest
from robotfix.ament import main_with_errors


@pytest.mark.robotfix
@pytest.mark.linter
def test_robotfix() -> None:
    rc, errors = main_with_errors(argv=[])
    assert rc == 0, 'RobotFix found problems:\n' + '\n'.join(errors)
