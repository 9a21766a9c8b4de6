"""RobotFix: a static checker for units, frames and refinements in ROS Python programs."""

__version__ = "0.1.0"
