"""The one place RobotFix touches the user's disk: bounded reads of regular files,
atomic writes, and whether a path stays inside the checked folders.

Every read of a file the user (or a repository) controls goes through
`read_regular`: a FIFO, a device (`/dev/zero`) or a socket, reached directly or
through a symlink, is refused at `open` without blocking, and no read takes more
than `limit` bytes. Every write goes through `atomic_write`: a temporary file
created exclusively beside the target (never through a planted symlink), fsync'd,
then `os.replace`d, so a full disk or a kill leaves the original intact.
"""

from __future__ import annotations

import contextlib
import os
import stat
import tempfile
from collections.abc import Callable, Iterable
from pathlib import Path

MAX_FILE_BYTES = 32 * 1024 * 1024  # no source or interface file is near this
_FLAGS = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_CLOEXEC", 0)
_NOFOLLOW = getattr(os, "O_NOFOLLOW", 0)


class UnreadableError(Exception):
    """A file that is not read, with the reason in words ("not a regular file")."""

    def __init__(self, reason: str) -> None:
        super().__init__(reason)
        self.reason = reason


def read_regular(
    path: str | os.PathLike[str], limit: int = MAX_FILE_BYTES, follow: bool = True
) -> bytes:
    """The bytes of a regular file, at most `limit` of them; UnreadableError otherwise.

    O_NONBLOCK makes opening a FIFO return at once, and fstat on the open descriptor
    (not the path) decides, so a file swapped after a check is still judged by what
    was opened. With follow=False a symlink at `path` itself is refused."""
    try:
        fd = os.open(path, _FLAGS | (0 if follow else _NOFOLLOW))
    except OSError as err:
        raise UnreadableError(_reason(err)) from None
    try:
        info = os.fstat(fd)
        if not stat.S_ISREG(info.st_mode):
            raise UnreadableError("not a regular file")
        if info.st_size > limit:
            raise UnreadableError(f"larger than {limit // (1024 * 1024)} MB")
        chunks = []
        size = 0
        while size <= limit:
            chunk = os.read(fd, min(1 << 20, limit + 1 - size))
            if not chunk:
                break
            chunks.append(chunk)
            size += len(chunk)
        if size > limit:  # it grew while we read
            raise UnreadableError(f"larger than {limit // (1024 * 1024)} MB")
        return b"".join(chunks)
    except OSError as err:
        raise UnreadableError(_reason(err)) from None
    finally:
        os.close(fd)


def read_head(path: str | os.PathLike[str], size: int) -> bytes:
    """The first `size` bytes of a regular file (all of it when shorter), without
    blocking on a FIFO or a device; UnreadableError otherwise."""
    try:
        fd = os.open(path, _FLAGS)
    except OSError as err:
        raise UnreadableError(_reason(err)) from None
    try:
        if not stat.S_ISREG(os.fstat(fd).st_mode):
            raise UnreadableError("not a regular file")
        return os.read(fd, size)
    except OSError as err:
        raise UnreadableError(_reason(err)) from None
    finally:
        os.close(fd)


def read_text(path: str | os.PathLike[str], limit: int = MAX_FILE_BYTES) -> str:
    """A regular file's text as UTF-8 (a BOM dropped); UnreadableError otherwise."""
    try:
        return read_regular(path, limit).decode("utf-8-sig")
    except UnicodeDecodeError as err:
        raise UnreadableError(f"not UTF-8 ({err.reason} at byte {err.start})") from None


def atomic_write(path: str | os.PathLike[str], data: bytes) -> None:
    """Replace the file at `path` with `data`, or leave it as it was.

    The temporary file is created with O_EXCL in the same folder (mkstemp), written,
    fsync'd and renamed over `path`: the rename replaces a symlink at `path` itself,
    never its target. An existing file's permission bits are kept."""
    target = Path(path)
    try:
        mode: int | None = stat.S_IMODE(os.stat(target, follow_symlinks=False).st_mode)
    except FileNotFoundError:
        mode = None
    fd, tmp = tempfile.mkstemp(
        dir=target.parent, prefix=f".{target.name}.", suffix=".tmp"
    )
    try:
        with os.fdopen(fd, "wb") as out:
            out.write(data)
            out.flush()
            os.fsync(out.fileno())
        if mode is not None:
            os.chmod(tmp, mode)
        os.replace(tmp, target)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        raise


def create_exclusive(path: str | os.PathLike[str], data: bytes) -> bool:
    """Write a new file only if nothing (not even a dangling symlink) is at `path`.
    True when written; False when something was there or it could not be made. A
    write that fails (a full disk) removes the file it created, so no empty or cut
    file stays behind to stop the next run from writing it whole."""
    try:
        fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL | _NOFOLLOW, 0o644)
    except OSError:
        return False
    try:
        try:
            rest = memoryview(data)
            while rest:
                rest = rest[os.write(fd, rest) :]
        finally:
            os.close(fd)  # on some file systems a write's error surfaces here
    except OSError:
        with contextlib.suppress(OSError):
            os.unlink(path)  # ours: O_EXCL made it
        return False
    return True


def within(
    path: str | os.PathLike[str],
    roots: Iterable[str | os.PathLike[str]],
    resolve: Callable[[str | os.PathLike[str]], str] = os.path.realpath,
) -> bool:
    """Whether `path`, with every symlink resolved, lies inside one of `roots`
    (also resolved). A path that cannot be resolved is not inside. `resolve`:
    os.path.realpath, or a caller's wrapper of it (a discovery notes each answer)."""
    try:
        real = Path(resolve(path))
        return any(
            real == (root := Path(resolve(r))) or root in real.parents for r in roots
        )
    except (OSError, ValueError):
        return False


def _reason(err: OSError) -> str:
    return err.strerror or type(err).__name__


# a file or folder changed (mtime or ctime) this recently is not trusted by its
# stamp (git's "racily clean" rule: the next change could land in the same timestamp
# tick, and some file systems keep whole seconds): the result cache, the discovery
# trace and the module index's kept answers all use it
RACY_NS = 2_000_000_000


def stamp(name: str | os.PathLike[str]) -> list[int] | None:
    """A file's or folder's stamp for what is kept between runs (the result cache's
    hashes, `discovery.Trace`, the module index's answers): what was read is
    trusted while its stamp is unchanged. The ctime is in it, as git keeps it: a
    rewrite that restores the size and the mtime (`cp -p`, `os.utime`) still
    changes the ctime, which no file operation sets back."""
    try:
        st = os.stat(name)
    except (OSError, ValueError):
        return None
    return [
        st.st_mtime_ns,
        st.st_ctime_ns,
        st.st_ino,
        st.st_dev,
        st.st_size,
        st.st_mode,
    ]
