"""Parameter files never crash the run and skip nothing without a word
(reliability report 2: N11 huge numbers, N14 nested lists, merge keys, alias keys).

What rcl makes of a scalar is checked against glibc's own strtoll and strtod (rcl
calls them), through ctypes: the oracle is the C library, not a second copy of
`paramfile`'s rules."""

from __future__ import annotations

import ctypes
import platform
import shutil
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from robotfix import paramcheck
from robotfix.ros import paramfile as P
from robotfix.ros import yamlfile as Y
from tests.test_cli import run as cli

PACKAGES = Path(__file__).parent / "cases" / "params" / "packages"
DRIVER = PACKAGES / "ros2_driver" / "ros2_driver" / "driver.py"
TRACKER = PACKAGES / "ros1_tracker" / "nodes" / "head_tracker.py"
glibc = pytest.mark.skipif(
    platform.libc_ver()[0] != "glibc", reason="the oracle is glibc's strtod"
)


def check(folder: Path, text: str, node: Path = DRIVER) -> list[tuple[int, str, str]]:
    """(line, code, message) of one parameter file, in order; a fault of ours is
    raised (no `faults` list is given)."""
    path = folder / "p.yaml"
    path.write_text(text, encoding="utf-8")
    found = paramcheck.check_parameter_files([path], [], [node], [path])
    return sorted((d.span.line, d.code, d.message) for d in found)


def ros2(body: str) -> str:
    return "driver:\n  ros__parameters:\n" + body


# -- N11: numbers of any length ---------------------------------------------------


def test_the_reports_repro_is_a_diagnostic_at_the_line(tmp_path: Path) -> None:
    """`wheel_base: 9...9` (5,000 digits) was a traceback and exit 1 with no
    diagnostic: rcl reads it as a string (strtoll and strtod: ERANGE), which the
    double parameter refuses."""
    package = tmp_path / "d"
    shutil.copytree(PACKAGES / "ros2_driver", package)
    (package / "pyproject.toml").write_text("")
    (package / "config" / "x.yaml").write_text(ros2(f"    wheel_base: {'9' * 5000}\n"))
    result = cli("check", ".", "--no-cache", "--format", "concise", cwd=package)
    assert "Traceback" not in result.stderr and "internal error" not in result.stderr
    assert result.returncode == 1
    assert "config/x.yaml:3:17: error[RF401]: `wheel_base: 999" in result.stdout
    assert "is a string, but the parameter is declared a double" in result.stdout


def test_a_fault_on_one_parameter_file_is_its_internal_error(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Whatever goes wrong of ours on one file: an internal error of that file
    (exit 2, said on stderr), the other files are checked, nothing is cached."""
    from robotfix.api import check_paths
    from robotfix.config import Config

    package = tmp_path / "d"
    shutil.copytree(PACKAGES / "ros2_driver", package)
    (package / "config" / "bad.yaml").write_text(ros2("    wheel_base: 0.25\n"))
    real = paramcheck._check_file

    def fails_on_bad(path: Path, *args: object) -> object:
        if path.name == "bad.yaml":
            raise ValueError("boom")
        return real(path, *args)  # type: ignore[arg-type]

    monkeypatch.setattr(paramcheck, "_check_file", fails_on_bad)
    result = check_paths([package], Config(root=tmp_path), use_cache=True)
    assert [(Path(e.path).name, e.summary) for e in result.internal_errors] == [
        ("bad.yaml", "ValueError: boom")
    ]
    assert any(d.path.endswith("driver.yaml") for d in result.diagnostics)
    again = check_paths([package], Config(root=tmp_path), use_cache=True)
    assert [Path(e.path).name for e in again.internal_errors] == ["bad.yaml"]


_LIBC = ctypes.CDLL(None, use_errno=True)
_LIBC.strtoll.restype = ctypes.c_longlong
_LIBC.strtoll.argtypes = [
    ctypes.c_char_p,
    ctypes.POINTER(ctypes.c_void_p),
    ctypes.c_int,
]
_LIBC.strtod.restype = ctypes.c_double
_LIBC.strtod.argtypes = [ctypes.c_char_p, ctypes.POINTER(ctypes.c_void_p)]


def rcl(text: str) -> tuple[str, object]:
    """rcl_yaml_param_parser's `get_value` for a plain scalar that is no bool word
    nor `.inf`: strtoll, else strtod, whole and without ERANGE, else a string."""
    data = text.encode()
    buffer = ctypes.create_string_buffer(data)
    end = ctypes.c_void_p()
    ctypes.set_errno(0)
    number = _LIBC.strtoll(buffer, ctypes.byref(end), 0)
    whole = end.value == ctypes.addressof(buffer) + len(data)
    if ctypes.get_errno() == 0 and whole:
        return "integer", number
    ctypes.set_errno(0)
    double = _LIBC.strtod(buffer, ctypes.byref(end))
    whole = end.value == ctypes.addressof(buffer) + len(data)
    if ctypes.get_errno() == 0 and whole:
        return "double", double
    return "string", text


DIGITS = st.integers(min_value=1, max_value=6000)
NUMBERS = st.one_of(
    DIGITS.map(lambda n: "9" * n),
    DIGITS.map(lambda n: "1" + "0" * n),
    DIGITS.map(lambda n: "1." + "0" * n),
    DIGITS.map(lambda n: "0." + "0" * n + "1"),
    DIGITS.map(lambda n: "0" + "7" * n),  # octal
    DIGITS.map(lambda n: "0x" + "f" * n),
    DIGITS.map(lambda n: "0x1." + "0" * n + "p-1074"),
    st.integers(min_value=-100_000, max_value=100_000).map(lambda e: f"1e{e}"),
    st.integers(min_value=-100_000, max_value=100_000).map(lambda e: f"0.5E{e:+}"),
    st.integers(min_value=-2000, max_value=2000).map(lambda e: f"0x1p{e}"),
    st.integers(min_value=-400, max_value=400).map(lambda e: f"0e{e}"),
    st.tuples(DIGITS, st.sampled_from(["1.5e", "1e-", "0x1p+", "0e"])).map(
        lambda t: t[1] + "0" * t[0] + "5"  # an exponent's leading zeros
    ),
    st.sampled_from(
        [
            "2.2250738585072011e-308",  # just below the smallest normal double
            "2.2250738585072014e-308",
            "4.9406564584124654e-324",
            "2.4703282292062327e-324",  # half the smallest subnormal
            "1.7976931348623157e308",
            "1.7976931348623159e308",  # rounds to inf
            "9223372036854775807",
            "9223372036854775808",
            "0x8000000000000000",
            "01000000000000000000000",
            "0x.8p-1073",
            "1" + "0" * 4300,
            ".5e-323",
        ]
    ),
)
SIGNED = st.tuples(st.sampled_from(["", "+", "-"]), NUMBERS).map("".join)


@glibc
@settings(max_examples=300, deadline=None)
@given(SIGNED)
def test_numbers_are_typed_as_glibc_reads_them(text: str) -> None:
    typed = P.ros2_scalar(Y.Scalar(text, True, None, 1, 0))
    assert typed is not None
    assert (typed.type, typed.value) == rcl(text)


SETTINGS = settings(
    max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow]
)
# the driver's parameters: a double in [0, 1.5], a string, an integer, a double
PARAMETERS = st.sampled_from(["max_speed", "frame_id", "rate_hz", "wheel_base"])
DECLARED = {
    "max_speed": "double",
    "frame_id": "string",
    "rate_hz": "integer",
    "wheel_base": "double",
}


@glibc
@SETTINGS
@given(PARAMETERS, SIGNED, st.booleans())
def test_a_huge_number_in_a_ros2_file_is_a_diagnostic_at_its_line(
    tmp_path_factory: pytest.TempPathFactory, name: str, text: str, listed: bool
) -> None:
    """No crash; a value rcl reads as another type than declared (a string for
    a double, a double for an integer, any array) is RF401 at its line, the only
    line anything is reported at."""
    folder = tmp_path_factory.mktemp("n11")
    value = f"[{text}, {text}]" if listed else text
    found = check(folder, ros2(f"    {name}: {value}\n"))
    assert {line for line, _, _ in found} <= {3}
    kind, number = rcl(text)
    if listed or kind != DECLARED[name]:
        assert [code for _, code, _ in found] == ["RF401"]
    else:  # the type rcl reads is the declared one: the driver's ranges decide
        broken = breaks_a_range(name, number)
        assert [code for _, code, _ in found] == (["RF101"] if broken else [])


def breaks_a_range(name: str, number: object) -> bool:
    """Whether the driver's declarations refuse a value of the declared type:
    `max_speed` is refined `0 < _ <= 1.5`, `rate_hz` has the range [1, 100]."""
    if name == "max_speed":
        return not 0 < float(number) <= 1.5  # type: ignore[arg-type]
    if name == "rate_hz":
        return not 1 <= int(number) <= 100  # type: ignore[call-overload]
    return False


@SETTINGS
@given(st.sampled_from(["rate", "max_pan", "speed", "lost_timeout"]), SIGNED)
def test_a_huge_number_in_a_ros1_file_never_crashes(
    tmp_path_factory: pytest.TempPathFactory, name: str, text: str
) -> None:
    """rosparam (PyYAML) reads `1e5` as a string and an integer of over 4,300
    digits not at all: that one is an RF004 warning, said at its line."""
    folder = tmp_path_factory.mktemp("n11")
    found = check(folder, f"{name}: {text}\n", TRACKER)
    assert {line for line, _, _ in found} <= {1}
    digits = text.lstrip("+-")  # decimal: octal (`0` first) has no such limit
    if digits.isdigit() and not digits.startswith("0") and len(digits) > 4300:
        assert [code for _, code, _ in found] == ["RF004"]
        assert "PyYAML cannot read the integer" in found[0][2]


def test_a_long_number_is_compared_as_the_double_ros_reads(tmp_path: Path) -> None:
    """Past the annotation grammar's bounds (100 digits, exponent 400) a value is
    the double ROS reads, and the message says so; `0.99...9` is 1.0 to ROS."""
    below = "0." + "9" * 100_000
    assert check(tmp_path, ros2(f"    max_speed: {below}\n")) == []
    assert check(tmp_path, ros2(f"    brake_ratio: {below}\n"))[0][1] == "RF101"
    far = check(tmp_path, ros2(f"    brake_ratio: 1.{'0' * 200}1\n"))
    assert far[0][1] == "RF101"


def test_a_long_run_of_digits_is_read_in_linear_time(tmp_path: Path) -> None:
    """`9...9x` (100,000 digits) is a string: the number patterns fail it in one
    pass (the old `[0-9]+\\.?[0-9]*` backtracked for minutes)."""
    found = check(tmp_path, ros2(f"    max_speed: {'9' * 100_000}x\n"))
    assert [(line, code) for line, code, _ in found] == [(3, "RF401")]


# -- N14: nested lists, merge keys, alias keys --------------------------------------


def test_a_list_of_lists_on_a_double_parameter_is_rf401(tmp_path: Path) -> None:
    """rcl reads `[[1.0]]` as the double array `[1.0]` and refuses other nested
    lists; either way a double parameter does not get a double."""
    found = check(
        tmp_path, ros2("    max_speed: [[1.0]]\n    timeout: [[1.0], [2.0]]\n")
    )
    assert [(line, code) for line, code, _ in found] == [(3, "RF401"), (4, "RF401")]
    assert "is a double array" in found[0][2]
    assert "is a nested list" in found[1][2]
    gains = check(tmp_path, ros2("    gains: [[0.5, 0.05, 0.0]]\n"))
    assert gains == []  # rcl's one inner list is the double array declared


def test_an_alias_bomb_that_is_a_nested_list_is_rf401(tmp_path: Path) -> None:
    bomb = "z0: &z0 [1.0, 1.0]\n" + "".join(
        f"z{i}: &z{i} [*z{i - 1}, *z{i - 1}]\n" for i in range(1, 30)
    )
    found = check(tmp_path, bomb + ros2("    max_speed: *z29\n"))
    # at the first alias, and where the list the alias names is written
    assert [(line, code) for line, code, _ in found] == [(2, "RF004"), (30, "RF401")]
    assert "rcl refuses aliases" in found[0][2]


def test_merge_keys_are_applied_and_rcl_not_applying_them_is_said(
    tmp_path: Path,
) -> None:
    """A merge brings `max_speed: 9.0` in: RF101 where the value is written; the
    mapping's own `timeout` wins over the merged one; rcl refuses the alias."""
    text = "base: &base\n  max_speed: 9.0\n  timeout: 9.0\n" + ros2(
        "    <<: *base\n    timeout: 1.0\n"
    )
    found = check(tmp_path, text)
    assert [(line, code) for line, code, _ in found] == [(2, "RF101"), (6, "RF004")]
    inline = check(tmp_path, ros2("    <<: {max_speed: 9.0}\n"))
    assert [(line, code) for line, code, _ in inline] == [(3, "RF004"), (3, "RF101")]
    assert "rcl does not apply the merge key" in inline[0][2]


def test_a_merge_of_a_scalar_is_said_not_checked(tmp_path: Path) -> None:
    found = check(tmp_path, ros2("    <<: 5\n    max_speed: 9.0\n"))
    assert [(line, code) for line, code, _ in found] == [
        (3, "RF004"),
        (3, "RF004"),
        (4, "RF101"),
    ]
    assert "merge not checked" in found[0][2]


def test_merge_bombs_and_self_merges_stay_cheap(tmp_path: Path) -> None:
    bomb = "m0: &m0 {max_speed: 9.0}\n" + "".join(
        f"m{i}: &m{i} {{<<: [*m{i - 1}, *m{i - 1}]}}\n" for i in range(1, 40)
    )
    found = check(tmp_path, bomb + ros2("    <<: *m39\n"))
    assert [code for _, code, _ in found] == ["RF101", "RF004"]
    looped = check(tmp_path, ros2("    limits: &l {<<: *l, max_turn: 9.0}\n"))
    assert ("RF004" in {c for _, c, _ in looped}) and any(
        "merges itself" in m for _, _, m in looped
    )


def test_rosparam_applies_merge_keys(tmp_path: Path) -> None:
    """ROS 1: PyYAML merges, so does rosparam; merged values are checked (they
    were skipped), and nothing is said about rcl."""
    found = check(tmp_path, "base: &b {rate: 100}\n<<: *b\n", TRACKER)
    assert [(line, code) for line, code, _ in found] == [(1, "RF101")]


def test_an_alias_key_is_checked_as_its_target(tmp_path: Path) -> None:
    found = check(tmp_path, "k: &k wheel_base\n" + ros2("    *k : 1\n"))
    assert [(line, code) for line, code, _ in found] == [(4, "RF004"), (4, "RF401")]
    assert "`wheel_base: 1`" in found[1][2]


def test_an_undefined_alias_is_not_valid_yaml(tmp_path: Path) -> None:
    found = check(tmp_path, ros2("    *k : 1\n"))
    assert [(line, code) for line, code, _ in found] == [(3, "RF003")]
    assert "undefined alias" in found[0][2]
