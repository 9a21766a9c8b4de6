"""robotfix.fs: reads that cannot block or balloon, writes that cannot truncate."""

from __future__ import annotations

import os
import stat
from pathlib import Path

import pytest

from robotfix import fs


def test_reads_a_regular_file_and_through_a_symlink(tmp_path: Path) -> None:
    (tmp_path / "a.py").write_bytes(b"x = 1\n")
    (tmp_path / "link.py").symlink_to("a.py")
    assert fs.read_regular(tmp_path / "a.py") == b"x = 1\n"
    assert fs.read_regular(tmp_path / "link.py") == b"x = 1\n"
    with pytest.raises(fs.UnreadableError):
        fs.read_regular(tmp_path / "link.py", follow=False)


def test_a_fifo_is_refused_at_once(tmp_path: Path) -> None:
    fifo = tmp_path / "fifo.py"
    os.mkfifo(fifo)
    (tmp_path / "to_fifo.py").symlink_to(fifo)
    for path in (fifo, tmp_path / "to_fifo.py"):
        with pytest.raises(fs.UnreadableError, match="not a regular file"):
            fs.read_regular(path)


def test_devices_and_folders_are_refused(tmp_path: Path) -> None:
    (tmp_path / "zero.py").symlink_to("/dev/zero")
    with pytest.raises(fs.UnreadableError, match="not a regular file"):
        fs.read_regular(tmp_path / "zero.py")
    with pytest.raises(fs.UnreadableError):
        fs.read_regular(tmp_path)
    with pytest.raises(fs.UnreadableError):
        fs.read_regular(tmp_path / "missing.py")


def test_reads_are_capped(tmp_path: Path) -> None:
    (tmp_path / "big.msg").write_bytes(b"#" * 2048)
    with pytest.raises(fs.UnreadableError, match="larger than"):
        fs.read_regular(tmp_path / "big.msg", limit=1024)


def test_read_text_drops_a_bom_and_rejects_non_utf8(tmp_path: Path) -> None:
    (tmp_path / "a.msg").write_bytes(b"\xef\xbb\xbffloat64 x\n")
    assert fs.read_text(tmp_path / "a.msg") == "float64 x\n"
    (tmp_path / "b.msg").write_bytes(b"\xff\xfe")
    with pytest.raises(fs.UnreadableError, match="not UTF-8"):
        fs.read_text(tmp_path / "b.msg")


def test_atomic_write_keeps_mode_and_replaces_a_link_not_its_target(
    tmp_path: Path,
) -> None:
    target = tmp_path / "node.py"
    target.write_text("old\n")
    target.chmod(0o755)
    fs.atomic_write(target, b"new\n")
    assert target.read_text() == "new\n"
    assert target.stat().st_mode & 0o777 == 0o755
    victim = tmp_path / "victim.txt"
    victim.write_text("precious\n")
    link = tmp_path / "results.json"
    link.symlink_to(victim)
    fs.atomic_write(link, b"{}")
    assert victim.read_text() == "precious\n"
    assert not link.is_symlink() and link.read_text() == "{}"
    assert [p.name for p in tmp_path.iterdir() if p.suffix == ".tmp"] == []


@pytest.mark.parametrize("umask, mode", [(0o022, 0o644), (0o077, 0o600)])
def test_atomic_write_over_a_symlink_makes_a_file_of_the_umask(
    tmp_path: Path, umask: int, mode: int
) -> None:
    # a symlink's own mode is 0777: planted at a cache file name, it made the
    # cache world-writable (reliability2 N4); a new file gets 0666 less the umask
    (tmp_path / "out.json").write_text("{}")
    link = tmp_path / "results.json"
    link.symlink_to(tmp_path / "out.json")
    before = os.umask(umask)
    try:
        fs.atomic_write(link, b"{}")
        fs.atomic_write(tmp_path / "new.json", b"{}")
    finally:
        os.umask(before)
    assert not link.is_symlink()
    assert stat.S_IMODE(link.stat().st_mode) == mode
    assert stat.S_IMODE((tmp_path / "new.json").stat().st_mode) == mode


def test_atomic_write_keeps_extended_attributes(tmp_path: Path) -> None:
    target = tmp_path / "results.json"
    target.write_text("{}")
    try:
        os.setxattr(target, "user.origin", b"kept")
    except OSError:
        pytest.skip("no user extended attributes on this file system")
    fs.atomic_write(target, b"[]")
    assert os.getxattr(target, "user.origin") == b"kept"


@pytest.mark.skipif(os.geteuid() != 0, reason="giving a file away: root")
def test_atomic_write_as_root_keeps_the_owner(tmp_path: Path) -> None:
    target = tmp_path / "results.json"
    target.write_text("{}")
    os.chown(target, 1234, 1234)
    target.chmod(0o4750)  # fchown clears setuid: the mode is set after it
    fs.atomic_write(target, b"[]")
    info = target.stat()
    assert (info.st_uid, info.st_gid, stat.S_IMODE(info.st_mode)) == (
        1234,
        1234,
        0o4750,
    )


def test_atomic_write_with_original_refuses_a_changed_file(tmp_path: Path) -> None:
    target = tmp_path / "node.py"
    target.write_text("new\n")
    with pytest.raises(fs.NotReplacedError, match="changed while it was read"):
        fs.atomic_write(target, b"annotated\n", original=b"old\n")
    assert target.read_text() == "new\n"
    (tmp_path / "link.py").symlink_to(target)
    with pytest.raises(fs.NotReplacedError, match="a symlink"):
        fs.atomic_write(tmp_path / "link.py", b"annotated\n", original=b"new\n")
    assert (tmp_path / "link.py").is_symlink()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["link.py", "node.py"]


def test_atomic_write_with_original_refuses_a_file_locked_by_another_program(
    tmp_path: Path,
) -> None:
    fcntl = pytest.importorskip("fcntl")
    target = tmp_path / "node.py"
    target.write_text("old\n")
    with open(target) as other:
        fcntl.flock(other, fcntl.LOCK_EX)
        with pytest.raises(fs.NotReplacedError, match="locked by another program"):
            fs.atomic_write(target, b"annotated\n", original=b"old\n")
    assert target.read_text() == "old\n"
    fs.atomic_write(target, b"annotated\n", original=b"old\n")
    assert target.read_text() == "annotated\n"


def test_atomic_write_failure_leaves_the_original(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    target = tmp_path / "node.py"
    target.write_text("original\n")

    def disk_full(fd: int) -> None:
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(os, "fsync", disk_full)
    with pytest.raises(OSError, match="No space"):
        fs.atomic_write(target, b"new text\n")
    assert target.read_text() == "original\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["node.py"]


def test_create_exclusive_never_follows_a_dangling_link(tmp_path: Path) -> None:
    (tmp_path / ".gitignore").symlink_to(tmp_path / "outside.txt")
    assert not fs.create_exclusive(tmp_path / ".gitignore", b"*\n")
    assert not (tmp_path / "outside.txt").exists()
    assert fs.create_exclusive(tmp_path / "new", b"*\n")
    assert not fs.create_exclusive(tmp_path / "new", b"again\n")


def test_within_resolves_links(tmp_path: Path) -> None:
    (tmp_path / "tree").mkdir()
    (tmp_path / "elsewhere").mkdir()
    (tmp_path / "elsewhere" / "theirs.py").write_text("")
    (tmp_path / "tree" / "link.py").symlink_to("../elsewhere/theirs.py")
    (tmp_path / "tree" / "mine.py").write_text("")
    assert fs.within(tmp_path / "tree" / "mine.py", [tmp_path / "tree"])
    assert not fs.within(tmp_path / "tree" / "link.py", [tmp_path / "tree"])
    assert fs.within(tmp_path / "tree" / "link.py", [tmp_path])
