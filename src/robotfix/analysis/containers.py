"""Sequences of numbers: what holds of the elements of a list, tuple or array field.

A sequence value knows its elements one by one (`elements`: a display, a constant
table), or only what holds of each of them (`Items`: a refinement, a message array
field's `#RobotFix#` lines, the filter of a comprehension), or both. A refinement on
a sequence is on its elements; `len(_)` in it is on its length (`Items.size`).

Lists are mutable and shared: what a list holds one element at a time is trusted
only while no other name, attribute or field can change it (`stripped` keeps what
its declaration says and forgets the rest). Pure functions of values and terms: the
checks are in checks.py, the evaluation in expressions.py and calls.py.
"""

from __future__ import annotations

import ast
from collections.abc import Callable
from dataclasses import replace
from fractions import Fraction

from robotfix.analysis.values import SEQUENCES, Items, Kept, Value
from robotfix.annotations import ast as A
from robotfix.annotations.units import Unit
from robotfix.astwalk import BLOCK_FIELDS, FIELDS, Mentions, fields

SELF = A.Name("_")
MAX_SPELLED = 32  # elements named one by one in `each` (`_ == a or _ == b ...`)
MAX_SUMMED = 16  # a known length up to which sum() adds one element per position
KIND_ORDER = ("bool", "int", "float")
# Methods that change a list in place, and those that only read it.
MUTATORS = frozenset(
    {"append", "extend", "insert", "pop", "remove", "clear", "sort", "reverse"}
)
READERS = frozenset({"index", "count", "copy"})


def each_of(value: Value) -> A.Expr:
    """A predicate over `_` that every element of `value` satisfies."""
    parts: list[A.Expr] = []
    if value.items is not None and value.items.each != A.TRUE:
        parts.append(value.items.each)
    if value.elements is not None:
        terms = list(dict.fromkeys(e.term for e in value.elements))
        if not terms:
            return A.Bool(False)  # no element at all
        if None not in terms and len(terms) <= MAX_SPELLED:
            equal = [A.Binary("==", SELF, t) for t in terms if t is not None]
            parts.append(A.join("or", equal))
        else:
            parts += _range_of([t for t in terms if t is not None], len(terms))
    return A.conjoin(parts)


def _range_of(terms: list[A.Expr], count: int) -> list[A.Expr]:
    """`lo <= _ <= hi` for many elements that are all numbers written out."""
    values = [fold(t) for t in terms]
    numbers = [v for v in values if v is not None]
    if len(numbers) != count or not numbers:
        return []
    is_int = all(isinstance(t, A.Num) and t.is_int for t in terms)
    low, high = A.Num(min(numbers), is_int), A.Num(max(numbers), is_int)
    return [A.Binary("<=", low, SELF), A.Binary("<=", SELF, high)]


def size_of(value: Value) -> A.Expr:
    """A predicate over `_` that the length of `value` satisfies."""
    if value.elements is not None:
        return A.Binary("==", SELF, number(len(value.elements)))
    if value.items is not None:
        return value.items.size
    return A.TRUE


def length_term(value: Value) -> A.Expr | None:
    """The length of `value` as a term, when its size pins it (`_ == n`)."""
    size = size_of(value)
    for part in A.conjuncts(size):
        if isinstance(part, A.Binary) and part.op == "==":
            if part.left == SELF and SELF not in A.walk(part.right):
                return part.right
            if part.right == SELF and SELF not in A.walk(part.left):
                return part.left
    return None


def item_kind(value: Value) -> str:
    """The kind of the elements: int, float, bool, str, or unknown."""
    kinds: set[str] = set()
    if value.elements is not None:
        kinds = {e.kind for e in value.elements}
    if value.items is not None and value.items.kind != "unknown":
        kinds.add(value.items.kind)
    if len(kinds) == 1:
        return kinds.pop()
    if kinds and kinds <= set(KIND_ORDER):
        return max(kinds, key=KIND_ORDER.index)
    return "unknown"


def common_unit(values: tuple[Value, ...]) -> Unit | None:
    """The unit the elements of a display share (literals take it), if one."""
    units = {v.unit for v in values if not v.literal}
    return units.pop() if len(units) == 1 else None


def number(value: int) -> A.Num:
    return A.Num(Fraction(value), True)


def at(predicate: A.Expr, term: A.Expr) -> A.Expr:
    """`predicate` with `_` standing for `term`."""
    return A.substitute(predicate, {"_": term})


# What holds of every element may speak of values of its own (`[r * 100 for r in
# ranges]`: each element is `r * 100` for some `r >= 0`): these are names `#<id>`,
# which every use of the predicate replaces by symbols of its own.
BOUND = "#"


def bound(term: A.Expr, since: int) -> A.Expr:
    """`term` with the symbols newer than `since` made bound names."""
    if isinstance(term, A.Sym):
        return A.Name(f"{BOUND}{term.ident}") if term.ident > since else term
    kids = A.children(term)
    if not kids:
        return term
    return A.rebuild(term, tuple(bound(k, since) for k in kids))


def instantiate(
    predicate: A.Expr, term: A.Expr, fresh: Callable[[str], A.Expr]
) -> A.Expr:
    """`at(predicate, term)`, its bound names replaced by fresh symbols (one per
    name), so that each element has values of its own."""
    names = {
        n.name: fresh(n.name) for n in A.names(predicate) if n.name.startswith(BOUND)
    }
    return A.substitute(predicate, {**names, "_": term})


def declared(kind: str, kept: Kept) -> Value:
    """A sequence of which only its declaration is known."""
    parts = [p for p in (kept.size, kept.shape) if p != A.TRUE]
    return Value(
        kind if kind in SEQUENCES else "list",
        unit=kept.unit,
        items=Items(kept.item, kept.each, A.conjoin(parts), kept),
    )


def each_only(kept: Kept) -> Kept:
    """A declaration's parts on each element (to check elements being added)."""
    return replace(kept, size=A.TRUE, shape=A.TRUE)


def followed(value: Value) -> bool:
    """Whether RobotFix knows more of a list than its elements' kind and unit."""
    items = value.items
    return value.elements is not None or (
        items is not None and (items.each != A.TRUE or items.size != A.TRUE)
    )


def stripped(value: Value) -> Value:
    """What stays true of a list that something else may change: its declaration
    (or only its elements' kind and unit). Tuples never change."""
    if value.kind != "list" or (value.elements is None and value.items is None):
        return value
    kept = value.items.kept if value.items is not None else None
    if kept is not None:
        return declared("list", kept)
    items = value.items or Items()
    message, of = items.message, items.of  # the elements' type stays
    types = {e.name if e.kind == "msg" else "" for e in value.elements or ()}
    if len(types) == 1 and "" not in types:  # `[Twist(), Twist()]`: messages
        message = (types.pop(), "unknown")
    kind = item_kind(value)
    return Value("list", unit=value.unit, items=Items(kind, message=message, of=of))


def with_element(
    value: Value, element: Value, index: int | None = None, grows: bool = True
) -> Value:
    """`value` after `append(element)` (`grows`), or after one element is replaced
    (at `index` when known). The caller checks a declaration against it (and then
    adds what the declaration says of the length, `holding`)."""
    items = value.items or Items(item_kind(value))
    elements = value.elements
    if elements is not None and element.term is not None and grows:
        elements = (*elements, element)
    elif (
        elements is not None
        and element.term is not None
        and index is not None
        and -len(elements) <= index < len(elements)
    ):
        changed = list(elements)
        changed[index] = element
        elements = tuple(changed)
    else:
        elements = None
    each: A.Expr = A.TRUE
    if element.term is not None:
        each = A.Binary(
            "or",
            each_of(value),
            A.Binary("==", SELF, element.term),
        )
    if A.larger_than(each, 200):
        each = A.TRUE
    kept = items.kept
    if kept is not None:
        each = kept.each if each == A.TRUE else each
    length = length_term(value)
    size = size_of(value)
    if grows:
        size = (
            A.Binary("==", SELF, A.Binary("+", length, number(1)))
            if length is not None
            else A.Binary(">=", SELF, number(1))
        )
    kind = _joint_kind(item_kind(value), element.kind)
    unit = value.unit if value.unit == element.unit or element.literal else None
    if kept is not None:
        unit = kept.unit
    elif value.elements == () and not element.literal:
        unit = element.unit
    # the elements' type stays while what is added is of it (`history.append(odom)`)
    message = items.message if element.kind == "msg" else None
    of = items.of if element.kind == "instance" else None
    if (message and message[0] != element.name) or (
        of is not None and getattr(of, "name", None) != element.name
    ):
        message = of = None
    return Value(
        value.kind,
        unit=unit,
        elements=elements,
        items=Items(kind, each, size, kept, message=message, of=of),
    )


def holding(value: Value) -> Value:
    """`value` once it was checked against its declaration: its length also keeps
    what the declaration says."""
    kept = value.items.kept if value.items is not None else None
    if kept is None or kept.size == A.TRUE or value.items is None:
        return value
    size = A.conjoin([value.items.size, kept.size])
    return replace(value, items=replace(value.items, size=size))


def _joint_kind(a: str, b: str) -> str:
    if a == b or b == "unknown":
        return a
    if {a, b} <= set(KIND_ORDER):
        return max((a, b), key=KIND_ORDER.index)
    return "unknown"


def forgetting(value: Value, grows: bool | None = None) -> Value:
    """`value` after a change to its elements RobotFix does not follow: what its
    declaration says; for a list of no declaration, only its length when it only
    grew (`grows`), or its elements when some were taken out (`grows` False)."""
    items = value.items or Items(item_kind(value))
    if items.kept is not None:
        return declared(value.kind, items.kept)
    length = length_term(value)
    each: A.Expr = A.TRUE
    size: A.Expr = A.TRUE
    if grows is True and length is not None:
        size = A.Binary(">=", SELF, length)
    elif grows is False:
        each = each_of(value)
        if length is not None:
            size = A.Binary("<=", SELF, length)
    return Value(value.kind, unit=value.unit, items=Items(items.kind, each, size))


def joined(x: Value, y: Value) -> Value:
    """A sequence that is `x` on one path and `y` on the other."""
    kind = x.kind if x.kind == y.kind else "list"
    same = x.items is not None and x.items == y.items
    if same and x.elements is None and y.elements is None:
        return replace(x, kind=kind, unit=x.unit if x.unit == y.unit else None)
    each: A.Expr = A.Binary("or", each_of(x), each_of(y))
    size = A.Binary("or", size_of(x), size_of(y))
    kept = x.items.kept if x.items is not None else None
    if kept is None or y.items is None or y.items.kept != kept:
        kept = None
    if A.larger_than(each, 400):
        each = A.TRUE
    return Value(
        kind,
        unit=x.unit if x.unit == y.unit else None,
        items=Items(
            item_kind(x) if item_kind(x) == item_kind(y) else "unknown",
            each,
            size,
            kept,
        ),
    )


def concatenated(x: Value, y: Value) -> Value:
    """`x + y` of two sequences."""
    kind = x.kind if x.kind == y.kind else "list"
    unit = x.unit if x.unit == y.unit else (x.unit if y.elements == () else None)
    if y.unit is not None and x.elements == ():
        unit = y.unit
    if x.elements is not None and y.elements is not None:
        elements = (*x.elements, *y.elements)
        return Value(kind, unit=unit, elements=elements)
    lx, ly = length_term(x), length_term(y)
    both = lx is not None and ly is not None
    size = A.Binary("==", SELF, A.Binary("+", lx, ly)) if both else A.TRUE  # type: ignore[arg-type]
    each = A.Binary("or", each_of(x), each_of(y))
    kinds = {item_kind(x), item_kind(y)}
    item = kinds.pop() if len(kinds) == 1 else "unknown"
    return Value(kind, unit=unit, items=Items(item, each, size))


def repeated(value: Value, times: Value) -> Value | None:
    """`[0.0] * n`: the elements of `value`, `n` times over."""
    count = times.term
    if count is None or times.kind not in ("int", "bool", "unknown"):
        return None
    known = fold(count)
    if (
        value.elements is not None
        and known is not None
        and known.denominator == 1
        and 0 <= known * len(value.elements) <= MAX_SPELLED
    ):
        return replace(value, elements=value.elements * int(known), items=None)
    length = length_term(value)
    size = (
        A.Binary(
            "==",
            SELF,
            A.Ite(
                A.Binary(">", count, number(0)), A.Binary("*", length, count), number(0)
            ),
        )
        if length is not None
        else A.TRUE
    )
    items = Items(item_kind(value), each_of(value), size)
    return Value(value.kind, unit=value.unit, items=items)


def sliced(value: Value, at_most: int | None = None) -> Value:
    """`xs[a:b]`: a new sequence of some of the elements; `at_most` of them when
    the slice's constant bounds say so (`xs[0:360]`, `xs[-90:]`)."""
    length = length_term(value)
    parts: list[A.Expr] = [A.Binary(">=", SELF, number(0))]
    if length is not None:
        parts.append(A.Binary("<=", SELF, length))
    if at_most is not None:
        parts.append(A.Binary("<=", SELF, number(at_most)))
    size = A.conjoin(parts) if len(parts) > 1 else A.TRUE
    return Value(
        "tuple" if value.kind == "tuple" else "list",
        unit=value.unit,
        items=Items(item_kind(value), each_of(value), size),
    )


def comprehension_size(value: Value, filtered: bool) -> A.Expr:
    """The length of `[f(x) for x in value]` (one `for`): that of `value`; with an
    `if`, at most that (its upper bounds)."""
    size = size_of(value)
    if not filtered or size == A.TRUE:
        return size
    length = length_term(value)
    if length is not None:
        return A.Binary(
            "and", A.Binary(">=", SELF, number(0)), A.Binary("<=", SELF, length)
        )
    return A.conjoin(
        [
            part
            for part in A.conjuncts(size)
            if isinstance(part, A.Binary)
            and part.op in ("<", "<=")
            and part.left == SELF
            and SELF not in A.walk(part.right)
        ]
    )


def slice_length(node: ast.Slice) -> int | None:
    """The most elements `xs[a:b]` can have whatever `xs` is, from constant bounds:
    `b - a` for `0 <= a`, `0 <= b` (`a` may be left out), `k` for `xs[-k:]`."""
    if node.step is not None:
        return None
    low = 0 if node.lower is None else _int_constant(node.lower)
    high = None if node.upper is None else _int_constant(node.upper)
    if low is None:
        return None
    if low < 0 and node.upper is None:
        return -low
    if high is None or low < 0 or high < 0:
        return None
    return max(0, high - low)


def _int_constant(node: ast.expr) -> int | None:
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub):
        found = _int_constant(node.operand)
        return None if found is None else -found
    if isinstance(node, ast.Constant) and type(node.value) is int:
        return node.value
    return None


def copied(value: Value) -> Value:
    """`list(xs)`, `sorted(xs)`: a new list of the same elements (in some order)."""
    return Value(
        "list",
        unit=value.unit,
        items=Items(item_kind(value), each_of(value), size_of(value)),
    )


def bounds(each: A.Expr) -> tuple[A.Expr | None, A.Expr | None]:
    """Closed lower and upper bounds on `_` that `each` states (`0 <= _ <= 10`,
    `abs(_) <= 2`), for sums over many elements."""
    low: A.Expr | None = None
    high: A.Expr | None = None
    for part in A.conjuncts(each):
        if not isinstance(part, A.Binary) or part.op not in ("<", "<=", ">", ">="):
            continue
        left, right, op = part.left, part.right, part.op
        if right == SELF:
            left, right = right, left
            op = {"<": ">", "<=": ">=", ">": "<", ">=": "<="}[op]
        if _closed(right) and left == SELF:
            if op in ("<", "<="):
                high = right
            else:
                low = right
        elif (
            _closed(right)
            and op in ("<", "<=")
            and isinstance(left, A.Func)
            and left.name == "abs"
            and left.args == (SELF,)
        ):
            high, low = right, A.Unary("-", right)
    return low, high


def fold(term: A.Expr) -> Fraction | None:
    """The value of a number written out (`3`, `-0.5`)."""
    if isinstance(term, A.Num):
        return term.value
    if isinstance(term, A.Unary) and term.op == "-":
        inner = fold(term.operand)
        return None if inner is None else -inner
    return None


def _closed(term: A.Expr) -> bool:
    return not any(isinstance(n, (A.Name, A.Sym)) for n in A.walk(term))


def lengths_as(expr: A.Expr, path: str, replacement: A.Expr) -> A.Expr:
    """`expr` with every `len(path)` replaced (the same object when there is none)."""
    if isinstance(expr, A.Func) and expr.name == "len" and expr.args == (A.Name(path),):
        return replacement
    kids = A.children(expr)
    if not kids:
        return expr
    new = tuple(lengths_as(k, path, replacement) for k in kids)
    if all(a is b for a, b in zip(new, kids, strict=True)):
        return expr
    return A.rebuild(expr, new)


# Calls that only read the list they are given (or copy it).
READING_CALLS = frozenset(
    {"len", "min", "max", "sum", "sorted", "list", "tuple", "set", "frozenset"}
    | {"enumerate", "reversed", "iter", "any", "all", "zip", "print", "str", "repr"}
)
_NESTED = frozenset({ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda, ast.ClassDef})


def shared_names(
    body: list[ast.stmt],
    changes: bool = False,
    lent: set[str] | None = None,
    keep: Mentions | None = None,
) -> set[str]:
    """Names in statements `body` (a function's or module's) that may share their
    list with another name, attribute, field or callee: used other than by a read,
    a change RobotFix follows (`xs.append(v)`, `xs[i] = v`), unpacking, or
    `return`. A use inside a nested function or class counts as shared (it may run
    at any time). With `changes`, a change it follows counts too (for a loop).
    Given `lent`, names shared only by being passed to calls (`g(xs)`) go there
    instead: they hold what they hold up to the first such call (`lends`).
    Given `keep`, only the statements it keeps are looked at: the answer holds
    for the names it looks for (`shares`)."""
    shared: set[str] = set()
    passed: set[str] = set()
    todo: list[tuple[ast.AST, bool]] = [
        (n, type(n) in _NESTED) for n in body if keep is None or keep(n)
    ]
    name_class, load_class = ast.Name, ast.Load
    while todo:
        node, nested = todo.pop()
        # the fields that may hold a node (no name string, context or operator)
        for field in FIELDS.get(type(node)) or fields(type(node)):
            value = getattr(node, field, None)
            if type(value) is not list:
                value = (value,)
            elif keep is not None and field in BLOCK_FIELDS:
                value = [s for s in value if keep(s)]
            for child in value:
                kind = type(child)
                if kind is name_class:
                    if type(child.ctx) is load_class and (  # type: ignore[union-attr]
                        nested
                        or not _plain_use(node, child)  # type: ignore[arg-type]
                        or (changes and _change(node))
                    ):
                        if lent is not None and not nested and _lent(node, child):  # type: ignore[arg-type]
                            passed.add(child.id)  # type: ignore[union-attr]
                        else:
                            shared.add(child.id)  # type: ignore[union-attr]
                elif isinstance(child, ast.AST):
                    todo.append((child, nested or kind in _NESTED))
    if lent is not None:
        lent |= passed - shared
    return shared


def shares(scope: ast.AST, name: str, lines: list[str]) -> bool:
    """Whether the local list `name` of `scope` (a function or the module) may be
    shared (`shared_names` of its body, `lent` apart), looked for only in the
    statements whose source `lines` may name it."""
    body = getattr(scope, "body", [])
    keep = Mentions.of(lines, (name,), scope)
    return name in shared_names(body, lent=set(), keep=keep)


def lends(func: ast.expr, names: list[ast.Name]) -> list[ast.Name]:
    """The names whose lists a call of `func` is handed (`g(xs)`; `names`: its
    positional arguments that are names, as the caller found them): from then on
    the callee may have kept or changed them. Calls that only read a list lend
    nothing. (`_lent` of each name argument, its tests made once.)"""
    if type(func) is ast.Name and func.id in READING_CALLS:
        return []
    return names


def _lent(parent: ast.AST, name: ast.Name) -> bool:
    if not isinstance(parent, ast.Call):
        return False
    func = parent.func
    reads = isinstance(func, ast.Name) and func.id in READING_CALLS
    return not reads and name in parent.args


def _change(parent: ast.AST) -> bool:
    """Whether a name used under `parent` has its list changed in place."""
    kind = type(parent)
    if kind is ast.Subscript:
        return type(parent.ctx) is not ast.Load  # type: ignore[attr-defined]
    return kind is ast.Attribute and parent.attr in MUTATORS  # type: ignore[attr-defined]


def _plain_use(parent: ast.AST, name: ast.Name) -> bool:
    kind = type(parent)
    if kind is ast.Subscript:
        return type(parent.ctx) is not ast.Del  # type: ignore[attr-defined]
    if kind is ast.Attribute:
        return parent.attr in MUTATORS or parent.attr in READERS  # type: ignore[attr-defined]
    if kind is ast.Call:
        func = parent.func  # type: ignore[attr-defined]
        return type(func) is ast.Name and func.id in READING_CALLS
    if kind is ast.IfExp:  # `a if xs else b` reads it; `xs if c else b` passes it on
        return parent.test is name  # type: ignore[attr-defined]
    if kind is ast.Assign:
        targets = parent.targets  # type: ignore[attr-defined]
        return all(type(t) in (ast.Tuple, ast.List) for t in targets)
    return kind in READING_PARENTS


READING_PARENTS = frozenset(
    {
        ast.Compare,
        ast.UnaryOp,
        ast.BinOp,
        ast.If,
        ast.While,
        ast.Assert,
        ast.For,
        ast.AsyncFor,
        ast.comprehension,
        ast.Starred,
        ast.FormattedValue,
        ast.Return,
        ast.Expr,
    }
)
