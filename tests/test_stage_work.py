"""The parameter, launch and discovery stages do each piece of work once (issue 25):
work counted, not timed, so these fail on the code that repeated it."""

from __future__ import annotations

from pathlib import Path

import pytest

from robotfix import paramcheck
from robotfix.analysis.parameters import summarize
from robotfix.ros import paramfile as P
from robotfix.ros import yamlfile as Y
from robotfix.source import SourceFile

NODE = """import rospy

rospy.init_node('tracker')
rate = rospy.get_param('~rate', 10)
gain = rospy.get_param('/tracker/gain', 1.0)
mode = rospy.get_param('mode', 'scan')
"""


def _entries(count: int) -> list[P.Entry]:
    text = "".join(f"key_{i}: {i}\n" for i in range(count)) + "rate: 5\nmode: 1\n"
    root = Y.parse(text)
    assert not isinstance(root, Y.YamlProblem) and root is not None
    loaded = P.classify(root, False)
    assert loaded is not None and loaded.layout == "ros1"
    return loaded.entries


def test_a_flat_file_resolves_each_rospy_parameter_once(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """`Table.ros1` resolved every rospy parameter of every summary again for each
    value of a flat file (461,250 path comparisons and as many resolutions on the
    issue-25 corpus); now once per summary, whatever the number of values."""
    summaries = [
        summarize(SourceFile.from_text(f"pkg/nodes/node_{i}.py", NODE))
        for i in range(3)
    ]
    calls: list[str] = []
    resolve = paramcheck.ros1_name
    monkeypatch.setattr(
        paramcheck,
        "ros1_name",
        lambda name, nodes: calls.append(name) or resolve(name, nodes),
    )
    counts = []
    for count in (10, 100):
        calls.clear()
        table = paramcheck.Table(summaries, {})
        found = [
            [(p.name, len(p.refinements)) for p in table.ros1(entry, None)]
            for entry in _entries(count)
        ]
        assert found[-2:] == [[("~rate", 0)] * 3, [("/mode", 0)] * 3]
        assert all(not f for f in found[:-2])
        counts.append(len(calls))
    assert counts[0] == counts[1]


def test_each_launch_file_looks_its_code_up_in_the_tables_one_map(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """`LaunchRun.check_file` mapped every summary of the table by its real path
    again for each launch file (165 times on the issue-25 corpus); the table
    maps them once, and a launch file's entries find their code there."""
    from robotfix import launchcheck
    from robotfix.ros.launch.model import NodeEntry, Place

    summaries = [
        summarize(SourceFile.from_text(f"pkg/nodes/node_{i}.py", NODE))
        for i in range(3)
    ]
    table = paramcheck.Table(summaries, {})

    class Walked(list):
        def __iter__(self):
            raise AssertionError("the table's summaries walked again")

    table.summaries = Walked(table.summaries)
    given: list[list[str]] = []
    monkeypatch.setattr(
        launchcheck,
        "_ros1_entry",
        lambda entry, code, table: given.append([s.path for s in code]) or [],
    )
    run = launchcheck.LaunchRun([], [])
    entry = NodeEntry(1, Place("a.launch", 3, 2), "pkg", "node_1.py", None, "")
    started = launchcheck._Started(entry, {table.real[summaries[1].path]})
    for name in ("a.launch", "b.launch"):
        assert run.check_file(name, [started], table, {}) == []
    assert given == [["pkg/nodes/node_1.py"]] * 2


def test_each_package_manifest_is_read_once_for_the_launch_files(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """`launchcheck._packages` asked whether each file's package was already found
    by scanning the packages found (96,000 path comparisons on the issue-25
    corpus), and read again the manifest of a package it could not name for each
    of its files; now each package folder is named once."""
    from robotfix import launchcheck

    files = []
    for name, manifest in (
        ("good", "<package><name>good</name></package>"),
        ("bad", "<package><name>no-name</name></package>"),
    ):
        (tmp_path / name / "launch").mkdir(parents=True)
        (tmp_path / name / "package.xml").write_text(manifest)
        for i in range(3):
            for folder in ("launch", "."):
                path = tmp_path / name / folder / f"f{i}.py"
                path.write_text("")
                files.append(path)
    read: list[Path] = []
    name_of = launchcheck.package_name
    monkeypatch.setattr(
        launchcheck,
        "package_name",
        lambda folder: read.append(folder) or name_of(folder),
    )
    assert launchcheck._packages(files) == {"good": tmp_path / "good"}
    assert sorted(read) == [tmp_path / "bad", tmp_path / "good"]


def _counting_realpath(monkeypatch: pytest.MonkeyPatch) -> list[str]:
    import os

    asked: list[str] = []
    realpath = os.path.realpath
    monkeypatch.setattr(
        os.path,
        "realpath",
        lambda p, **k: asked.append(os.fspath(p)) or realpath(p, **k),
    )
    return asked


def test_discovery_resolves_no_walked_folder_again(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The walk knows each folder's real path (its parent's and its name, when it
    is no link), but the `exclude` of the folder's nearest configuration looked
    for that configuration from `os.path.realpath` of the folder again (1,004 of
    the issue-25 corpus's 3,541 real paths); now it is handed over."""
    from robotfix.config import Config, Flags
    from robotfix.discovery import discover

    folder = tmp_path
    for i in range(12):
        folder = folder / f"level{i}"
        (folder / "side").mkdir(parents=True)
        (folder / "side" / "node.py").write_text("x = 1\n")
    config = Config(root=tmp_path, flags=Flags())
    asked = _counting_realpath(monkeypatch)
    found = discover([tmp_path], config)
    assert len(found.python_files) == 12
    assert len(asked) < 12, asked


def test_a_run_asks_the_disk_each_real_path_once(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """The stages after the checks asked `os.path.realpath` of one file many times
    (a C++ file for its node's parameters and for the graph; a Python file for
    the parameter table and for its summary): 3,541 times for 918 paths on the
    issue-25 corpus. Now a run answers each probe once (`fs.answering`)."""
    from collections import Counter

    from robotfix.api import check_paths
    from robotfix.config import Config

    workspace = Path(__file__).parent / "cases" / "cpp_params" / "nav_ws"
    plain = check_paths([workspace], Config(root=workspace)).diagnostics
    asked = _counting_realpath(monkeypatch)
    assert check_paths([workspace], Config(root=workspace)).diagnostics == plain
    again = {p: n for p, n in Counter(asked).items() if n > 1}
    assert not again, again


def test_composable_nodes_sort_the_code_files_once(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Each composable node's entry (its package's C++ files are the code it may
    load) sorted every code file of the run again and looked through them for
    its package's: 562 sorts and scans of some 800 files on the issue-25
    corpus; now one sort, and one scan per package."""
    from types import SimpleNamespace

    from robotfix import graphcheck
    from robotfix.launchcheck import _Started
    from robotfix.ros.graph.model import FileGraph
    from robotfix.ros.launch.model import NodeEntry, Place

    package = tmp_path / "pkg"
    (package / "src").mkdir(parents=True)
    (package / "package.xml").write_text("<package><name>pkg</name></package>")
    code = {}
    for i in range(5):
        (package / "src" / f"c{i}.cpp").write_text("")
        code[str(package / "src" / f"c{i}.cpp")] = FileGraph()

    def entries(count: int) -> SimpleNamespace:
        started = [
            _Started(
                NodeEntry(2, Place("l.py", i, 0), "pkg", None, None, "", plugin="a::B")
            )
            for i in range(count)
        ]
        return SimpleNamespace(
            packages={"pkg": package}, started=started, targets={}, executables={}
        )

    sorts: list[int] = []  # the sorts of every code file (an entry's own: not)
    monkeypatch.setattr(
        graphcheck,
        "sorted",
        lambda items, **k: sorts.append(len(items)) or sorted(items, **k),
        raising=False,
    )
    probed: list[str] = []  # the package's files looked for: once, not per entry
    probe = graphcheck.probe
    monkeypatch.setattr(
        graphcheck,
        "probe",
        lambda kind, path: probed.append(str(path)) or probe(kind, path),
    )
    counts = []
    for count in (2, 20):
        sorts.clear()
        probed.clear()
        found = graphcheck.started_entries(entries(count), code)  # type: ignore[arg-type]
        assert [s.files for s in found] == [sorted(code)] * count
        counts.append(sum(1 for n in sorts if n == len(code)))
        assert probed.count(str(package)) == 1
    assert counts[0] == counts[1]


def test_an_executable_many_entries_start_is_looked_up_once_a_call(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Each entry that starts a C++ executable asked the real path of each of its
    source files again (the two calls of a run on the issue-25 corpus: 1,372
    of its 2,062 entries start one of 149 executables; 15,099 `probe`s, now
    1,847): now once an executable a call, each entry its files all the same."""
    from types import SimpleNamespace

    from robotfix import graphcheck
    from robotfix.launchcheck import _Started
    from robotfix.ros.graph.model import FileGraph
    from robotfix.ros.launch.model import NodeEntry, Place

    package = tmp_path / "pkg"
    (package / "src").mkdir(parents=True)
    (package / "package.xml").write_text("<package><name>pkg</name></package>")
    (package / "CMakeLists.txt").write_text(
        "add_executable(talker src/a.cpp src/b.cpp)\n"
    )
    code = {}
    for name in ("a", "b", "c"):
        (package / "src" / f"{name}.cpp").write_text("")
        code[str(package / "src" / f"{name}.cpp")] = FileGraph()

    def entries(count: int) -> SimpleNamespace:
        started = [
            _Started(NodeEntry(2, Place("l.py", i, 0), "pkg", "talker", None, ""))
            for i in range(count)
        ]
        return SimpleNamespace(
            packages={"pkg": package}, started=started, targets={}, executables={}
        )

    probed: list[str] = []
    probe = graphcheck.probe
    monkeypatch.setattr(
        graphcheck,
        "probe",
        lambda kind, path: probed.append(str(path)) or probe(kind, path),
    )
    sources = [str(package / "src" / f"{name}.cpp") for name in ("a", "b")]
    for count in (2, 20):
        probed.clear()
        found = graphcheck.started_entries(entries(count), code)  # type: ignore[arg-type]
        assert [s.files for s in found] == [sources] * count
        assert [probed.count(s) for s in sources] == [2, 2]  # its code's, its own


def test_a_cpp_call_that_names_no_maker_is_not_read(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """Every call of a C++ file was taken apart (its callee's nodes found and
    their texts decoded) before its name was compared with those that make an
    endpoint: 85% of the issue-25 corpus's 12,487 calls make none. Now a call
    whose callee's bytes hold no such name is passed over at once."""
    from robotfix.ros.graph import cpp

    decoded: list[str] = []
    text = cpp._text
    monkeypatch.setattr(cpp, "_text", lambda node: decoded.append("") or text(node))

    def source(calls: int) -> bytes:
        body = "".join(f"  helper_{i}(x, y.size());\n" for i in range(calls))
        return (
            b'class Talker : public rclcpp::Node {\n  Talker() : Node("talker") {\n'
            + body.encode()
            + b'    pub_ = create_publisher<std_msgs::msg::String>("chatter", 10);\n'
            + b"  }\n};\n"
        )

    counts = []
    for calls in (5, 50):
        decoded.clear()
        graph = cpp.read_cpp(source(calls))
        assert [(e.kind, e.name) for e in graph.endpoints] == [("publisher", "chatter")]
        counts.append(len(decoded))
    assert counts[0] == counts[1]


def test_looking_for_a_configuration_makes_no_path_per_folder(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """`config.find` made a Path of the folder, of all its parents and of two
    candidate files for each folder a walk asked about (a fifth of the stages'
    26,000 Path objects on the issue-25 corpus); the folders are text now, and
    only a configuration found is a Path."""
    from robotfix import config

    deep = tmp_path / "a" / "b" / "c" / "d"
    deep.mkdir(parents=True)
    (tmp_path / "a" / "robotfix.toml").write_text("strict = true\n")
    memo: dict[str, Path | None] = {}
    made: list[object] = []
    real_path = config.Path

    def counted(*parts: object) -> Path:
        made.append(parts)
        return real_path(*parts)  # type: ignore[arg-type]

    monkeypatch.setattr(config, "Path", counted)
    assert config.find(tmp_path / "a", memo) == tmp_path / "a" / "robotfix.toml"
    made.clear()
    for folder in (deep.parent.parent, deep.parent, deep):
        assert config.find(folder, memo) == tmp_path / "a" / "robotfix.toml"
    assert made == []


def test_a_runs_real_paths_are_os_paths_and_resolve_each_folder_once(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """In a run (`fs.answering`) a file's real path is its folder's, asked once,
    and its name, unless it is a symlink: `os.path.realpath` looked at every
    folder above each path again (38,831 lstats on the issue-25 corpus, whose
    repositories are symlinks). Every answer is `os.path.realpath`'s."""
    import os

    from robotfix import fs

    real = tmp_path / "real"
    (real / "pkg" / "src").mkdir(parents=True)
    (tmp_path / "linked").symlink_to(real)
    (real / "pkg" / "src" / "a.cpp").write_text("")
    (real / "pkg" / "src" / "b.cpp").symlink_to(real / "pkg" / "src" / "a.cpp")
    (real / "loop").symlink_to(real / "loop")
    monkeypatch.chdir(tmp_path)
    names = [
        *(str(tmp_path / "linked" / "pkg" / "src" / f"f{i}.cpp") for i in range(20)),
        str(tmp_path / "linked" / "pkg" / "src" / "a.cpp"),
        str(tmp_path / "linked" / "pkg" / "src" / "b.cpp"),
        str(tmp_path / "linked" / "pkg" / "src" / ".." / "src" / "a.cpp"),
        str(tmp_path / "linked" / "loop" / "x" / "y.cpp"),
        str(tmp_path / "linked" / "pkg" / "src") + "/",
        "linked/pkg/src/a.cpp",
        "./linked/pkg/../pkg/src/a.cpp",
        "a.cpp",
        "/",
    ]
    expected = [os.path.realpath(n) for n in names]
    asked = _counting_realpath(monkeypatch)
    with fs.answering():
        assert [fs.probe("realpath", n) for n in names] == expected
    assert len(asked) < 12, asked


def test_discovery_shares_the_runs_answers(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Discovery resolved each package's interface folders and parameter folders
    with `os.path.realpath` of its own (345 on the issue-25 corpus), which the
    later stages asked again; in a run it takes the run's answers
    (`fs.asked`), still noting them in its own trace."""
    from robotfix import fs
    from robotfix.config import Config
    from robotfix.discovery import discover

    for i in range(15):
        package = tmp_path / f"pkg{i}"
        (package / "msg").mkdir(parents=True)
        (package / "config").mkdir()
        (package / "package.xml").write_text(f"<package><name>pkg{i}</name></package>")
        (package / "msg" / "Num.msg").write_text("int64 num\n")
        (package / "config" / "p.yaml").write_text("a: 1\n")
        (package / "node.py").write_text("x = 1\n")
    import os

    from robotfix import discovery

    asked = _counting_realpath(monkeypatch)
    monkeypatch.setitem(discovery._PROBES, "realpath", os.path.realpath)
    with fs.answering():
        found = discover([tmp_path], Config(root=tmp_path))
    assert len(found.python_files) == 15 and len(found.parameter_files) == 15
    assert len(asked) < 15, len(asked)
