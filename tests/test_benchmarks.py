"""The benchmarks time what they say: a run that failed, or that checked less than
the tests do, stops the benchmark instead of being reported as a time."""

from __future__ import annotations

import os
import shutil
import sys
from pathlib import Path

import pytest

from robotfix.api import check_paths
from robotfix.config import Config

sys.path.insert(0, str(Path(__file__).parent.parent / "benchmarks"))
import instruction_ratio
import peers
import seed_programs
import seeds


def test_the_seed_workload_with_its_msg_folders_is_the_tests_check() -> None:
    files = seeds.programs(seeds.folders())
    found = check_paths(
        files, Config(msg_paths=tuple(seeds.msg_folders(seeds.folders())))
    )
    seeds.verify(files, found.diagnostics, None)


def test_the_seed_workload_without_its_msg_folders_is_caught() -> None:
    """benchmarks/seed_programs.py and peers.py used to time this: 13 of 21 bugs."""
    files = seeds.programs(seeds.folders())
    found = check_paths(files, Config())
    with pytest.raises(
        SystemExit, match=r"t16_negative_sum/buggy\.py: line 12: expected error RF101"
    ):
        seeds.verify(files, found.diagnostics, None)


def test_a_wrong_exit_status_is_caught() -> None:
    seed = seeds.SEED / "t14_forbidden_value"
    found = check_paths([seed / "buggy.py"], Config())
    seeds.verify([seed / "buggy.py"], found.diagnostics, seeds.FOUND)
    with pytest.raises(SystemExit, match="exit status 0 with errors"):
        seeds.verify([seed / "buggy.py"], found.diagnostics, 0)


def _broken_project(tmp_path: Path) -> Path:
    """A folder whose configuration robotfix refuses (exit status 2)."""
    (tmp_path / "pyproject.toml").write_text("[tool.robotfix]\nmsg-paths = 3\n")
    (tmp_path / "node.py").write_text("x = 1\n")
    return tmp_path / "node.py"


@pytest.mark.skipif(shutil.which("valgrind") is None, reason="needs valgrind")
def test_instruction_ratio_does_not_count_a_failed_run(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    node = _broken_project(tmp_path)
    monkeypatch.chdir(tmp_path)
    with pytest.raises(SystemExit, match="exited 2: not counted"):
        instruction_ratio.main([str(node.parent)])


def test_instruction_ratio_counts_each_layout_in_another_environment() -> None:
    # a count repeats only where every object lies where it lay: each layout must
    # move them (another padding length), and the first is the environment as given
    env = {"PATH": "/bin", instruction_ratio.PAD: "stale"}
    layouts = [instruction_ratio.layout(env, n) for n in range(7)]
    assert layouts[0] == {"PATH": "/bin"}
    assert len({len(e.get(instruction_ratio.PAD, "")) for e in layouts}) == 7
    assert all(e["PATH"] == "/bin" for e in layouts)


def test_instruction_ratio_reports_the_ratio_of_the_medians() -> None:
    lines = instruction_ratio.summary([100, 90, 130], [500, 460, 520])
    assert lines[2].startswith("ratio: 5.00x")  # 500 / 100, not a median of ratios
    assert "median of 3" in lines[0] and "median of 3" in lines[1]
    assert lines[-1] == "ratio in one layout: 4.00x to 5.11x"
    assert len(instruction_ratio.summary([100], [450])) == 3  # one layout: as before


def test_instruction_ratio_python_counts_the_python_files_alone(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """--python: the check and the floor both read a copy holding only the Python
    files (the corpus target 1 names), not the C++ and launch files beside them."""
    repo = tmp_path / "ros2+demos"
    (repo / "pkg" / "src").mkdir(parents=True)
    (repo / "pkg" / "node.py").write_text("x = 1\n")
    (repo / "pkg" / "src" / "talker.cpp").write_text("int main() {}\n")
    (repo / "pkg" / "demo.launch.xml").write_text("<launch/>\n")
    seen: dict[str, list[str]] = {}

    def counted(command: list[str], env: dict[str, str], out: Path) -> int:
        if out.name == "cg.floor":
            seen["floor"] = Path(command[-1]).read_text().split()
        else:
            folders = command[command.index("check") + 1 : command.index("--no-cache")]
            seen["check"] = sorted(
                str(f.relative_to(folders[0])) for f in Path(folders[0]).rglob("*.*")
            )
        return 100

    ran = type("Ran", (), {"returncode": 0})
    monkeypatch.setattr(instruction_ratio.shutil, "which", lambda name: "/bin/true")
    monkeypatch.setattr(instruction_ratio.subprocess, "run", lambda *a, **k: ran)
    monkeypatch.setattr(instruction_ratio, "instructions", counted)
    assert instruction_ratio.main(["--python", str(repo)]) == 0
    assert seen["check"] == ["ros2_demos/pkg/node.py"]
    assert [Path(f).name for f in seen["floor"]] == ["node.py"]
    assert all("ros2_demos" in f for f in seen["floor"])


def test_peers_does_not_time_a_failed_run(tmp_path: Path) -> None:
    node = _broken_project(tmp_path)
    command = [sys.executable, "-m", "robotfix", "check", str(node)]
    with pytest.raises(SystemExit, match="exited 2"):
        peers.timed(command, tmp_path)


def test_seed_programs_does_not_time_a_failed_run(tmp_path: Path) -> None:
    node = _broken_project(tmp_path)
    with pytest.raises(SystemExit, match="robotfix failed"):
        seeds.checked([str(node)], [node], tmp_path, dict(os.environ))


def test_a_timed_seed_run_replays_no_result_cache(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """Each timed run gets an empty result cache of its own, so none is a replay (the
    old benchmark timed the project's `.robotfix_cache/` after its warm-up)."""
    seed = seeds.SEED / "t14_forbidden_value"
    caches: list[str] = []

    def record(args: list[str], *_: object) -> float:
        cache = args[args.index("--cache-dir") + 1]
        assert not Path(cache).exists()
        caches.append(cache)
        return 0.0

    monkeypatch.setattr(seed_programs, "checked", record)
    for _ in range(2):
        seed_programs.fresh([str(seed / "buggy.py")], [seed / "buggy.py"])
    assert len(set(caches)) == 2


def test_the_demand_bound_tells_plain_statements_from_carrying_ones(
    tmp_path: Path,
) -> None:
    """benchmarks/demand_bound.py's oracle watches the evaluator it names: a log
    call carries nothing, a message built and published does, and a function of
    log calls only is spared whole. Renamed stages would stop the script, not make
    it report that nothing is spared."""
    import demand_bound

    (tmp_path / "node.py").write_text(
        "from geometry_msgs.msg import Twist\n"
        "class Node:\n"
        "    def log(self, n):\n"
        "        self.get_logger().info(f'{n} left')\n"
        "    def tick(self):\n"
        "        print('tick')\n"
        "        msg = Twist()\n"
        "        msg.linear.x = 0.5\n"
        "        self.pub.publish(msg)\n"
    )
    with demand_bound.Oracle().installed() as oracle:
        demand_bound.run([tmp_path])
    assert oracle.spent["Expr"] > oracle.spared["Expr"] > 0
    assert oracle.spared["Assign"] == 0 < oracle.spent["Assign"]
    assert oracle.carrying == 3  # msg = Twist(), msg.linear.x = ..., publish
    assert 0 < oracle.functions["plain"] < oracle.functions["all"]


def test_the_demand_rule_keeps_what_feeds_a_statement_that_matters() -> None:
    """benchmarks/demand_rule.py's syntactic slice: a value bound for a message field
    is kept with the field's store (backward), a value read from a parameter is kept
    (forward), a count only a plain statement reads is spared, and `--generous`
    spares more (it drops the parameters and the module's names as sources)."""
    import ast

    import demand_rule

    tree = ast.parse(
        "from geometry_msgs.msg import Twist\n"
        "def tick(self, speed):\n"
        "    n = 0\n"  # read only by the plain line below
        "    n += 1\n"
        "    x = 0.5\n"  # feeds msg.linear.x
        "    y = speed * 2\n"  # reads a parameter
        "    msg = Twist()\n"
        "    msg.linear.x = x\n"
        "    self.pub.publish(msg)\n"
    )
    function = tree.body[1]
    assert isinstance(function, ast.FunctionDef)
    lines = {id(s): s.lineno for s in ast.walk(function) if isinstance(s, ast.stmt)}
    plain = demand_rule.Rule(generous=False).plan(function, {"Twist"})
    assert sorted(lines[k] for k in plain) == [3, 4]
    generous = demand_rule.Rule(generous=True).plan(function, {"Twist"})
    assert sorted(lines[k] for k in generous) == [3, 4, 6]


def test_parsed_twice_names_who_parses_a_file_again(tmp_path: Path) -> None:
    """benchmarks/parsed_twice.py counts a Python launch file: its check parses it,
    then the launch reading does (docs/performance.md, fix/parse8 and fix/graph10).
    A module checked before the file that imports it was parsed twice too, until
    its summary was made from its check's parse (fix/mod10): it is counted once.
    A renamed parser shows as another name, never as nothing parsed again."""
    import parsed_twice

    package = tmp_path / "pkg"
    (package / "launch").mkdir(parents=True)
    (package / "__init__.py").write_text("")
    (package / "a_limits.py").write_text("MAX_SPEED = 0.5\n")
    (package / "b_node.py").write_text(
        "import rclpy\nfrom geometry_msgs.msg import Twist\n"
        "from pkg.a_limits import MAX_SPEED\n\n\n"
        "def command(pub):\n    msg = Twist()\n    msg.linear.x = MAX_SPEED\n"
        "    pub.publish(msg)\n"
    )
    launch = package / "launch" / "talk.launch.py"
    launch.write_text(
        "from launch import LaunchDescription\n"
        "from launch_ros.actions import Node\n\n\n"
        "def generate_launch_description():\n"
        '    return LaunchDescription([Node(package="pkg", executable="talker")])\n'
    )
    with parsed_twice.counting() as (again, sizes):
        check_paths([tmp_path], Config(root=tmp_path), jobs=1)
    assert sizes[str((package / "a_limits.py").resolve())] == len("MAX_SPEED = 0.5\n")
    assert [size for _, size in again.most_common()] == [sizes[str(launch.resolve())]]
    (first, second), _ = again.most_common(1)[0]
    assert "run._check_one" in first and "reader._parse" in second
