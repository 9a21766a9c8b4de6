"""A cached run over an unchanged tree (issue 9 speed, issue 13 item 5): files are
known by their stat, parameter files and the catalog by what they were read from,
and every answer is still exactly the uncached one."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

import pytest

import robotfix
import robotfix.cache
import robotfix.run
from robotfix import cli, fs
from robotfix.cache import MENTION_WORDS
from robotfix.config import Config
from robotfix.paramcheck import MENTIONS
from robotfix.run import check_paths

PACKAGES = Path(__file__).parent / "cases" / "params" / "packages"

CMD_MSG = "float64 speed  # [m/s]\n#RobotFix# speed <= 2.0\n"
NODE = """\
import rclpy
from rclpy.node import Node
from demo.msg import Cmd
from demo.limits import clamp


class Driver(Node):
    def __init__(self) -> None:
        super().__init__("driver")
        self.pub = self.create_publisher(Cmd, "cmd", 10)
        self.create_timer(0.1, self.tick)

    def tick(self) -> None:
        c = Cmd()
        c.speed = clamp(1.5)
        self.pub.publish(c)
"""
LIMITS = """\
from typing import Annotated


def clamp(x: float) -> Annotated[float, "_ <= 3.0"]:
    return min(x, 3.0)
"""
OTHER = """\
import rclpy
from rclpy.node import Node


class Other(Node):
    def __init__(self) -> None:
        super().__init__("other")
        self.count = 0
"""


def write(path: Path, text: str) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)


def age(root: Path, seconds: float = 60.0) -> None:
    """Every file's mtime well in the past (a file changed within `fs.RACY_NS` is
    always hashed). Its ctime, which no call sets back, is now: `tree` lets the
    stat fast path trust a recent stamp."""
    then = time.time() - seconds
    for path in root.rglob("*"):
        if path.is_file():
            os.utime(path, (then, then))


@pytest.fixture
def tree(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    # the files' ctimes are seconds old at most: trusted here, as they would be
    # RACY_NS later (every edit below changes a stamp, long after the last hash)
    monkeypatch.setattr(robotfix.cache, "RACY_NS", 0)
    monkeypatch.setattr(robotfix.run, "RACY_NS", 0)
    root = tmp_path / "ws"
    write(root / "pyproject.toml", "")
    demo = root / "src" / "demo"
    write(demo / "package.xml", "<package><name>demo</name></package>\n")
    write(demo / "msg" / "Cmd.msg", CMD_MSG)
    write(demo / "demo" / "__init__.py", "")
    write(demo / "demo" / "driver.py", NODE)
    write(demo / "demo" / "limits.py", LIMITS)
    write(demo / "demo" / "other.py", OTHER)
    shutil.copytree(PACKAGES / "ros2_driver", root / "src" / "ros2_driver")
    age(root)
    return root


def run(root: Path, cache: bool = True) -> tuple[str, int, int]:
    """The concise report, files checked, files whose results came from the cache."""
    config = Config(root=root)
    result = check_paths([root / "src"], config, use_cache=cache)
    text = cli.render(result, "concise", 1, 0)
    return text, len(result.checked), result.from_cache


def test_the_fixture_finds_something(tree: Path) -> None:
    text, files, cached = run(tree, cache=False)
    assert files == 7 and cached == 0  # with ros2_driver's limits.py
    assert "RF101" in text and "RF401" in text  # the driver's YAML
    assert "driver.py" in text  # clamp's 3.0 against Cmd's 2.0


def test_unchanged_files_are_not_read_again(
    tree: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    cold = run(tree)
    assert cold[2] == 0
    reads: list[str] = []
    real = fs.read_regular

    def counting(path: Path, *args: object, **kwargs: object) -> bytes:
        reads.append(str(path))
        return real(path, *args, **kwargs)  # type: ignore[arg-type]

    monkeypatch.setattr(fs, "read_regular", counting)
    warm = run(tree)
    assert warm == (cold[0], cold[1], cold[1])  # all from the cache, same report
    read = [r for r in reads if os.path.isfile(r)]  # not a probe for setup.py
    assert not [r for r in read if r.endswith((".py", ".yaml", ".msg"))]


def test_a_touched_file_is_rehashed_not_rechecked(tree: Path) -> None:
    cold = run(tree)
    age(tree, 30.0)  # every mtime changes, no byte does
    assert run(tree) == (cold[0], cold[1], cold[1])
    assert run(tree) == (cold[0], cold[1], cold[1])


def test_an_edited_file_is_rechecked(tree: Path) -> None:
    assert run(tree)[2] == 0
    other = tree / "src" / "demo" / "demo" / "other.py"
    other.write_text(OTHER + "        self.count += 1\n")
    text, files, cached = run(tree)
    assert cached == files - 1 and text == run(tree, cache=False)[0]


def test_an_edited_helper_rechecks_its_importers(tree: Path) -> None:
    run(tree)
    limits = tree / "src" / "demo" / "demo" / "limits.py"
    limits.write_text(LIMITS.replace("3.0", "1.0"))  # now within Cmd's 2.0
    text, files, cached = run(tree)
    assert cached == files - 2  # limits.py and driver.py, which imports it
    assert text == run(tree, cache=False)[0]
    assert "driver.py" not in text


def test_an_edited_parameter_file_is_rechecked(tree: Path) -> None:
    cold = run(tree)
    yaml = tree / "src" / "ros2_driver" / "config" / "near_misses.yaml"
    assert "near_misses.yaml" not in cold[0]
    yaml.write_text(yaml.read_text().replace("max_speed: 1.5", "max_speed: 9.5"))
    text, files, cached = run(tree)
    assert cached == files  # no Python file changed
    assert "near_misses.yaml" in text and "RF101" in text
    assert text == run(tree, cache=False)[0]


def test_a_changed_interface_file_rechecks_its_users(tree: Path) -> None:
    cold = run(tree)
    assert "driver.py" in cold[0]
    msg = tree / "src" / "demo" / "msg" / "Cmd.msg"
    msg.write_text(CMD_MSG.replace("2.0", "5.0"))  # clamp's 3.0 fits now
    text, files, cached = run(tree)
    assert cached < files and "driver.py" not in text
    assert text == run(tree, cache=False)[0]
    msg.write_text("float64 speed  # [m/s]\nnot a field line\n")  # broken: RF5xx
    text, _, _ = run(tree)
    assert text == run(tree, cache=False)[0] and "Cmd.msg" in text
    age(tree)
    assert run(tree)[0] == text  # its problem comes from the cache too


def test_mentions_cover_every_parameter_word() -> None:
    """A Python file the cache says mentions no parameter word is left out of the
    parameter files' key: the words must be all paramcheck's."""
    words = {w for group in MENTIONS.values() for w in group}
    assert words <= set(MENTION_WORDS)


def test_a_cached_run_imports_no_analysis(tree: Path) -> None:
    run(tree)  # fills the cache in this process
    probe = (
        "import sys\n"
        "import robotfix.run\n"
        "robotfix.run.RACY_NS = 0  # as in `tree`: Cmd.msg's ctime is recent\n"
        "from robotfix.cli import main\n"
        f"status = main(['check', {str(tree / 'src')!r}])\n"
        "heavy = ('robotfix.analysis', 'lark', 'z3', 'pint', 'robotfix.paramcheck')\n"
        "print(sorted(m for m in sys.modules if m.startswith(heavy)))\n"
    )
    done = run_probe(probe, tree)
    assert done.stdout.strip().endswith("[]"), done.stdout + done.stderr


def run_probe(probe: str, cwd: Path) -> subprocess.CompletedProcess[str]:
    """`python -c probe` in a fresh process, with this checkout's robotfix."""
    env = {**os.environ, "PYTHONPATH": str(Path(robotfix.__file__).parent.parent)}
    return subprocess.run(
        [sys.executable, "-c", probe],
        capture_output=True,
        text=True,
        env=env,
        cwd=cwd,
        check=False,
    )
