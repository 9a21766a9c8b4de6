"""RobotFix: static checking of units, frames and refinements in ROS Python code."""

__version__ = "0.1.0"

# the collector's thresholds for a check (Python's: 700, 10, 10): young collections
# wait for 200,000 allocations, as mypy's do, because a check makes millions of
# short-lived objects while large trees stay alive (`run.check_paths`; the one-shot
# commands' whole process, `cli.run`)
GC_THRESHOLDS = (200_000, 50, 1000)
