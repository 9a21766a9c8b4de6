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
