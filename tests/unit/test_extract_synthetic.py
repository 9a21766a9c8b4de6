"""Nodes parsed from a string annotation are told apart by id (their text is the
string's, not a slice of the file); the reader must keep them alive, or a node
allocated later (another module's tree, read through an alias) could take a freed
node's id and lose its own source text and column."""

from __future__ import annotations

import ast
import gc
import weakref

from robotfix.annotations.extract import _Reader


def test_parsed_string_nodes_outlive_their_use() -> None:
    reader = _Reader("speed", lambda name: True)
    written = ast.parse("x: 'Optional[Annotated[float, \"Unit(m)\"]]'").body[0]
    assert isinstance(written, ast.AnnAssign)
    assert isinstance(written.annotation, ast.Constant)
    parsed = reader.parse_string(written.annotation, written.annotation.value)
    assert parsed is not None
    kept = weakref.ref(parsed)
    inner = weakref.ref(parsed.slice)  # type: ignore[attr-defined]
    del parsed  # `form` keeps only the inner node of `Optional[...]`
    gc.collect()
    assert kept() is not None and inner() is not None
    assert id(kept()) in reader.synthetic
