"""Which files cannot produce a finding: those are parsed (RF001/RF002, suppressions,
RF010) but not analysed (issue 13; mypy skips unannotated bodies for the same reason).

A finding needs something that carries a unit, a frame or a refinement, or a name
that can be unbound. `skippable` answers "nothing can" syntactically and
conservatively: every test below only ever sends a file to the analysis, so a file
it lets through is one the analysis would have reported nothing on. A unit, frame
or refinement enters a file only through

- an annotation of ours: the text has `Annotated`, `Unit(`, `Frame(` or `Tag(`
  (string annotations and comments included, so no alias spelling escapes it);
- a message, service or action class: an import with a part `msg`, `srv` or
  `action`, or a part the catalog knows as an interface package (the seed
  programs write `from std_msgs import Float64`);
- a library call or object the stubs describe: a name or attribute that is the
  name of a stub member able to give a unit or a refinement
  (`stubs.load.defined_names`), or that the API model keys on (registrations,
  time objects, node constructors, tf2 calls) - by name, since a method of an
  unknown receiver is looked up by its name alone; a name read only as the
  receiver of an attribute (`time` in `time.sleep`) counts through the attribute;
- a parameter: `_param` or `ParamListener` anywhere in the text (every
  declaration and read `analysis/parameters.py` follows). The calls are names of
  the vocabulary too, but the word is the cheaper exit: without it, 38 more of
  corpus25's 1,391 files were skipped and the run cost 0.6% more instructions;
- another module of the tree: a plain `import` of a module of the tree, or a name
  `from` one that is itself a module, a re-export, an alias, or a member whose
  summary carries something (`carries`: a refinement, a type, a unit, a frame, a
  message, an instance, a list); a module of the tree whose summary is unknown (a
  fault of ours) counts too. A plain member (a function with nothing refined or
  typed, a class with nothing of these, a plain constant) gives the analysis
  only what an unknown name would: its tests can prune paths, which only ever
  removes findings. This is asked after the cheaper tests: it may build
  summaries (which the file's analysis would build too);
- a declaration without a value (`x: float` in a body), whose read is RF301.

RF301 needs no annotation, so `unbound.may_be_unbound` runs a plain
definite-assignment pass over every scope, more pessimistic than the analysis:
a read that may be unbound there sends the file to the analysis.

RF902 (the work budget) is a warning about the analysis, not a finding; files
large enough to come near it (over a 16th of the budget in bytes, 125 kB) are
analysed as before. A smaller file can spend it too (one-line helpers inlined
into each other, 30 calls deep four times); skipped, it has nothing to find, so
only the warning is not given.

`tests/test_relevance.py` checks the claim on every case file and on generated
programs: a file this module skips gets no diagnostic from the full analysis.
"""

from __future__ import annotations

import ast
import functools
import os
import re
import unicodedata
import weakref
from collections.abc import Iterable
from typing import Any

from robotfix import budget
from robotfix.analysis.constants import SCALARS
from robotfix.analysis.imported import (
    ClassSummary,
    FunctionSummary,
    Resolver,
    absolute,
)
from robotfix.analysis.unbound import COMPOUND, may_be_unbound
from robotfix.analysis.values import Value
from robotfix.astwalk import FIELDS, fields
from robotfix.ros import api_model, frames_model
from robotfix.ros.catalog import MsgCatalog
from robotfix.stubs.load import StubSet, defined_names

# declare_parameter(s), get_param(eter), has_parameter, ParamListener (g_p_l)...
PARAMETER_WORDS = ("_param", "paramlistener")
MARKERS = ("Annotated", "Unit(", "Frame(", "Tag(")
INTERFACE_PARTS = frozenset({"msg", "srv", "action"})
BYTES_PER_STEP_BUDGET = 16  # a file over FILE_STEPS / 16 bytes is analysed: RF902

ENABLED = os.environ.get("ROBOTFIX_NO_SKIP", "") == ""  # off: analyse every file


def skippable(
    tree: ast.Module,
    text: str,
    catalog: MsgCatalog,
    stubs: StubSet,
    resolver: Resolver | None,
) -> bool:
    """Can the analysis of this file report nothing? (True only when sure.)"""
    if not text.isascii():  # Python reads identifiers NFKC-normalised, so do we
        text = unicodedata.normalize("NFKC", text)
    if (
        not ENABLED
        or len(text) * BYTES_PER_STEP_BUDGET > budget.FILE_STEPS
        or any(marker in text for marker in MARKERS)
    ):
        return False
    lowered = text.lower()
    if any(word in lowered for word in PARAMETER_WORDS):
        return False
    # the exits in the order they fire on real code (corpus2): parameters, imports
    # of the tree, a stub name; every statement first (cheap), every name only
    # when the text has a stub word at all
    imported: list[tuple[int, str | None, tuple[str, ...]]] = []
    declared: set[str] = set()  # names some function declares `global`
    for node in _statements(tree.body):
        kind = type(node)
        if kind is ast.Import:
            for alias in node.names:  # type: ignore[attr-defined]
                if _interface(alias.name, catalog):
                    return False
                imported.append((0, alias.name, ()))
        elif kind is ast.ImportFrom:
            assert isinstance(node, ast.ImportFrom)
            if node.module and _interface(node.module, catalog):
                return False
            if node.level and resolver is not None:  # `from . import Cmd`
                base = absolute(resolver.package, node.level, node.module)
                if base and _interface(base, catalog):
                    return False
            names = tuple(a.name for a in node.names)
            if any(n in INTERFACE_PARTS for n in names):
                return False
            imported.append((node.level, node.module, names))
        elif kind is ast.AnnAssign and node.value is None:  # type: ignore[attr-defined]
            return False
        elif kind is ast.Global:
            declared.update(node.names)  # type: ignore[attr-defined]
    vocabulary = _vocabulary(stubs)
    # a stub member imported under another name (`from math import degrees as d`)
    if any(n in vocabulary for _, _, names in imported for n in names):
        return False
    # no stub word anywhere in the text: no name or attribute can be one
    if _written(text, vocabulary) and _names_one(tree, vocabulary):
        return False
    # before the definite-assignment pass: what it builds, the file's analysis
    # would build too (the summaries of the modules it imports)
    if resolver is not None and _tree_relevant(resolver, imported):
        return False
    return not may_be_unbound(tree, frozenset(declared), ":=" in text)


def _names_one(tree: ast.Module, vocabulary: frozenset[str]) -> bool:
    """Is a name or attribute of the tree a stub word? A name read only as the
    receiver of an attribute (`time` in `time.sleep`) counts through the
    attribute. Names, constants and attribute chains are read under their
    parent, never stacked."""
    todo: list[ast.AST] = [tree]
    pop, append = todo.pop, todo.append
    name_class, attribute_class, constant_class = ast.Name, ast.Attribute, ast.Constant
    node_class, known = ast.AST, FIELDS
    child: Any
    while todo:
        node = pop()
        kind = type(node)
        for name in known.get(kind) or fields(kind):
            value = getattr(node, name, None)
            for child in value if type(value) is list else (value,):
                part = type(child)
                if part is attribute_class:
                    while part is attribute_class:
                        if child.attr in vocabulary:
                            return True
                        child = child.value
                        part = type(child)
                    if part is name_class:
                        continue  # a receiver
                if part is name_class:
                    if child.id in vocabulary:
                        return True
                elif part is not constant_class and isinstance(child, node_class):
                    append(child)
    return False


def _written(text: str, vocabulary: frozenset[str]) -> bool:
    """Is a stub word written in the text as a whole word (`\\bword\\b`: a run of
    word characters that is nothing more)? An ASCII text is cut into its runs in C
    (its other characters made spaces, then `split`), a set's test each: a third of
    the pattern's instructions (which try the words at every letter), a quarter on
    a text that holds none, as most that get here do."""
    words = _ascii_words(vocabulary)
    if words is None or not text.isascii():
        return _pattern(vocabulary).search(text) is not None
    return not words.isdisjoint(text.encode("ascii").translate(_SPACED).split())


# each ASCII byte but a word character (`[A-Za-z0-9_]`, all `\w` is in ASCII) -> a space
_SPACED = bytes(
    c if c >= 128 or chr(c).isalnum() or c == ord("_") else ord(" ") for c in range(256)
)


@functools.lru_cache(maxsize=8)
def _ascii_words(vocabulary: frozenset[str]) -> frozenset[bytes] | None:
    """The words as bytes, when each is ASCII word characters only (the runs of
    an ASCII text that `split` gives); None else."""
    if not all(re.fullmatch(r"\w+", word, re.ASCII) for word in vocabulary):
        return None
    return frozenset(word.encode("ascii") for word in vocabulary)


@functools.lru_cache(maxsize=8)
def _pattern(vocabulary: frozenset[str]) -> re.Pattern[str]:
    """A stub word, whole: its alternatives a trie (`Time(?:Msg|r)?`), which `re`
    searches at about twice the speed of the 84 words side by side."""
    return re.compile(r"\b(?:" + _trie(sorted(vocabulary)) + r")\b")


def _trie(words: list[str]) -> str:
    """A pattern of exactly `words` (sorted), their common prefixes shared."""
    if len(words) == 1:
        return re.escape(words[0])
    rests: dict[str, list[str]] = {}
    for word in words:
        rests.setdefault(word[:1], []).append(word[1:])
    ends = "" in rests  # a word ends here, a longer one goes on
    branches = [re.escape(c) + _trie(after) for c, after in rests.items() if c]
    if not branches:
        return ""
    if len(branches) == 1 and not ends:
        return branches[0]
    return "(?:" + "|".join(branches) + (")?" if ends else ")")


def _statements(body: list[ast.stmt]) -> Iterable[ast.stmt]:
    """Every statement, nested ones too (those in `match` cases included)."""
    todo = list(reversed(body))
    while todo:
        stmt = todo.pop()
        yield stmt
        if type(stmt) not in COMPOUND:  # most statements hold none
            continue
        for field in ("body", "orelse", "finalbody"):
            todo.extend(reversed(getattr(stmt, field, ())))
        for handler in getattr(stmt, "handlers", ()):
            todo.extend(reversed(handler.body))
        for case in getattr(stmt, "cases", ()):
            todo.extend(reversed(case.body))


def _interface(dotted: str, catalog: MsgCatalog) -> bool:
    """`x.msg`, `x.srv.y`, or a top-level package the catalog has interfaces of."""
    parts = dotted.split(".")
    return any(p in INTERFACE_PARTS for p in parts) or _has_package(catalog, parts[0])


_PACKAGES: weakref.WeakKeyDictionary[MsgCatalog, dict[str, bool]] = (
    weakref.WeakKeyDictionary()
)


def _has_package(catalog: MsgCatalog, part: str) -> bool:
    known = _PACKAGES.setdefault(catalog, {})
    if part not in known:
        known[part] = catalog.has_package(part)
    return known[part]


@functools.lru_cache(maxsize=8)
def _vocabulary(stubs: StubSet) -> frozenset[str]:
    return (
        defined_names(stubs)
        | set(api_model.REGISTRATIONS)
        | api_model.TIME_OBJECTS
        | api_model.NODE_CONSTRUCTORS
        | api_model.PARAMETER_CALLS
        | set(frames_model.TF2_CALLS)
    )


def _tree_relevant(
    resolver: Resolver, imported: list[tuple[int, str | None, tuple[str, ...]]]
) -> bool:
    """Does an import give the file something from a module of the tree? A module
    (all of it reachable through its name), or a member that `carries` something."""
    exists = getattr(resolver, "exists", None)
    for level, module, names in imported:
        base = module if level == 0 else absolute(resolver.package, level, module)
        if base is None:
            continue
        parts = base.split(".")
        prefixes = [".".join(parts[:i]) for i in range(1, len(parts) + 1)]
        if not names:  # `import a.b`: `a.c.f()` reaches any module under `a`
            if any(_in_tree(resolver, exists, p) for p in prefixes):
                return True
            continue
        if not _in_tree(resolver, exists, base):
            # `from a.b import x` where `a` is of the tree, `a.b` not: not followed
            if any(_in_tree(resolver, exists, p) for p in prefixes[:-1]):
                return True
            continue
        summary = resolver.module(base)
        if summary is None or "*" in names:
            return True
        for name in names:
            if _in_tree(resolver, exists, f"{base}.{name}"):
                return True  # a module: its submodules are reached through it
            resolver.member(base, summary, name)
            if name in summary.reexports or name in summary.aliases:
                return True
            member = (
                summary.functions.get(name)
                or summary.classes.get(name)
                or summary.constants.get(name)
            )
            if carries(member):
                return True
    return False


def _in_tree(resolver: Resolver, exists: object, name: str) -> bool:
    if callable(exists):
        return bool(exists(name))
    return resolver.module(name) is not None


PLAIN_KINDS = SCALARS | {"none", "unknown"}  # what a plain constant holds


def carries(member: object, depth: int = 0) -> bool:
    """Can what a summary says of an imported member give an importer something to
    find with: a refinement, a type, a unit, a frame, or a value that is not a
    plain number, string or flag (a member the summary does not know: nothing,
    the importer knows no more of it than of an unknown name)."""
    if member is None:
        return False
    if depth > 3:
        return True
    if isinstance(member, FunctionSummary):
        return (
            bool(member.decls)
            or member.returns is not None
            or member.result is not None
        )
    if isinstance(member, ClassSummary):
        return (
            bool(member.attributes or member.types)
            or any(carries(m, depth + 1) for _, m in member.methods)
            or any(carries(v, depth + 1) for _, v in member.constants)
        )
    if isinstance(member, Value):  # a number, string or flag, and nothing else
        plain = Value(member.kind, member.term, literal=member.literal)
        return not (
            member.kind in PLAIN_KINDS
            and member == plain
            and member.conversion is None
            and member.choices is None
        )
    return True  # anything newer
