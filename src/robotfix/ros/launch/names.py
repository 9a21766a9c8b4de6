"""Which files are launch files, by name (discovery needs no reader for it)."""

from __future__ import annotations

YAML_SUFFIXES = (".yaml", ".yml")
LAUNCH_SUFFIXES = (".py", ".xml", *YAML_SUFFIXES, ".launch")  # in a `launch/` folder
# the ends of the names only launch files have (every file of a walk is asked)
_ENDINGS = (
    ".launch",
    *(
        f"{sep}launch{suffix}"
        for sep in (".", "_")
        for suffix in (".py", ".xml", *YAML_SUFFIXES)
    ),
)


def is_launch_name(name: str) -> bool:
    """A file name only launch files have (`x.launch.py`, `x_launch.py`,
    `x.launch.xml`, `x.launch.yaml`, `x.launch`)."""
    return name.endswith(_ENDINGS)


def is_launch_file(folder_name: str, name: str) -> bool:
    """A launch file by where it is: named as one, or a launch-file kind of file in a
    `launch/` folder."""
    return is_launch_name(name) or (
        folder_name == "launch" and name.endswith(LAUNCH_SUFFIXES)
    )
