"""Stubs: `.pyi` files that say, with `Annotated` signatures, what the functions and
classes of libraries RobotFix cannot see into take and return (see `load.py`)."""
