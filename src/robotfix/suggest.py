"""`robotfix suggest`: propose `Annotated[..., "Unit('...')"]` for unannotated
variables whose unit the analysis can pin down, as a unified diff; `--apply` writes
it.

It never damages a file: the edited text must parse to the same program plus the
annotations (and the import), and every name the annotations write must mean there
what the edit means (robotfix.bindings: `typing.Annotated` when the module binds
`Annotated` itself), or nothing is shown or written; lines are split where `ast`
splits them; the import goes below a shebang, an encoding cookie, a licence header,
the docstring and `__future__` imports; line endings and the encoding (a BOM, a PEP
263 cookie) are kept; the write is atomic and keeps the owner, group, mode and
extended attributes (robotfix.fs), only of a file with one name that has not changed
since it was read, and never through a symlink to a file outside the checked paths.
A file that cannot be read or written gets one line on stderr, the others are still
processed, and the exit status is then 2.
"""

from __future__ import annotations

import ast
import difflib
import io
import os
import stat
import sys
import tokenize
import warnings
from pathlib import Path
from typing import TYPE_CHECKING

from robotfix import api, fs
from robotfix.bindings import IMPORTS, Bindings
from robotfix.config import Config, ConfigError, Flags, by_settings, load
from robotfix.discovery import discover, install_space
from robotfix.ros.catalog import MsgCatalog
from robotfix.source import LINE_BREAK

if TYPE_CHECKING:
    from robotfix.project.summary import Project

EXIT_OK, EXIT_FAILURE = 0, 2


class UnsafeEditError(Exception):
    """The suggestions cannot be applied safely; `reason` says why, in words."""

    def __init__(self, reason: str) -> None:
        super().__init__(reason)
        self.reason = reason


def run_suggest(paths: list[Path], msg_paths: list[Path], apply: bool) -> int:
    status = EXIT_OK
    present = []
    for path in paths:
        if os.path.exists(path):
            present.append(path)
        else:
            _say(f"robotfix: error: {path}: no such file or directory")
            status = EXIT_FAILURE
    if not present:
        return EXIT_FAILURE
    try:
        # `--msg-path` over every file's own settings (its nearest configuration),
        # as for `robotfix check`
        settings = Flags(msg_paths=tuple(msg_paths)).apply(load(present[0]))
        found = discover(present, settings)
        files = _unique(found.python_files)
        groups = by_settings(files, settings)
    except (ConfigError, OSError) as err:
        _say(f"robotfix: error: {err}")
        return EXIT_FAILURE
    for notice in found.notices:  # links leaving the paths, unreadable folders
        _say(f"robotfix: {notice.path}: {notice.message}; not written")
        status = EXIT_FAILURE
    apart = {file for _, group in groups for file in group}
    own = [file for file in files if file not in apart]
    changed_files = 0
    for config, group in [(settings, own), *groups]:
        if not group:
            continue
        catalog = _catalog(present, config)
        project = api.make_project(present, config, catalog)
        for file in group:
            outcome = _suggest_file(file, present, catalog, apply, config, project)
            if outcome is None:
                status = EXIT_FAILURE
            elif outcome:
                changed_files += 1
    if not changed_files:
        print(f"No suggestions in {_plural(len(files), 'file')}.")
    return status


def _suggest_file(
    file: Path,
    roots: list[Path],
    catalog: MsgCatalog,
    apply: bool,
    settings: Config,
    project: Project,
) -> bool | None:
    """Whether the file has suggestions (shown, and written with `apply`);
    None when something could not be done (said on stderr)."""
    try:
        original = fs.read_regular(file)
    except fs.UnreadableError as err:
        _say(f"robotfix: {file}: cannot read: {err.reason}; skipped")
        return None
    try:
        text, encoding = _decode(original)
    except (SyntaxError, UnicodeError, LookupError) as err:
        _say(f"robotfix: {file}: cannot decode: {err}; skipped")
        return None
    try:
        changed = annotate(text, str(file), catalog, settings, project)
    except UnsafeEditError as err:
        _say(f"robotfix: {file}: not annotated: {err.reason}")
        return None
    except Exception as err:  # one file's internal error never stops the run
        _say(
            f"robotfix: internal error while suggesting for {file}: "
            f"{type(err).__name__}: {err}; skipped"
        )
        return None
    if changed == text:
        return False
    _print_diff(file, text, changed)
    if not apply:
        return True
    return True if _write(file, roots, original, changed, encoding) else None


def _write(
    file: Path, roots: list[Path], original: bytes, changed: str, encoding: str
) -> bool:
    """Write the edited text over the file's real path; False (said why) if not."""
    real = Path(os.path.realpath(file))
    if not fs.within(file, roots):
        _say(
            f"robotfix: {file}: links to {real}, outside the checked paths; not written"
        )
        return False
    try:
        data = changed.encode(encoding)
    except UnicodeError:
        _say(f"robotfix: {file}: the suggestions cannot be written in {encoding}")
        return False
    try:
        mode = os.stat(real).st_mode
    except OSError as err:
        _say(f"robotfix: {file}: cannot write: {err.strerror or err}; left as it was")
        return False
    if not mode & (stat.S_IWUSR | stat.S_IWGRP | stat.S_IWOTH) or not os.access(
        real, os.W_OK
    ):
        _say(f"robotfix: {file}: read-only; not written")
        return False
    try:
        fs.atomic_write(real, data, original)
    except fs.NotReplacedError as err:
        _say(f"robotfix: {file}: {err.reason}{'' if err.replaced else '; not written'}")
        return False
    except OSError as err:
        _say(f"robotfix: {file}: cannot write: {err.strerror or err}; left as it was")
        return False
    return True


def _unique(files: list[Path]) -> list[Path]:
    """One path per real file (a symlink into the tree and its target are one file),
    preferring a spelling that is not a symlink; in the given order."""
    chosen: dict[str, Path] = {}
    for file in files:
        real = os.path.realpath(file)
        if real not in chosen or (chosen[real].is_symlink() and not file.is_symlink()):
            chosen[real] = file
    kept = set(map(id, chosen.values()))
    return [file for file in files if id(file) in kept]


def _decode(data: bytes) -> tuple[str, str]:
    """The text, decoded as Python does (BOM, PEP 263 cookie), and the codec that
    encodes it back to the same bytes."""
    encoding, _ = tokenize.detect_encoding(io.BytesIO(data).readline)
    text = data.decode(encoding)
    if text.encode(encoding) != data:
        raise UnicodeError(f"{encoding} does not give back the same bytes")
    return text, encoding


def _print_diff(file: Path, text: str, changed: str) -> None:
    before = [body for body, _ in _split(text)]
    after = [body for body, _ in _split(changed)]
    diff = difflib.unified_diff(before, after, f"a/{file}", f"b/{file}", lineterm="")
    sys.stdout.writelines(line + "\n" for line in diff)


def _catalog(paths: list[Path], settings: Config) -> MsgCatalog:
    folders = list(settings.msg_paths) + api.ros_interface_folders(paths)
    return MsgCatalog(
        api.interface_files(folders),
        rep103=settings.rep103,
        unit_suffixes=settings.unit_suffixes,
        distro=settings.ros_distro,
        installed=install_space(),
    )


def annotate(
    text: str,
    path: str,
    catalog: MsgCatalog,
    settings: Config | None = None,
    project: Project | None = None,
    suggestions: list[api.Suggestion] | None = None,
) -> str:
    """The text with every suggestion applied (or those given: the editor's one),
    and `Annotated` imported if needed (spelt `typing.Annotated` when the module
    binds `Annotated` itself). UnsafeEditError if the result would not be the same
    program plus the annotations, or a name the edit writes would mean something
    else there. `settings` and `project`: the user's stubs and the modules the file
    imports, as `check` sees them."""
    if suggestions is None:
        suggestions = api.unit_suggestions(text, path, catalog, settings, project)
    if not suggestions:
        return text
    tree = _parse(text)
    if tree is None:
        return text
    names = _bindings(text, tree)
    spelling = _spelling(names)
    lines = _split(text)
    applied: list[int] = []
    for s in sorted(suggestions, key=lambda s: (s.line, s.col), reverse=True):
        if not 1 <= s.line <= len(lines):
            continue
        body, end = lines[s.line - 1]
        start = _char_col(body, s.col)
        stop = start + len(s.name)
        if not _whole_name(body, start, stop, s.name):
            continue
        annotation = f": {spelling}[{s.kind}, \"Unit('{s.unit}')\"]"
        rest = body[stop:]
        if rest.startswith("=") and not rest.startswith("=="):
            rest = " = " + rest[1:].lstrip(" ")  # a default: `speed: T = 0.5`
        lines[s.line - 1] = (body[:stop] + annotation + rest, end)
        applied.append(s.line)
    if not applied:
        return text
    root = spelling.split(".")[0]
    imported_at = names.imported_at(root)
    if imported_at is None or imported_at >= min(applied):
        at = _import_index(text, tree)
        newline = _newline(text, lines, at)
        if at > 0 and not lines[at - 1][1]:  # the last line, without a break
            lines[at - 1] = (lines[at - 1][0], newline)
        lines.insert(at, (IMPORTS[root], newline))
        applied = [line + (line > at) for line in applied]
    result = "".join(body + end for body, end in lines)
    _verify(tree, result, applied)
    return result


def _bindings(text: str, tree: ast.Module, edited: bool = False) -> Bindings:
    try:
        return Bindings(text, tree)
    except (SyntaxError, ValueError) as err:
        would = "edited file would not compile" if edited else "file does not compile"
        raise UnsafeEditError(f"the {would} ({err})") from None
    except (RecursionError, MemoryError):
        raise UnsafeEditError("the file is nested too deeply to check") from None


def _spelling(names: Bindings) -> str:
    """`Annotated`, or `typing.Annotated` if the module binds `Annotated` to
    anything but typing's; UnsafeEditError if it binds `typing` too."""
    if not names.rebound("Annotated"):
        return "Annotated"
    if not names.rebound("typing"):
        return "typing.Annotated"
    raise UnsafeEditError(
        "this module binds both `Annotated` and `typing` to something else"
    )


def _split(text: str) -> list[tuple[str, str]]:
    """(line, its break) at the breaks `ast` counts: not at a form feed or U+2028."""
    lines = []
    start = 0
    for match in LINE_BREAK.finditer(text):
        lines.append((text[start : match.start()], match.group()))
        start = match.end()
    if start < len(text):
        lines.append((text[start:], ""))
    return lines


def _char_col(line: str, byte_col: int) -> int:
    if line.isascii():
        return byte_col
    return len(line.encode("utf-8")[:byte_col].decode("utf-8", errors="replace"))


def _whole_name(line: str, start: int, stop: int, name: str) -> bool:
    """`name` is at line[start:stop] as a whole name (not `speed` of `speed_limit`)."""
    if line[start:stop] != name:
        return False
    before = line[start - 1] if start > 0 else ""
    after = line[stop] if stop < len(line) else ""
    return not (after and (name + after).isidentifier()) and not (
        before and (before + name).isidentifier()
    )


def _parse(text: str) -> ast.Module | None:
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # SyntaxWarning in user code is theirs
            return ast.parse(text)
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        return None


def _import_index(text: str, tree: ast.Module) -> int:
    """The index in `_split(text)` where `from typing import Annotated` goes: after
    the logical line that ends the docstring and `__future__` imports, or else just
    before the first statement, so below a shebang, a coding cookie and a licence."""
    header: list[ast.stmt] = []
    for node in tree.body:
        docstring = (
            not header
            and node is tree.body[0]
            and isinstance(node, ast.Expr)
            and isinstance(node.value, ast.Constant)
            and isinstance(node.value.value, str)
        )
        future = isinstance(node, ast.ImportFrom) and node.module == "__future__"
        if not (docstring or future):
            break
        header.append(node)
    try:
        tokens = list(tokenize.generate_tokens(io.StringIO(_joined(text)).readline))
    except (tokenize.TokenError, SyntaxError):
        tokens = []
    if header:
        last = header[-1].end_lineno or header[-1].lineno
        for tok in tokens:
            if tok.type == tokenize.NEWLINE and tok.start[0] >= last:
                return tok.start[0]  # after the logical line (`\` continuations too)
        return last
    skipped = {tokenize.COMMENT, tokenize.NL, tokenize.NEWLINE, tokenize.ENCODING}
    for tok in tokens:
        if tok.type not in skipped:
            return tok.start[0] - 1
    first = tree.body[0] if tree.body else None
    return first.lineno - 1 if first is not None else 0


def _joined(text: str) -> str:
    """The text with every break `ast` counts made `\\n`, so tokenize's lines are
    `ast`'s lines."""
    return "".join(body + ("\n" if end else "") for body, end in _split(text))


def _newline(text: str, lines: list[tuple[str, str]], at: int) -> str:
    """The break of the line the import goes after (or before), else the file's."""
    for index in (at - 1, at):
        if 0 <= index < len(lines) and lines[index][1]:
            return lines[index][1]
    first = LINE_BREAK.search(text)
    return first.group() if first else "\n"


def _verify(before: ast.Module, text: str, applied: list[int]) -> None:
    """The edited text is the same program plus the annotations on the `applied`
    lines (one per entry) and the import, and every name those annotations write
    means there what the edit meant: anything else raises UnsafeEditError, and
    nothing is shown or written. `before` (the original's tree) is normalised in
    place."""
    after = _parse(text)
    if after is None:
        try:
            ast.parse(text)
        except (SyntaxError, ValueError) as err:
            raise UnsafeEditError(f"the edited file would not parse ({err})") from None
        except (RecursionError, MemoryError):
            pass
        raise UnsafeEditError("the edited file would not parse")
    _verify_names(text, after, set(applied))
    added = _count_annotated(after) - _count_annotated(before)
    # the transformer edits in place: `before` is not used after this
    if added != len(applied) or ast.dump(_Unannotate().visit(after)) != ast.dump(
        _Unannotate().visit(before)
    ):
        raise UnsafeEditError("the edit would change more than the annotations")


def _verify_names(text: str, after: ast.Module, lines: set[int]) -> None:
    """Each name the annotations on `lines` write (`Annotated` or `typing`, and
    `float`) is bound nowhere in the module to anything else, and one that needs
    an import is imported at the top level above its first use."""
    first: dict[str, int] = {}
    for node in ast.walk(after):
        if isinstance(node, (ast.AnnAssign, ast.arg)) and node.lineno in lines:
            for name in _written_names(node.annotation):
                first[name] = min(first.get(name, node.lineno), node.lineno)
    names = _bindings(text, after, edited=True)
    for name, line in sorted(first.items()):
        if names.rebound(name):
            raise UnsafeEditError(f"`{name}` is bound in this module to something else")
        at = names.imported_at(name)
        if name in IMPORTS and (at is None or at >= line):
            raise UnsafeEditError(f"`{name}` would be used above its import")


def _written_names(annotation: ast.expr | None) -> list[str]:
    """The names in an annotation as `annotate` writes it: `Annotated` (or
    `typing`) and the type's names (`float`, or `list` and `float`); none for any
    other annotation."""
    if not (
        _is_suggested(annotation)
        and isinstance(annotation, ast.Subscript)
        and isinstance(annotation.slice, ast.Tuple)
    ):
        return []
    head = annotation.value
    root = head.value if isinstance(head, ast.Attribute) else head
    kind = annotation.slice.elts[0]
    names = [root, *ast.walk(kind)]
    return [n.id for n in names if isinstance(n, ast.Name)]


def _count_annotated(tree: ast.Module) -> int:
    return sum(
        isinstance(node, ast.AnnAssign)
        or (isinstance(node, ast.arg) and _is_suggested(node.annotation))
        for node in ast.walk(tree)
    )


def _is_suggested(annotation: ast.expr | None) -> bool:
    """`Annotated[float, "Unit('...')"]` (or `typing.Annotated[...]`, or
    `list[float]` inside), as `annotate` writes it."""
    return (
        isinstance(annotation, ast.Subscript)
        and _is_annotated(annotation.value)
        and isinstance(annotation.slice, ast.Tuple)
        and len(annotation.slice.elts) == 2
        and isinstance(annotation.slice.elts[1], ast.Constant)
        and isinstance(annotation.slice.elts[1].value, str)
        and annotation.slice.elts[1].value.startswith("Unit('")
    )


def _is_annotated(head: ast.expr) -> bool:
    """`Annotated` or `typing.Annotated`."""
    if isinstance(head, ast.Attribute):
        return head.attr == "Annotated" and _is_name(head.value, "typing")
    return _is_name(head, "Annotated")


def _is_name(node: ast.expr, name: str) -> bool:
    return isinstance(node, ast.Name) and node.id == name


class _Unannotate(ast.NodeTransformer):
    """`x: T = v` and `self.x: T = v` -> `x = v`, a parameter's
    `Annotated[float, "Unit(...)"]` dropped, and the imports the edit adds
    (`from typing import Annotated`, `import typing`) dropped: what is left must be
    the same before and after the edit."""

    def visit_AnnAssign(self, node: ast.AnnAssign) -> ast.AST:
        if node.value is None or not isinstance(node.target, (ast.Name, ast.Attribute)):
            return node
        return ast.Assign(targets=[node.target], value=node.value, type_comment=None)

    def visit_arg(self, node: ast.arg) -> ast.AST:
        if _is_suggested(node.annotation):
            node.annotation = None
        return node

    def visit_Import(self, node: ast.Import) -> ast.AST | None:
        return _unless_added(node)

    def visit_ImportFrom(self, node: ast.ImportFrom) -> ast.AST | None:
        return _unless_added(node)


def _unless_added(node: ast.Import | ast.ImportFrom) -> ast.AST | None:
    """None for an import as the edit adds it, else the import."""
    return None if ast.unparse(node) in IMPORTS.values() else node


def _plural(n: int, word: str) -> str:
    return f"{n} {word}" if n == 1 else f"{n} {word}s"


def _say(message: str) -> None:
    print(message, file=sys.stderr)
