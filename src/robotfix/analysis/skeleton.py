"""The editor memo's view of a module's text (`analysis/unitmemo.py`): its
skeleton, the text with the numbers of function bodies blanked where only their own
function reads them (the module docstring of `unitmemo` says which are kept), and
what an edit of numbers only, or of a comment line between statements, changed of
it, told from the text.
"""

from __future__ import annotations

import ast
import re
from collections.abc import Sequence

from robotfix.analysis import inline
from robotfix.analysis.parameters import WORDS
from robotfix.astwalk import walk

# the characters of most numbers' literals (`1_000`, `2.5e-3`, `3j`; an edit of a
# hex literal is taken for one of code: only slower)
_NUMBER_CHARS = frozenset("0123456789_.eE+-jJ")
# what `str.splitlines` takes for a line break and ast does not (ast: `\n`, `\r\n`
# and a lone `\r`, as `source.LINE_BREAK`)
_OTHER_BREAKS = "\x0b\x0c\x1c\x1d\x1e\x85\u2028\u2029"
_AST_BREAK = re.compile(r"(?<=\n)|(?<=\r)(?!\n)")


def lines_of(text: str) -> list[str]:
    """`text`'s lines with their ends, as ast numbers them (a form feed in a
    comment is no line break): `str.splitlines` when the text holds none of
    the breaks only it sees (a scan of microseconds), else split on ast's."""
    if not any(c in text for c in _OTHER_BREAKS):
        return text.splitlines(keepends=True)
    lines = _AST_BREAK.split(text)
    if lines and not lines[-1]:
        lines.pop()
    return lines


def _common(a: str, b: str, bound: int, from_end: bool) -> int:
    """How many characters two texts share at their start (or end), at most
    `bound`, found by comparing halves (slices compared in C: a keystroke in a
    30 kB text costs microseconds)."""
    low, high = 0, bound
    while low < high:
        middle = (low + high + 1) // 2
        if from_end:
            same = (
                a[len(a) - middle : len(a) - low] == b[len(b) - middle : len(b) - low]
            )
        else:
            same = a[low:middle] == b[low:middle]
        if same:
            low = middle
        else:
            high = middle - 1
    return low


Region = tuple[int, int, int]


def region(before: str, after: str) -> Region:
    """Where two texts differ: the length of their common start, and where the
    differing part ends in each (the common end follows). Found once per edit
    and handed to the tests below (each finds it when not given it)."""
    start = _common(before, after, min(len(before), len(after)), from_end=False)
    bound = min(len(before), len(after)) - start
    tail = _common(before, after, bound, from_end=True)
    return start, len(before) - tail, len(after) - tail


def numbers_only(before: str, after: str, where: Region | None = None) -> bool:
    """Whether the one region where two texts differ holds only characters of
    numbers: otherwise text that `skeleton` keeps as it is changed, and so did
    the skeleton."""
    start, end, new_end = where or region(before, after)
    if "#" in before[before.rfind("\n", 0, start) + 1 : start]:
        return False  # in a comment (or after a `#` in a string: only slower)
    return _NUMBER_CHARS.issuperset(before[start:end]) and (
        _NUMBER_CHARS.issuperset(after[start:new_end])
    )


# What the analysis reads of a text besides its tree: whether the whole text holds
# one of these (`":=" in source.text`: interpreter, binder, frames), and whether a
# function's lines do (`parameters.WORDS`, `parameters._mentions`). A comment
# holding one is not taken for a comment alone (`comment_only`).
TEXT_WORDS = ("Annotated", "setattr", ":=", *WORDS)


def comment_only(
    tree: ast.Module, before: str, after: str, where: Region | None = None
) -> bool:
    """Whether two texts differ in one line only, which holds a comment or blanks
    and nothing else in both, none of `TEXT_WORDS`, and lies between statements
    (`tree` is `after`'s): no expression or simple statement spans it, so nothing
    the analysis reads holds it but the text of the statements around it (a
    method's, a class's, which key their items) and the skeleton, which then
    counts as unchanged. Not told in a text with a line that ends at a lone
    `\r` (ast counts it as a line break)."""
    if _lone_cr(before) or _lone_cr(after):
        return False
    start, end, new_end = where or region(before, after)
    changed = (before[start:end], after[start:new_end])
    if changed == ("", "") or any("\n" in c for c in changed):
        return False  # no change, or a line added, removed or split
    first = before.rfind("\n", 0, start) + 1  # the line's start, in both texts
    for text, stop in ((before, end), (after, new_end)):
        last = text.find("\n", stop)
        line = text[first : len(text) if last < 0 else last]
        kept = line.strip(" \t\f\r")
        if (kept and not kept.startswith("#")) or any(w in line for w in TEXT_WORDS):
            return False
    return _between(tree.body, before.count("\n", 0, start) + 1)


def _lone_cr(text: str) -> bool:
    """Whether a line of `text` ends at a lone `\r` (a break ast counts)."""
    return "\r" in text and text.count("\r") != text.count("\r\n")


def _line_end(text: str, at: int) -> int:
    found = text.find("\n", at)
    return len(text) if found < 0 else found


def _between(block: list[ast.stmt], line: int) -> bool:
    """Whether `line` lies in `block` between statements, or inside a compound one
    between its parts (`_in_compound`)."""
    for statement in block:
        if line < first_place(statement)[0]:
            return True
        if line <= _last(statement):
            return _in_compound(statement, line)
    return True


def _in_compound(node: ast.stmt | ast.excepthandler, line: int) -> bool:
    """Whether `line`, within compound `node` (a statement or an `except` clause),
    lies outside every expression of its header and between the statements of
    its blocks; False in a simple statement."""
    if isinstance(node, ast.Match):
        return False  # its cases carry no lines of their own
    names = ("body", "orelse", "finalbody")
    blocks = [b for b in (getattr(node, n, None) for n in names) if b]
    if not blocks:
        return False
    handlers = getattr(node, "handlers", [])
    inner = {id(s) for b in blocks for s in b} | {id(h) for h in handlers}
    for child in ast.iter_child_nodes(node):
        if id(child) not in inner and any(_spans(p, line) for p in walk(child)):
            return False
    for handler in handlers:
        if first_place(handler)[0] <= line <= _last(handler):
            return _in_compound(handler, line)
    for block in blocks:
        if first_place(block[0])[0] <= line <= _last(block[-1]):
            return _between(block, line)
    return True


def _spans(node: ast.AST, line: int) -> bool:
    first = getattr(node, "lineno", None)
    return first is not None and first <= line <= (node.end_lineno or first)  # type: ignore[attr-defined]


def first_place(node: ast.stmt | ast.excepthandler) -> tuple[int, int]:
    """Where a statement starts: at its first decorator's line, if any."""
    decorators: list[ast.expr] = getattr(node, "decorator_list", [])
    if decorators:
        return (min(d.lineno for d in decorators), 0)
    return (node.lineno, node.col_offset)


def _last(node: ast.stmt | ast.excepthandler) -> int:
    return node.end_lineno or node.lineno


def skeleton(
    tree: ast.Module, lines: list[str], also: tuple[int, int, int] | None = None
) -> str:
    """The module's text with the numeric literals of function bodies blanked where
    only their own function reads them (see the module docstring); `also`: one
    more number (line, start and end column: `method_number`'s), blanked with its
    length (only its method's nodes lie on its line), which only that method's
    items read (their keys hold its text)."""
    spans: dict[int, list[tuple[int, int]]] = {}
    if also is not None:
        spans[also[0]] = [(also[1], -also[2])]  # a negative end: length too
    todo: list[ast.AST] = []
    for node in walk(tree):
        # a helper its callers evaluate (`return v / 3.6`) is kept whole
        if (
            isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef))
            and inline.returned(node) is None
        ):
            todo.extend(node.body)
    seen: set[int] = set()
    while todo:
        node = todo.pop()
        if id(node) in seen:
            continue
        seen.add(id(node))
        if _blanked(node):
            spans.setdefault(node.lineno, []).append(  # type: ignore[attr-defined]
                (node.col_offset, node.end_col_offset)  # type: ignore[attr-defined]
            )
        else:
            todo.extend(_inside(node))
    if not spans:
        return "".join(lines)
    out = list(lines)
    for number, columns in spans.items():
        if number - 1 >= len(out):
            continue
        raw = out[number - 1].encode("utf-8", "surrogatepass")
        for start, end in sorted(columns, reverse=True):
            whole, end = end < 0, abs(end)
            rest = raw[end:].strip()
            mark = (
                b"#"
                if whole or not rest or rest.startswith(b"#")
                else b"#%d#" % (end - start)
            )
            raw = raw[:start] + mark + raw[end:]
        out[number - 1] = raw.decode("utf-8", "surrogatepass")
    return "".join(out)


def _blanked(node: ast.AST) -> bool:
    """A number the skeleton blanks where it meets it (`_inside`)."""
    return (
        type(node) is ast.Constant
        and type(node.value) in (int, float)
        and node.lineno == node.end_lineno
    )


def _inside(node: ast.AST) -> Sequence[ast.AST]:
    """The parts of a node of a function body in which the skeleton blanks
    numbers: none of a call, an `assert`, `raise`, a nested function (its own
    body is queued on its own), a lambda or a class; of a store to a name its
    value only (a store to an attribute or an item is kept whole, and so is an
    annotation); of an `if` or `while` its body, not its test."""
    kind = type(node)
    if kind is ast.Constant or kind in _KEPT:
        return ()
    if kind in (ast.Assign, ast.AugAssign, ast.AnnAssign):
        targets = node.targets if kind is ast.Assign else [node.target]  # type: ignore[attr-defined]
        if any(not isinstance(t, ast.Name) for t in targets):
            return ()
        value = node.value  # type: ignore[attr-defined]
        return () if value is None else (value,)
    if kind in (ast.If, ast.While):
        return [*node.body, *node.orelse]  # type: ignore[attr-defined]
    return list(ast.iter_child_nodes(node))


def same_skeleton(
    tree: ast.Module, before: str, after: str, where: Region | None = None
) -> bool | None:
    """Whether an edit of numbers only (`numbers_only`) left the skeleton as it
    was, told without making it: True when it changed one number the skeleton
    blanks (and its length, or nothing but a comment follows it), False when
    the number it changed is kept, None when that cannot be told this way."""
    found = _edited_number(tree, before, after, where)
    if found is None:
        return None
    path, a, b = found
    number = path[-1]
    functions = [
        i
        for i, n in enumerate(path)
        if isinstance(n, (ast.FunctionDef, ast.AsyncFunctionDef))
    ]
    if not functions:
        return False  # a module's or a class's number: kept
    function = path[functions[-1]]
    if (
        inline.returned(function) is not None
        or not any(path[functions[-1] + 1] is s for s in function.body)  # type: ignore[attr-defined]
        or not all(
            any(child is c for c in _inside(parent))
            for parent, child in zip(
                path[functions[-1] + 1 : -1], path[functions[-1] + 2 :], strict=True
            )
        )
    ):
        return False
    if not _one_number(number, a, b):
        return None
    raw = b.encode()
    delta = len(a.encode()) - len(raw)
    rest = raw[number.end_col_offset :].strip()  # type: ignore[attr-defined]
    return delta == 0 or not rest or rest.startswith(b"#")


def method_number(
    tree: ast.Module, before: str, after: str, where: Region | None = None
) -> tuple[int, int, int] | None:
    """Where (line, start and end column in `after`) an edit of numbers only
    changed one number that lies in the body of a method of a top-level class
    whose text holds none of `TEXT_WORDS`, and that is no one-expression helper:
    a number only that method's own items read, whatever its place (see
    `unitmemo`: the parameter summary reads only functions whose text holds a
    parameter word; the module phase and the syntactic facts other items ask of
    a method, `ends` and may-raise, read no number; helpers evaluated at their
    calls are module-level ones; the type model's answers are asked again).
    None for any other edit."""
    found = _edited_number(tree, before, after, where)
    if found is None or len(found[0]) < 4:
        return None
    path = found[0]
    root, method = path[1], path[2]
    if not (
        isinstance(root, ast.ClassDef)
        and isinstance(method, (ast.FunctionDef, ast.AsyncFunctionDef))
        and any(path[3] is s for s in method.body)
        and inline.returned(method) is None
    ):
        return None
    lines = lines_of(after)
    text = "".join(lines[first_place(method)[0] - 1 : method.end_lineno])
    number = path[-1]
    if any(word in text for word in TEXT_WORDS) or not _one_number(number, *found[1:]):
        return None
    return number.lineno, number.col_offset, number.end_col_offset  # type: ignore[attr-defined]


def _edited_number(
    tree: ast.Module, before: str, after: str, where: Region | None
) -> tuple[list[ast.AST], str, str] | None:
    """For an edit of numbers only within one line, the nodes from the module
    down to the one number it changed (`tree` is `after`'s), and the edited
    line before and after; None when the edit is not of one whole number."""
    if _lone_cr(before) or _lone_cr(after):
        return None  # lines are counted by `\n` here
    start, stop, new_stop = where or region(before, after)
    changed = (before[start:stop], after[start:new_stop])
    if changed == ("", "") or any("\n" in c for c in changed):
        return None
    first = before.rfind("\n", 0, start) + 1  # the line's start, in both texts
    a = before[first : _line_end(before, stop)]
    b = after[first : _line_end(after, new_stop)]
    begin = len(after[first:start].encode())
    end = len(after[first:new_stop].encode())
    path: list[ast.AST] = [tree]
    line = before.count("\n", 0, start) + 1
    while True:  # down to the node holding the change
        for child in ast.iter_child_nodes(path[-1]):
            if not hasattr(child, "end_lineno"):
                continue
            if (child.lineno, child.col_offset) <= (line, begin) and (  # type: ignore[attr-defined]
                (line, end) <= (child.end_lineno, child.end_col_offset)  # type: ignore[attr-defined]
            ):
                path.append(child)
                break
        else:
            break
    number = path[-1]
    if not _blanked(number) or type(number.value) is bool:  # type: ignore[attr-defined]
        return None
    return path, a, b


def _one_number(number: ast.AST, a: str, b: str) -> bool:
    """Whether the text `number` replaced on its line (`a` before, `b` after)
    was one number too (not `1+2` made `12`)."""
    delta = len(a.encode()) - len(b.encode())
    was = a.encode()[number.col_offset : number.end_col_offset + delta].decode()  # type: ignore[attr-defined]
    try:
        parsed = ast.parse(was, mode="eval").body
    except SyntaxError:
        return False
    return _blanked(parsed) and type(parsed.value) is not bool  # type: ignore[attr-defined]


_KEPT = (
    *(ast.Call, ast.Assert, ast.Raise, ast.Global, ast.Nonlocal),
    *(ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda, ast.ClassDef),
)
