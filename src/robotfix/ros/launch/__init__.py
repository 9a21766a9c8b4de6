"""Launch files, read and never run: ROS 2 Python (`python.py`, with `ast`), ROS 2
XML and YAML and ROS 1 roslaunch XML (`frontend.py` over `tree.py`), into the
launch entries of `model.py`; `$(...)` substitutions and package paths in
`substitution.py`.

`read` follows the includes of files in the checked tree (each file at most once
on a chain, `MAX_INCLUDE_DEPTH` deep), with the arguments the includer passes.
"""
