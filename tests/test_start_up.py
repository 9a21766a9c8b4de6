"""The fixed cost of every `robotfix check` process (issue 25): a cold check loads
no module only another command or another kind of file needs (each one's
dataclasses cost an `exec` per generated method at import)."""

from __future__ import annotations

import hashlib
import sys
from pathlib import Path
from typing import Any

import pytest

import robotfix
import robotfix.cache
from robotfix import fs
from robotfix.cache import _OWN_SUFFIXES, own_digest
from robotfix.config import Config
from robotfix.run import check_paths

sys.path.insert(0, str(Path(__file__).parent))
from test_cached_run import run_probe

NODE = """\
import rclpy
from rclpy.node import Node
from geometry_msgs.msg import Twist


class Driver(Node):
    def __init__(self) -> None:
        super().__init__("driver")
        self.pub = self.create_publisher(Twist, "cmd_vel", 10)

    def tick(self) -> None:
        msg = Twist()
        msg.linear.x = 0.5
        self.pub.publish(msg)
"""
# a probe's first lines: every stamp trusted at once (`fs.RACY_NS` 0 wherever it is
# read), as in a tree untouched for two seconds, so that the cache keeps everything
TRUSTED = """\
from robotfix import cache, discovery, run
from robotfix.project import modules
for module in (cache, discovery, run, modules):
    module.RACY_NS = 0
"""


def demo_package(root: Path) -> Path:
    """`root/src/demo`, a ROS package of an empty Python package: its folder."""
    package = root / "src" / "demo"
    (package / "demo").mkdir(parents=True)
    (package / "package.xml").write_text("<package><name>demo</name></package>")
    (package / "demo" / "__init__.py").write_text("")
    return package / "demo"


# the editor's memo (api.py), `robotfix suggest`'s flow log, and the readers of
# launch files, parameter YAML and C++ sources
NOT_LOADED = (
    "robotfix.analysis.unitmemo",
    "robotfix.analysis.skeleton",
    "robotfix.analysis.unitreads",
    "robotfix.analysis.flows",
    "robotfix.ros.launch.model",
    "robotfix.ros.paramfile",
    "robotfix.ros.yamlfile",
    "robotfix.ros.graph.cpp",
    "robotfix.ros.graph.cpp_scan",
)


def test_a_check_of_python_alone_loads_no_other_commands_modules(
    tmp_path: Path,
) -> None:
    (demo_package(tmp_path) / "driver.py").write_text(NODE)
    probe = (
        "import sys\n"
        "from robotfix.cli import main\n"
        f"main(['check', {str(tmp_path / 'src')!r}, '--no-cache', '-j', '1'])\n"
        f"print(sorted(m for m in {NOT_LOADED!r} if m in sys.modules))\n"
        "print('robotfix.analysis.interpreter' in sys.modules)\n"
    )
    done = run_probe(probe, tmp_path)
    lines = done.stdout.strip().splitlines()
    assert lines[-2:] == ["[]", "True"], done.stdout + done.stderr


def test_own_digest_is_the_full_walks() -> None:
    """The walk that skips `__pycache__` folders digests what the full walk did
    (sorted as paths, each file's stamp), in the same order."""
    package = Path(robotfix.__file__).resolve().parent
    digest = hashlib.blake2b(digest_size=16)
    for path in sorted(package.rglob("*")):
        if path.suffix in _OWN_SUFFIXES and "__pycache__" not in path.parts:
            digest.update(f"{path.relative_to(package)} {fs.stamp(path)}".encode())
    assert own_digest.__wrapped__() == digest.hexdigest()


def test_a_cached_run_makes_each_entry_key_once(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A run names a file many times (its stat, its bytes, its entry): the cache
    makes its key (`abspath`, which asks the cwd of a relative name) once."""
    (demo_package(tmp_path) / "driver.py").write_text(NODE)
    monkeypatch.chdir(tmp_path)
    config = Config(root=tmp_path)
    cold = check_paths([Path("src")], config, jobs=1, use_cache=True)
    asked: list[object] = []
    real = robotfix.cache.entry_key
    monkeypatch.setattr(
        robotfix.cache, "entry_key", lambda p: asked.append(p) or real(p)
    )
    warm = check_paths([Path("src")], config, jobs=1, use_cache=True)
    assert warm.from_cache == len(warm.checked) == len(cold.checked) == 2
    assert asked and len(asked) == len(set(asked))


# what only reading interface files and annotations needs (ros/catalog.py's loading)
READERS = (
    "robotfix.annotations.ast",
    "robotfix.annotations.parser",
    "robotfix.annotations.units",
    "robotfix.ros.msg",
    "robotfix.ros.comments",
)
MSG = """\
#RobotFix# Unit(speed) == "m/s"
float64 speed  # [m/s]
"""


def test_a_warm_cached_run_loads_no_reader_of_interfaces_or_annotations(
    tmp_path: Path,
) -> None:
    """An unchanged tree's run takes every result and the catalog's digests from
    the cache: the catalog reads no file, so its readers are not even imported."""
    package = demo_package(tmp_path)
    (package.parent / "msg").mkdir()
    (package.parent / "msg" / "Speed.msg").write_text(MSG)
    (package / "driver.py").write_text(
        NODE + "\nfrom demo.msg import Speed\nSPEED = Speed().speed\n"
    )
    probe = (
        TRUSTED + "import sys\n"
        "from robotfix.cli import main\n"
        f"main(['check', {str(tmp_path / 'src')!r}, '-j', '1'])\n"
        f"print(sorted(m for m in {READERS!r} if m in sys.modules))\n"
    )
    cold = run_probe(probe, tmp_path)
    assert cold.stdout.strip().splitlines()[-1] != "[]", cold.stdout + cold.stderr
    warm = run_probe(probe, tmp_path)
    *output, loaded = warm.stdout.strip().splitlines()
    assert loaded == "[]", warm.stdout + warm.stderr
    assert output == cold.stdout.strip().splitlines()[:-1]


# modules whose regular expressions are compiled at their first use (`lazyre.py`)
LAZY_PATTERNS = (
    "annotations/units.py",
    "discovery.py",
    "source.py",
    "ros/executables.py",
    "ros/package.py",
    "stubs/load.py",
    "stubs/reader.py",
)


def test_a_check_of_a_plain_file_compiles_none_of_their_patterns(
    tmp_path: Path,
) -> None:
    """A one-file check of `x = 1` (pre-commit, the ament linter, an editor's
    start) reads no unit, C++ build file or suppression comment: the ~25 patterns
    of those modules (compiled at import before, 15 M instructions) stay text."""
    (tmp_path / "a.py").write_text("x = 1\n")
    probe = (
        "import re, sys, traceback\n"
        "real = re._compile\n"
        "made = []\n"
        "def spy(pattern, flags):\n"
        "    frame = next(f for f in reversed(traceback.extract_stack()[:-1])\n"
        "                 if '/re/' not in f.filename and 'lazyre' not in f.filename)\n"
        "    made.append(frame.filename.replace(chr(92), '/'))\n"
        "    return real(pattern, flags)\n"
        "re._compile = spy\n"
        "from robotfix.cli import main\n"
        "main(['check', 'a.py', '--no-cache', '-j', '1'])\n"
        "names = {f.split('/robotfix/')[-1] for f in made}\n"
        f"print(sorted(names & {set(LAZY_PATTERNS)!r}))\n"
    )
    done = run_probe(probe, tmp_path)
    assert done.stdout.strip().splitlines()[-1] == "[]", done.stdout + done.stderr


def test_super_init_parses_no_stub_that_only_defines_an_init() -> None:
    """`super().__init__("talker")` in a node class is a call by method name: the
    stubs' seven `__init__` methods disagree and none checks a positional
    argument, which shipped_names.json says without parsing rclpy/duration.pyi,
    rclpy/time.pyi and rospy.pyi (17 M instructions of each such check)."""
    import ast

    from robotfix.api import check_source
    from robotfix.stubs.load import DATA

    texts = {p.read_text(encoding="utf-8"): p.name for p in DATA.rglob("*.pyi")}
    parsed: list[str] = []
    real = ast.parse

    def parse(source: Any, *args: Any, **kwargs: Any) -> Any:
        if source in texts:
            parsed.append(texts[source])
        return real(source, *args, **kwargs)

    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(ast, "parse", parse)
        check_source(NODE.replace("driver", "talker"), "talker.py")
    assert not {"duration.pyi", "time.pyi", "rospy.pyi"} & set(parsed), parsed
    # what the candidates could check is still theirs to check
    from robotfix.stubs.load import StubSet, unchecked_call

    fresh = StubSet()
    assert unchecked_call(fresh, "__init__", 1, [])
    assert not unchecked_call(fresh, "__init__", 0, ["seconds"])
    assert not unchecked_call(fresh, "wait_for_service", 1, [])
    assert unchecked_call(fresh, "wait_for_service", 0, [])
    assert fresh._modules == {}


KEPT_AS_THEY_ARE = ("robotfix.annotations.ast", "robotfix.analysis.unitmemo")


def test_the_dataclasses_have_docstrings() -> None:
    """`dataclass` gives a class without a docstring one made from
    `inspect.signature` at import (~0.27 M instructions a class: 16 M of a check of
    three repositories for the 59 a check loaded without one); every module's
    classes write their own, but `annotations/ast.py`'s (its text keys the shipped
    stubs' parsed predicates, `stub_predicates.json`) and the editor's memo's (at
    the module size cap; a check never loads it)."""
    import dataclasses
    import importlib
    import pkgutil

    generated = []
    for found in pkgutil.walk_packages(robotfix.__path__, "robotfix."):
        if found.name.endswith("__main__") or found.name in KEPT_AS_THEY_ARE:
            continue
        module = importlib.import_module(found.name)
        generated += [
            f"{found.name}.{cls.__qualname__}"
            for cls in vars(module).values()
            if isinstance(cls, type)
            and cls.__module__ == module.__name__
            and dataclasses.is_dataclass(cls)
            and (cls.__doc__ or "").startswith(f"{cls.__name__}(")
        ]
    assert generated == []


def test_a_lazy_pattern_is_its_compiled_pattern() -> None:
    import re

    from robotfix.lazyre import lazy

    pattern = lazy(r"#\s*robotfix:\s*ignore(?:\[(?P<codes>[^\]]*)\])?", re.I)
    assert "search" not in vars(pattern)  # not compiled before its first use
    found = pattern.search("x = 1  # RobotFix: ignore[RF101]")
    assert found is not None and found["codes"] == "RF101"
    assert isinstance(vars(pattern)["search"].__self__, re.Pattern)  # kept, bound
    assert pattern.flags & re.I and pattern.groupindex == {"codes": 1}
    assert lazy(rb"#\s*include").match(b"# include") is not None


def test_a_check_command_makes_no_young_collection_of_its_imports(
    tmp_path: Path,
) -> None:
    """`cli.run` sets the check's collector thresholds before the command imports
    RobotFix (at Python's 700 those imports made about 30 collections that found
    next to nothing) and never restores Python's (which made one more collection,
    of all a run had allocated since its last, after the check)."""
    (tmp_path / "node.py").write_text(NODE)
    probe = (
        "import gc, sys, atexit\n"
        "from robotfix import cli\n"
        "made = []\n"
        "gc.callbacks.append(lambda phase, info: made.append(info['generation'])"
        " if phase == 'start' else None)\n"
        "atexit.register(lambda: print('collections', made, gc.get_threshold()))\n"
        "sys.argv = ['robotfix', 'check', 'node.py', '--no-cache', '-j', '1']\n"
        "cli.run()\n"
    )
    done = run_probe(probe, tmp_path)
    assert done.returncode == 0, done.stdout + done.stderr
    assert done.stdout.splitlines()[-1] == "collections [] (200000, 50, 1000)"


@pytest.mark.parametrize("command", ["check", "lsp"])
def test_the_editors_server_keeps_pythons_collector(
    tmp_path: Path, command: str
) -> None:
    """A long-lived `robotfix lsp` keeps Python's young collections (short pauses
    between keystrokes); a one-shot command's process ends after its run."""
    probe = (
        "import gc, sys\n"
        "from robotfix import cli\n"
        "print(gc.get_threshold())\n"
        "cli.main = lambda: print(gc.get_threshold()) or 0\n"
        f"sys.argv = ['robotfix', {command!r}]\n"
        "cli.run()\n"
    )
    done = run_probe(probe, tmp_path)
    before, during = done.stdout.splitlines()
    kept = command == "lsp"
    assert during == (before if kept else str(robotfix.GC_THRESHOLDS)), done.stderr


def test_a_check_of_one_process_asks_nothing_of_the_cores(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """`-j 1` (and the default on one core) never reads the affinity and control
    group quotas that cap `-j` (4.7 M instructions of every such process)."""
    from robotfix import cores

    def refuse(*args: object) -> int:
        raise AssertionError("the cores were asked")

    monkeypatch.setattr(cores, "available", refuse)
    (tmp_path / "node.py").write_text(NODE)
    result = check_paths([tmp_path / "node.py"], Config(root=tmp_path), jobs=1)
    assert result.files == 1 and not result.internal_errors
