"""RobotFix: static checking of units, frames and refinements in ROS Python code."""

__version__ = "0.1.0"
