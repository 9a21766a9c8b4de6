"""Parameters are checked values (issue 10 item 3): parameter files of realistic
packages checked against the nodes' declarations (inline `# error:` comments in the
YAML files, strict), the rcl and rosparam typing of YAML scalars, rclpy's range
rules, and hostile YAML (aliases, depth, size) that must never hang or crash.
The Python side (defaults, reads) is in tests/cases/params/."""

from __future__ import annotations

import math
import shutil
import sys
import time
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from robotfix import cli, paramcheck, rules
from robotfix.api import check_paths
from robotfix.config import Config
from robotfix.diagnostics import Diagnostic
from robotfix.ros import paramfile as P
from robotfix.ros import yamlfile as Y
from robotfix.testing.expectations import (
    Expectation,
    compare,
    compare_files,
    read_line_expectations,
)

PACKAGES = Path(__file__).parent / "cases" / "params" / "packages"


def yaml_expectations(path: Path) -> list[Expectation]:
    """`key: value  # error: RF101 "text"` at the end of a YAML line."""
    return read_line_expectations(path.read_text(encoding="utf-8"))


def run(paths: list[Path], **kwargs: object) -> list[Diagnostic]:
    config = Config(root=paths[0].parent)
    return check_paths(paths, config, **kwargs).diagnostics  # type: ignore[arg-type]


def yaml_files(package: Path) -> list[Path]:
    return sorted([*package.rglob("*.yaml"), *package.rglob("*.yml")])


@pytest.mark.parametrize(
    "package", sorted(p for p in PACKAGES.iterdir() if p.is_dir()), ids=lambda p: p.name
)
def test_parameter_files_of_a_package(package: Path) -> None:
    """Every diagnostic of the run is compared: in the YAML files and in the nodes
    (but the graph's, RF603-RF607: tests/test_graph.py; a package's one node has
    topics nobody else in it publishes or subscribes)."""
    files = [*yaml_files(package), *sorted(package.rglob("*.py"))]
    found = [d for d in run([package]) if d.code not in rules.GRAPH_RULES]
    problems = compare_files(files, found)
    assert not problems, "\n".join(problems)


def test_a_named_parameter_file_is_checked_against_its_package(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """`robotfix check config/driver.yaml`: the package's nodes are read (not
    checked) to know the declarations; the same findings as the whole package."""
    package = PACKAGES / "ros2_driver"
    monkeypatch.chdir(package)
    named = Path("config") / "driver.yaml"
    found = run([named])
    assert not compare(yaml_expectations(package / named), found)
    assert {d.path for d in found} == {str(named)}


def test_cli_reports_yaml_lines_and_fails_the_run(
    capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(PACKAGES / "ros2_driver")
    status = cli.main(
        ["check", "--no-cache", "--format", "concise", "config/driver.yaml"]
    )
    out = capsys.readouterr().out
    assert status == 1
    assert (
        "config/driver.yaml:4:16: error[RF101]: `max_speed: 2.0` (node `driver`)" in out
    )
    near = cli.main(["check", "--no-cache", "config/near_misses.yaml"])
    assert near == 0


def test_results_are_the_same_with_the_cache_and_workers(tmp_path: Path) -> None:
    """Parameter files are checked on every run (they depend on every node), so a
    cached or parallel run reports exactly what a plain one does."""
    package = PACKAGES / "ros1_tracker"
    plain = run([package])
    first = check_paths([package], Config(root=tmp_path), use_cache=True).diagnostics
    second = check_paths([package], Config(root=tmp_path), use_cache=True)
    assert second.from_cache > 0
    assert plain == first == second.diagnostics
    assert check_paths([package], Config(root=tmp_path), jobs=2).diagnostics == plain


def test_an_imported_alias_checks_parameter_files_and_its_change_counts(
    tmp_path: Path,
) -> None:
    """driver.py's `turn: TurnRate` comes from limits.py: the parameter file's
    value is checked against it, with the cache and workers as without, and a
    cached run sees a change to the limit (limits.py mentions no parameter)."""
    package = tmp_path / "ros2_driver"
    shutil.copytree(PACKAGES / "ros2_driver", package)
    turn = "`abs(turn_rate) <= MAX_TURN_RATE`"

    def turns(**options: Any) -> list[str]:
        result = check_paths([package], Config(root=tmp_path), **options)
        return [d.message for d in result.diagnostics if turn in d.message]

    assert len(turns()) == 1
    assert turns(use_cache=True) == turns(use_cache=True) == turns(jobs=2) == turns()
    limits = package / "ros2_driver" / "limits.py"
    limits.write_text(limits.read_text().replace("= 2.0", "= 3.0"))
    assert turns(use_cache=True) == []
    assert turns(use_cache=True) == []


# -- the two packages' nodes are unknown to each other ---------------------------


def write(path: Path, text: str) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text, encoding="utf-8")
    return path


NODE = """
from rclpy.node import Node

class N(Node):
    def __init__(self):
        super().__init__("{name}")
        self.declare_parameter("rate", {default})
"""


def package(root: Path, name: str, node: str, default: str) -> Path:
    folder = root / name
    write(folder / "package.xml", f"<package><name>{name}</name></package>")
    write(folder / name / "node.py", NODE.format(name=node, default=default))
    return folder


def test_an_ambiguous_key_is_reported_only_when_wrong_for_every_node(
    tmp_path: Path,
) -> None:
    """Two nodes named `talker` in two packages: `rate: 5` is an integer for one
    (fine) and not a double for the other: which node gets the file is decided at
    launch, so it is not an error. A `/**` key only concerns the file's package."""
    a = package(tmp_path, "pkg_a", "talker", "10")
    package(tmp_path, "pkg_b", "talker", "10.0")
    params = write(
        a / "config" / "p.yaml",
        "talker:\n  ros__parameters:\n    rate: 5\n"
        "/**:\n  ros__parameters:\n    rate: 5.0\n",
    )
    found = [d for d in run([tmp_path]) if d.path == str(params)]
    assert [(d.span.line, d.code) for d in found] == [(6, "RF401")]


def test_a_node_that_declares_from_overrides_is_silent(tmp_path: Path) -> None:
    folder = tmp_path / "auto"
    write(folder / "package.xml", "<package><name>auto</name></package>")
    write(
        folder / "auto" / "node.py",
        "from rclpy.node import Node\n"
        "class A(Node):\n"
        "    def __init__(self):\n"
        "        super().__init__('auto', "
        "automatically_declare_parameters_from_overrides=True)\n"
        "        self.declare_parameter('rate', 1.0)\n",
    )
    write(folder / "config" / "a.yaml", "auto:\n  ros__parameters:\n    rate: 1\n")
    assert run([folder]) == []


# -- hostile and broken files ---------------------------------------------------

LAUGHS = "a: &a [1, 1, 1, 1, 1, 1, 1, 1, 1]\n" + "".join(
    f"{c}: &{c} [{', '.join([f'*{p}'] * 9)}]\n"
    for p, c in zip("abcdefgh", "bcdefghi", strict=True)
)


def test_billion_laughs_is_neither_expanded_nor_fatal(tmp_path: Path) -> None:
    """9**9 leaves behind aliases: read as a graph, walked within a budget."""
    started = time.process_time()
    parsed = Y.parse(LAUGHS)
    assert isinstance(parsed, Y.Mapping)
    found = P.classify(parsed)
    assert found is not None and found.layout == "ros1"
    cyclic = Y.parse("a: &x [*x, *x]\nb: &y {k: *y}\n")
    assert P.classify(cyclic) is not None
    path = write(tmp_path / "laughs.yaml", LAUGHS)
    assert paramcheck.check_parameter_files([path], [], [], [path]) == []
    assert time.process_time() - started < 30  # a generous bound: it takes ms


def test_too_deep_too_large_or_broken_files_are_rf003_when_named(
    tmp_path: Path,
) -> None:
    deep = write(tmp_path / "deep.yaml", "[" * 500 + "]" * 500 + "\n")
    broken = write(tmp_path / "broken.yaml", "node:\n  ros__parameters: [\n")
    large = write(tmp_path / "large.yaml", "x: 1\n" * (Y.MAX_YAML_BYTES // 5 + 1))
    named = [deep, broken, large]
    found = paramcheck.check_parameter_files(named, [], [], named)
    assert [(Path(d.path).name, d.code, d.span.line) for d in found] == [
        ("deep.yaml", "RF003", 1),
        ("broken.yaml", "RF003", 3),
        ("large.yaml", "RF003", 1),
    ]
    assert "larger than" in found[2].message
    found_in_config = paramcheck.check_parameter_files(named, [], [], [])
    assert [(d.code, d.severity.value) for d in found_in_config] == [
        ("RF004", "warning")
    ] * 3


# -- typing of YAML scalars -------------------------------------------------------


def scalar(text: str, plain: bool = True, tag: str | None = None) -> Y.Scalar:
    return Y.Scalar(text, plain, tag, 1, 0)


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("true", ("bool", True)),
        ("Off", ("bool", False)),
        ("y", ("bool", True)),
        ("42", ("integer", 42)),
        ("-0x1F", ("integer", -31)),
        ("017", ("integer", 15)),  # strtoll with base 0: octal
        ("08", ("double", 8.0)),  # not octal, so strtod reads it
        ("9223372036854775808", ("double", 9.223372036854775808e18)),
        ("1e3", ("double", 1000.0)),
        (".5", ("double", 0.5)),
        ("-.inf", ("double", -math.inf)),
        ("1_000", ("string", "1_000")),
        ("0.5m", ("string", "0.5m")),
        ("1e999", ("string", "1e999")),  # ERANGE: rcl keeps the text
    ],
)
def test_ros2_scalars_are_typed_as_rcl_types_them(
    text: str, expected: tuple[str, object]
) -> None:
    typed = P.ros2_scalar(scalar(text))
    assert typed is not None
    assert (typed.type, typed.value) == expected


def test_quoted_and_str_tagged_scalars_are_strings() -> None:
    assert P.ros2_scalar(scalar("5", plain=False)) == P.Typed("string", "5", "5")
    assert P.ros2_scalar(scalar("true", tag=Y.STR_TAG)) == P.Typed(
        "string", "true", "true"
    )
    assert P.ros2_scalar(scalar("")) is None


@settings(max_examples=60, deadline=None)
@given(st.integers(min_value=-(2**63), max_value=2**63 - 1))
def test_every_int64_is_an_integer(number: int) -> None:
    assert P.ros2_scalar(scalar(str(number))) == P.Typed("integer", number, str(number))


@settings(max_examples=60, deadline=None)
@given(
    st.floats(allow_nan=False, allow_infinity=False).filter(
        lambda x: x == 0 or abs(x) >= sys.float_info.min
    )
)
def test_every_float_repr_is_a_double(number: float) -> None:
    """(A subnormal's is a string: glibc's strtod sets ERANGE for it, see
    tests/test_reliability_params.py.)"""
    text = repr(number)
    typed = P.ros2_scalar(scalar(text))
    assert typed is not None and typed.type == "double" and typed.value == number


def test_ros1_scalars_follow_yaml_1_1() -> None:
    def typed(text: str) -> tuple[str, object] | None:
        found = P.ros1_value(scalar(text), [100])
        return None if found is None else (found.type, found.value)

    assert typed("1_000") == ("integer", 1000)
    assert typed("yes") == ("bool", True)
    assert typed("1e3") == ("string", "1e3")  # YAML 1.1 needs a dot and a sign
    assert typed("1.0e+3") == ("double", 1000.0)
    assert typed("rad(pi/2)") is None  # rosparam evaluates it


# -- rclpy's range rules ------------------------------------------------------------


def rng(low: float, high: float, step: float = 0, integer: bool = False) -> P.Range:
    return P.Range(integer, low, high, step, 0, 0, 1)  # type: ignore[arg-type]


def test_ranges_accept_what_rclpy_accepts() -> None:
    assert rng(0.0, 1.0).accepts(1.0000005)  # within 1e-6 relative of a bound
    assert not rng(0.0, 1.0).accepts(1.00001)
    assert rng(1.0, 0.0).accepts(0.5)  # bounds in either order
    assert rng(0.0, 1.0, 0.25).accepts(0.75)
    assert not rng(0.0, 1.0, 0.25).accepts(0.8)
    assert not rng(0.0, 1.0).accepts(math.nan)
    assert rng(0, 10, 3, integer=True).accepts(10)  # a bound is always fine
    assert not rng(0, 10, 3, integer=True).accepts(5)
    assert rng(0, 10, 3, integer=True).accepts(6)


def test_generate_parameter_library_validators() -> None:
    def broken(name: str, args: str, value: str) -> str | None:
        node = Y.parse(f"v: {value}\na: {args}\n")
        assert isinstance(node, Y.Mapping)
        typed = P.ros2_value(node.get("v"), [100])
        assert typed is not None
        return P.gpl_violation(name, node.get("a"), typed, [100])

    assert broken("bounds", "[0, 1]", "1.5") == "bounds<> [0, 1]"
    assert broken("bounds", "[0, 1]", "1") is None
    assert broken("gt", "[0]", "0") == "gt<> [0]"
    assert broken("lt_eq", "2.0", "2.0") is None  # one argument without brackets
    assert broken("one_of", '[["a", "b"]]', "c") == 'one_of<> ["a", "b"]'
    assert broken("size_gt", "[1]", "[a]") == "size_gt<> [1]"
    assert broken("element_bounds", "[0, 1]", "[0.5, 2.0]") == "element_bounds<> [0, 1]"
    assert broken("subset_of", "[[1, 2]]", "[1, 3]") == "subset_of<> [1, 2]"
    assert broken("custom::check", "null", "3") is None


# -- nothing crashes --------------------------------------------------------------

DRIVER = PACKAGES / "ros2_driver" / "ros2_driver" / "driver.py"
SCALARS = st.one_of(
    st.none(),
    st.booleans(),
    st.integers(min_value=-(2**70), max_value=2**70),
    st.floats(),
    st.text(max_size=8),
)
TREES = st.recursive(
    SCALARS,
    lambda inner: st.one_of(
        st.lists(inner, max_size=4),
        st.dictionaries(
            st.sampled_from(
                ["driver", "/**", "ros__parameters", "max_speed", "limits", "type"]
            )
            | st.text(max_size=5),
            inner,
            max_size=4,
        ),
    ),
    max_leaves=25,
)


@settings(max_examples=40, deadline=None)
@given(TREES)
def test_any_yaml_tree_is_checked_without_crashing(tree: object) -> None:
    import tempfile

    import yaml

    text = yaml.safe_dump(tree)
    with tempfile.TemporaryDirectory() as folder:
        path = write(Path(folder) / "p.yaml", text)
        for found in paramcheck.check_parameter_files([path], [], [DRIVER], [path]):
            assert found.code in ("RF101", "RF401", "RF003", "RF004", "RF602")
            if found.code == "RF602":  # a section of another node than `driver`
                assert "section `driver`" not in found.message


@pytest.mark.parametrize("body", ["{}", "{max_speed: 0.5}"])
def test_a_section_of_a_known_node_is_no_rf602_even_without_values(
    tmp_path: Path, body: str
) -> None:
    """`driver: {ros__parameters: {}}` names the driver's node: the code's node names
    are read even when the file sets no value (they were not, and every section
    of such a file was said to name no node)."""
    path = write(tmp_path / "p.yaml", f"driver:\n  ros__parameters: {body}\n")
    found = paramcheck.check_parameter_files([path], [], [DRIVER], [path])
    assert [d.code for d in found] == []


@settings(max_examples=60, deadline=None)
@given(st.text(max_size=60))
def test_any_text_parses_or_is_a_yaml_problem(text: str) -> None:
    found = Y.parse(text)
    if not isinstance(found, Y.YamlProblem):
        P.classify(found)


ARGUMENTS = st.lists(
    st.sampled_from(
        [
            "'a'",
            "1",
            "1.5",
            "-2",
            "None",
            "x",
            "[1, 2.0]",
            "('b', 1.0, d)",
            "[('c', 2)]",
            "d",
            "ParameterDescriptor(integer_range=[IntegerRange(to_value=3)])",
            "ParameterDescriptor(floating_point_range=[FloatingPointRange("
            "from_value=1.0, to_value=-1.0, step=0.3)])",
            "name='b'",
            "value=2.0",
            "descriptor=d",
            "*a",
            "**k",
            "Parameter.Type.DOUBLE",
            "float('nan')",
            "1e308 * 10",
        ]
    ),
    max_size=4,
)
CALL_SITES = (
    "self.declare_parameter({})",
    "v: Annotated[float, '0 < _ <= 1'] = self.declare_parameter({}).value",
    "w: Annotated[int, '_ > 0'] = self.get_parameter({}).value",
    "u: Annotated[str, \"_ == 'a'\"] = rospy.get_param({})",
    "self.declare_parameters({})",
    "t = self.get_parameter({}).get_parameter_value().double_value",
)


@settings(max_examples=60, deadline=None)
@given(ARGUMENTS, ARGUMENTS, st.sampled_from(CALL_SITES), st.sampled_from(CALL_SITES))
def test_any_parameter_call_is_analysed_without_crashing(
    first: list[str], second: list[str], site_a: str, site_b: str
) -> None:
    from robotfix.api import check_source

    source = (
        "from typing import Annotated\nimport rospy\nfrom rclpy.node import Node\n"
        "d = ParameterDescriptor(floating_point_range=[FloatingPointRange("
        "from_value=0.0, to_value=1.0)])\n"
        "class N(Node):\n    def __init__(self, x, *a, **k):\n"
        "        super().__init__('n')\n"
        f"        {site_a.format(', '.join(first))}\n"
        f"        {site_b.format(', '.join(second))}\n"
    )
    for found in check_source(source, "fuzz.py"):
        assert found.code in ("RF101", "RF102", "RF301", "RF401", "RF001"), found


@pytest.mark.parametrize("name", ["ros1_tracker", "ros2_driver", "gpl_turtle"])
def test_workers_hand_paramcheck_their_summaries(
    name: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    """With `-j 2` each worker sends back the parameter summaries it made from the
    trees it parsed, so the main process parses no Python file again for the
    parameter files (it did, 0.6 s of a 4.7 s run on a 242k-line corpus), and the
    result is the one `-j 1` gives."""
    from robotfix import run as run_module

    package = PACKAGES / name
    plain = run([package])
    parsed: list[str] = []
    summarize = paramcheck.summarize
    monkeypatch.setattr(
        paramcheck,
        "summarize",
        lambda source: parsed.append(source.path) or summarize(source),
    )
    monkeypatch.setattr(run_module, "MIN_PARALLEL", 1)
    assert check_paths([package], Config(), jobs=2).diagnostics == plain
    assert parsed == []


def test_a_worker_summary_survives_the_trip() -> None:
    """What a worker sends: the same summary without the analysis's node ids, and
    `UNKNOWN` (a default that is no constant) still the one `is` compares with."""
    import pickle

    from robotfix.analysis.parameters import summarize as summarize_parameters
    from robotfix.analysis.paramsummary import UNKNOWN
    from robotfix.run import _portable
    from robotfix.source import SourceFile

    text = (
        "import rclpy\nfrom rclpy.node import Node\n\n\n"
        "class Driver(Node):\n"
        "    def __init__(self, start):\n"
        "        super().__init__('driver')\n"
        "        self.declare_parameter('max_speed', 0.5)\n"
        "        self.declare_parameter('start', start)\n"
    )
    summary = summarize_parameters(SourceFile.from_text("driver.py", text))
    assert summary.by_node and any(d.default is UNKNOWN for d in summary.decls)
    portable = _portable(summary)
    assert portable is not None and portable.by_node == {}
    back = pickle.loads(pickle.dumps(portable))
    assert back.decls == summary.decls
    assert [d.default for d in back.decls][1] is UNKNOWN


def test_notes_stay_notes_from_the_cache(tmp_path: Path) -> None:
    """Issue 24: an RF102 note on a parameter file's value came back from the
    result cache as a warning (the cache dropped a diagnostic's own severity)."""
    package = shutil.copytree(PACKAGES / "ros2_limits", tmp_path / "ros2_limits")
    config = Config(root=tmp_path, cache_dir=tmp_path / "cache")
    runs = [check_paths([package], config, use_cache=True) for _ in range(2)]
    assert runs[1].from_cache == runs[0].from_cache + 2
    levels = [[(d.code, d.severity.value) for d in r.diagnostics] for r in runs]
    assert ("RF102", "note") in levels[0]
    assert levels[1] == levels[0]


DTPARAM_STUB = """\
class DTParam:
    @ros_parameter(name="name", default="default", low="min_value", high="max_value")
    def __init__(
        self,
        name: str,
        default: object = ...,
        help: str = ...,
        param_type: object = ...,
        min_value: float = ...,
        max_value: float = ...,
    ) -> None: ...
"""
DTPARAM_NODE = """\
#!/usr/bin/env python3
import rospy
from duckietown.dtros import DTParam


class StopLineFilterNode:
    def __init__(self):
        rospy.init_node("stop_line_filter_node")
        self.stop_distance = DTParam("~stop_distance", min_value=0.0, max_value=0.5)
        self.min_segs = DTParam("~min_segs", 2, "how many", None, 1)
"""


def _dtparam_package(root: Path, stub: str = DTPARAM_STUB) -> Path:
    package = root / "stop_line_filter"
    (package / "src").mkdir(parents=True)
    (package / "package.xml").write_text(
        '<package format="2"><name>stop_line_filter</name></package>'
    )
    (package / "src" / "stop_line_filter_node").write_text(DTPARAM_NODE)
    config = package / "config" / "stop_line_filter_node" / "default.yaml"
    config.parent.mkdir(parents=True)
    config.write_text("stop_distance: 22\nmin_segs: 0\nmax_y: 0.2\n")
    stubs = package / "stubs" / "duckietown" / "dtros"
    stubs.mkdir(parents=True)
    (stubs / "__init__.pyi").write_text(stub)
    (package / "robotfix.toml").write_text('stub-paths = ["stubs"]\n')
    return package


def test_a_parameter_api_described_in_a_stub_is_checked_in_its_files(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    """Issue 24: duckietown's `DTParam("~name", min_value=..., max_value=...)`,
    described by `@ros_parameter` in the package's stubs, gets its YAML checked, from
    the package and from the workspace root (the package's own stub-paths)."""
    package = _dtparam_package(tmp_path)
    for cwd in (package, tmp_path):
        monkeypatch.chdir(cwd)
        assert cli.main(["check", ".", "--no-cache", "--format", "concise"]) == 1
        out = capsys.readouterr().out
        assert "`stop_distance: 22` violates `stop_distance <= 0.5`" in out
        assert "`min_segs: 0` violates `min_segs >= 1`" in out
        assert "Found 2 errors" in out
    (package / "robotfix.toml").write_text("")  # without the stub: nothing to say
    assert cli.main(["check", ".", "--no-cache", "--format", "concise"]) == 0


def test_a_malformed_ros_parameter_is_a_stub_problem(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    bad = DTPARAM_STUB.replace('low="min_value"', 'low="minimum"')
    package = _dtparam_package(tmp_path, bad)
    monkeypatch.chdir(package)
    cli.main(["check", ".", "--no-cache", "--format", "concise"])
    out = capsys.readouterr().out
    assert "RF512" in out and "`ros_parameter` takes name, default" in out
    assert "RF101" not in out
