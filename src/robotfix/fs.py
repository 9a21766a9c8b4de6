"""The one place RobotFix touches the user's disk: bounded reads of regular files,
atomic writes, and whether a path stays inside the checked folders.

Every read of a file the user (or a repository) controls goes through
`read_regular`: a FIFO, a device (`/dev/zero`) or a socket, reached directly or
through a symlink, is refused at `open` without blocking, and no read takes more
than `limit` bytes. Every write goes through `atomic_write`: a temporary file
created exclusively beside the target (never through a planted symlink), given the
target's owner, group, extended attributes and mode, fsync'd, then `os.replace`d,
so a full disk or a kill leaves the original intact; a user's file is replaced only
if it still holds what was read.
"""

from __future__ import annotations

import contextlib
import errno
import os
import stat
import tempfile
from collections.abc import Callable, Iterable, Iterator
from pathlib import Path
from typing import Any

try:
    import fcntl
except ImportError:  # not on Windows
    fcntl = None  # type: ignore[assignment]

MAX_FILE_BYTES = 32 * 1024 * 1024  # no source or interface file is near this
_FLAGS = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_CLOEXEC", 0)
_NOFOLLOW = getattr(os, "O_NOFOLLOW", 0)
# what `atomic_write` gives a file that replaces no regular file: 0666 less the
# umask, as `open()` would (0644 under the usual umask 022, 0600 under 077)
_NEW_FILE_MODE = 0o666


def _umask() -> int:
    mask = os.umask(0o022)  # POSIX has no read-only query; set it back at once
    os.umask(mask)
    return mask


_MEANWHILE = "another program wrote to it during the rewrite"
_LOST = f"{_MEANWHILE}, and one of its writes is lost"


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
    was opened. With follow=False a symlink at `path` itself is refused. While
    `noting`, the file's stamp is noted first."""
    for trace in _NOTING:
        trace.stamp(path)
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


# the traces noting what is read and probed (`noting`), innermost last
_NOTING: list[Any] = []


@contextlib.contextmanager
def noting(trace: Any) -> Iterator[Any]:
    """While inside, every file `read_regular` reads is stamped in `trace` and
    every `probe` answer kept there (a `Noted`, a `discovery.Trace`): a cached
    stage that reads the disk only through these holds while the trace does.
    None: nothing is noted (no cache will keep it)."""
    if trace is None:
        yield None
        return
    _NOTING.append(trace)
    try:
        yield trace
    finally:
        _NOTING.remove(trace)


class Noted:
    """What a computation read and probed (`noting`), to be handed to the traces
    noting when its result is used again (`remembered`)."""

    def __init__(self) -> None:
        self.stamps: dict[str, list[int] | None] = {}
        self.probes: dict[tuple[str, str], Any] = {}

    def stamp(self, path: str | os.PathLike[str]) -> None:
        name = os.fspath(path)
        if name not in self.stamps:
            self.stamps[name] = stamp(name)

    def take(self, other: Noted) -> None:
        for name, found in other.stamps.items():
            self.stamps.setdefault(name, found)
        self.probes.update(other.probes)


def replay(noted: Noted) -> None:
    """Hand what a computation noted to the traces noting now."""
    for trace in _NOTING:
        trace.take(noted)


def remembered(
    memo: dict[Any, tuple[Any, Noted]], key: Any, make: Callable[[], Any]
) -> Any:
    """`make()`, kept in `memo` under `key`: used again, what making it read and
    probed is handed to the traces noting then, as if it were made again."""
    if key in memo:
        value, noted = memo[key]
        replay(noted)
        return value
    noted = Noted()
    with noting(noted):
        value = make()
    memo[key] = (value, noted)
    return value


# the answers `probe` gave in the run under way (`answering`), by question
_ANSWERS: list[dict[tuple[str, str], Any]] = []


@contextlib.contextmanager
def answering() -> Iterator[None]:
    """While inside (a run), `probe` asks the disk each question once: the
    stages ask many again (the real path of a C++ file for its node's
    parameters and for the graph, `package.xml` up the folders above every
    file: 2,319 real paths of 512 files and 7,983 `isfile` of 3,536 on the
    issue-25 corpus). Each answer is still noted in the traces noting when it
    is asked."""
    _ANSWERS.append(_ANSWERS[-1] if _ANSWERS else {})
    try:
        yield
    finally:
        _ANSWERS.pop()


def probe(kind: str, path: str | os.PathLike[str]) -> Any:
    """`os.path.isfile` ("isfile") or `os.path.realpath` ("realpath") of `path`,
    noted in the traces `noting` holds (asked once in a run: `answering`)."""
    name = os.fspath(path)
    answer = asked(kind, name)
    for trace in _NOTING:
        trace.probes[(kind, name)] = answer
    return answer


def asked(kind: str, name: str) -> Any:
    """`probe`'s answer, not noted (discovery notes its own, in its trace)."""
    known = _ANSWERS[-1] if _ANSWERS else None
    if known is not None and (kind, name) in known:
        return known[(kind, name)]
    answer = os.path.isfile(name) if kind == "isfile" else _realpath(name, known)
    if known is not None:
        known[(kind, name)] = answer
    return answer


def _realpath(name: str, known: dict[tuple[str, str], Any] | None) -> str:
    """`os.path.realpath(name)`; in a run, a file that is no symlink is its
    folder's real path (asked once: `known`) and its name: `realpath` looks
    at every folder above a path again (an lstat each: 38,831 for the 4,385
    real paths of the issue-25 corpus's stages, its repositories symlinks)."""
    folder, base = os.path.split(name)
    if known is None or not folder or base in ("", ".", "..") or os.path.islink(name):
        return os.path.realpath(name)
    if ("realpath", folder) not in known:
        known[("realpath", folder)] = _realpath(folder, known)
    return os.path.join(known[("realpath", folder)], base)


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


class NotReplacedError(Exception):
    """`atomic_write` left a user's file as it was, for a reason in words ("changed
    while it was read", "has 2 hard links"); `replaced` when it did replace it but
    a write of another program was lost on the way."""

    def __init__(self, reason: str, replaced: bool = False) -> None:
        super().__init__(reason)
        self.reason = reason
        self.replaced = replaced


def atomic_write(
    path: str | os.PathLike[str], data: bytes, original: bytes | None = None
) -> None:
    """Replace the file at `path` with `data`, or leave it as it was.

    The temporary file is created with O_EXCL in the same folder (mkstemp), written,
    given the replaced file's owner, group, extended attributes (ACLs among them)
    and permission bits, fsync'd and renamed over `path`: the rename replaces a
    symlink at `path` itself, never its target. Only a regular file at `path` lends
    its metadata; anything else (nothing, a symlink, a FIFO) gives 0666 less the
    umask.

    With `original` (a user's file, as it was read) nothing is written, and
    NotReplacedError says why, unless `path` is a regular file with that content,
    one name (a rename would leave its other hard links with the old text), no
    other program's flock, and an owner, group and attributes this user can give
    the new file. The file is read again, and its stat and the stat of `path`
    compared with the first, just before the rename; a write that still reaches
    the old file (between that check and the rename, or through a descriptor
    opened before it) and is seen once the rename is synced, puts the file back
    as that write left it. What remains: a write after that last look, through a
    descriptor opened before the rename (README, `robotfix suggest`)."""
    target = Path(path)
    late = _replace(target, data, original)
    if late is None:
        return
    try:
        again = _replace(target, late, data)
    except (NotReplacedError, OSError):
        again = b""
    if again is not None:
        raise NotReplacedError(_LOST, replaced=True)
    raise NotReplacedError(f"{_MEANWHILE}; put back with that write")


def _replace(target: Path, data: bytes, original: bytes | None) -> bytes | None:
    """`atomic_write` once; with `original`, the old file's text if a write reached
    it after the last check (None otherwise)."""
    held, why = _open_existing(target)
    try:
        checked: tuple[int, os.stat_result, bytes] | None = None
        if original is not None:
            if held is None:
                raise NotReplacedError(why)
            checked = (held, _check_original(held, original), original)
        fd, tmp = tempfile.mkstemp(
            dir=target.parent, prefix=f".{target.name}.", suffix=".tmp"
        )
        try:
            with os.fdopen(fd, "wb") as out:
                out.write(data)
                out.flush()
                _copy_metadata(held, out.fileno(), strict=checked is not None)
                os.fsync(out.fileno())
            if checked is not None:
                _recheck(*checked, target)
            os.replace(tmp, target)
        except BaseException:
            with contextlib.suppress(OSError):
                os.unlink(tmp)
            raise
        if checked is None:
            return None
        _sync_folder(target.parent)  # the rename is durable; late writers have landed
        return _written_meanwhile(*checked[:2])
    finally:
        if held is not None:
            os.close(held)  # and with it the flock


def _written_meanwhile(held: int, first: os.stat_result) -> bytes | None:
    """Just after the rename: the replaced file's text if a write reached it since
    `first` (its ctime moved with the rename; its size and mtime did not)."""
    late = os.fstat(held)
    if (late.st_size, late.st_mtime_ns) == (first.st_size, first.st_mtime_ns):
        return None
    text = _head(held, MAX_FILE_BYTES + 1)
    if len(text) > MAX_FILE_BYTES:
        raise NotReplacedError(_LOST, replaced=True)
    return text


def _sync_folder(folder: Path) -> None:
    """fsync a folder, so a rename in it survives a crash (best effort)."""
    with contextlib.suppress(OSError):
        fd = os.open(folder, os.O_RDONLY | getattr(os, "O_DIRECTORY", 0))
        try:
            os.fsync(fd)
        finally:
            os.close(fd)


def _open_existing(target: Path) -> tuple[int | None, str]:
    """A descriptor of the regular file at `target` itself (not through a symlink),
    or None and why not: nothing there, something else, or not openable."""
    try:
        fd = os.open(target, _FLAGS | _NOFOLLOW)
    except OSError as err:
        return None, "a symlink" if err.errno == errno.ELOOP else _reason(err)
    if stat.S_ISREG(os.fstat(fd).st_mode):
        return fd, ""
    os.close(fd)
    return None, "not a regular file"


def _check_original(held: int, original: bytes) -> os.stat_result:
    """The stat of the user's file that is to be replaced, once it is known to hold
    `original`, to have one name and to be locked by no other program."""
    first = os.fstat(held)
    if first.st_nlink > 1:
        raise NotReplacedError(
            f"has {first.st_nlink} hard links, which a rewrite would split"
        )
    if fcntl is not None:
        try:
            fcntl.flock(held, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            raise NotReplacedError("locked by another program") from None
        except OSError:
            pass  # a file system without flock: the checks below still run
    if not _holds(held, original):
        raise NotReplacedError("changed while it was read")
    return first


def _recheck(held: int, first: os.stat_result, original: bytes, target: Path) -> None:
    """Just before the rename: the content, the open file's stat and the stat of the
    name being replaced are still those of `first`."""
    if (
        not _holds(held, original)
        or _stamp(os.fstat(held)) != _stamp(first)
        or _stamp(os.stat(target, follow_symlinks=False)) != _stamp(first)
    ):
        raise NotReplacedError("changed while it was read")


def _stamp(st: os.stat_result) -> list[int]:
    """`stamp_of`, and what else a rename over a user's file must not change."""
    return [*stamp_of(st), st.st_nlink, st.st_uid, st.st_gid]


def _holds(fd: int, original: bytes) -> bool:
    """Whether the open file holds exactly `original`."""
    return _head(fd, len(original) + 1) == original


def _head(fd: int, limit: int) -> bytes:
    """At most `limit` bytes of the open file, from its start."""
    os.lseek(fd, 0, os.SEEK_SET)
    chunks = []
    size = 0
    while size < limit and (chunk := os.read(fd, min(1 << 20, limit - size))):
        chunks.append(chunk)
        size += len(chunk)
    return b"".join(chunks)


def _copy_metadata(held: int | None, out: int, strict: bool) -> None:
    """Give `out` the owner, group, extended attributes and mode of the file open
    as `held`, or 0666 less the umask without one. What this user cannot give is
    left as the new file has it, or, when `strict`, refused (NotReplacedError)."""
    if held is None:
        os.fchmod(out, _NEW_FILE_MODE & ~_umask())
        return
    source, made = os.fstat(held), os.fstat(out)
    if (source.st_uid, source.st_gid) != (made.st_uid, made.st_gid):
        try:
            os.fchown(out, source.st_uid, source.st_gid)
        except PermissionError:
            if strict:
                raise NotReplacedError(
                    f"owned by uid {source.st_uid}, gid {source.st_gid}, which "
                    "this user cannot give the rewritten file"
                ) from None
    for name in _xattr_names(held, strict):
        try:
            value = os.getxattr(held, name)
            if _xattr(out, name) != value:
                os.setxattr(out, name, value)
        except OSError as err:
            if strict:
                raise NotReplacedError(
                    f"its extended attribute {name} cannot be kept ({_reason(err)})"
                ) from None
    os.fchmod(out, stat.S_IMODE(source.st_mode))  # after fchown, which clears setuid


def _xattr_names(fd: int, strict: bool) -> list[str]:
    if not hasattr(os, "listxattr"):
        return []
    try:
        return os.listxattr(fd)
    except OSError as err:
        if err.errno in (errno.ENOTSUP, errno.EOPNOTSUPP) or not strict:
            return []  # a file system without extended attributes
        raise NotReplacedError(
            f"its extended attributes cannot be read ({_reason(err)})"
        ) from None


def _xattr(fd: int, name: str) -> bytes | None:
    try:
        return os.getxattr(fd, name)
    except OSError:
        return None


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
    return stamp_of(st)


def stamp_of(st: os.stat_result) -> list[int]:
    """`stamp`, of a stat already made."""
    return [
        st.st_mtime_ns,
        st.st_ctime_ns,
        st.st_ino,
        st.st_dev,
        st.st_size,
        st.st_mode,
    ]
