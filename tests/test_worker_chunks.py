"""How a run splits its files among worker processes (`run._chunks`): a ROS
package's files stay in one task, so the summaries of the modules they import are
built once, not in each worker; every file is in exactly one task."""

from __future__ import annotations

from pathlib import Path

from robotfix.run import CHUNKS_PER_JOB, _chunks


def _tree(tmp_path: Path, packages: dict[str, int], size: int = 100) -> list[Path]:
    files = []
    for name, count in packages.items():
        folder = tmp_path / name
        (folder / name).mkdir(parents=True)
        (folder / "package.xml").write_text(f"<package><name>{name}</name></package>")
        for i in range(count):
            path = folder / name / f"m{i}.py"
            path.write_text("x = 1\n" + "#" * size)
            files.append(path)
    return sorted(files)


def test_a_package_stays_in_one_task(tmp_path: Path) -> None:
    files = _tree(tmp_path, {f"pkg{i}": 3 for i in range(10)}, size=10)
    todo = [(f, b"x" * 10) for f in files]  # a package: 1/10 of the source
    chunks = _chunks(todo, jobs=2)
    assert sorted(p for c in chunks for p, _ in c) == files  # each file once
    for chunk in chunks:
        assert len({p.parent.parent for p, _ in chunk}) == 1
    assert len(chunks) == 10


def test_a_large_package_is_split_and_the_largest_task_goes_first(
    tmp_path: Path,
) -> None:
    files = _tree(tmp_path, {"big": 40, "small": 2})
    todo = [(f, b"x" * (1000 if "big" in str(f) else 10)) for f in files]
    chunks = _chunks(todo, jobs=2)
    total = sum(len(d) for _, d in todo)
    assert all(
        sum(len(d) for _, d in c) <= max(total // (2 * CHUNKS_PER_JOB), 1000)
        for c in chunks
    )
    assert len(chunks) > 2
    sizes = [sum(len(d) for _, d in c) for c in chunks]
    assert sizes == sorted(sizes, reverse=True)
    assert sorted(p for c in chunks for p, _ in c) == files
