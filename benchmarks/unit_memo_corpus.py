"""The per-unit analysis memo (analysis/unitmemo.py) against fresh checks on real
code: for each Python file under a folder, EDITS random edits of one unit each
(tests/test_unit_memo.py's `edit`), each checked with the document's memo and
fresh; prints the number of edits compared, the mismatches (must be 0) and the
memo's hits and misses.

Usage: python benchmarks/unit_memo_corpus.py FOLDER [EDITS] [MODE]
MODE: literal, blanked, comment or method (else every kind of edit).
With `literal`, every edit changes a number inside a function (the edits that leave
the other units' keys alone, so most of them are replayed); with `blanked`, a number
the skeleton blanks (`same_skeleton`), after the text was checked twice (so its
items are recorded), in files with a class: the edits after which the memo replays
a method around the edited one; with `comment`, a chain of edits each of one line
that holds a comment or blanks only (a comment written there, some with a word the
analysis reads in the text), after the text was checked twice, in files with a
class: the edits after which the memo counts the skeleton unchanged
(`comment_only`); with `method`, a chain of edits of one number the skeleton
keeps (in a call, a test, a store to an attribute) inside a method whose text
holds no word the analysis reads (`method_number`), made other numbers of the
same length and then longer ones, after the text was checked twice, in files
with a class: the edits after which the memo keys the items by the skeleton
with that number blanked, and replays the other methods.
"""

from __future__ import annotations

import ast
import json
import random
import re
import sys
import zlib
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent.parent / "tests"))
from test_unit_memo import KINDS, _number_edits, _parses, _replace, edit

from robotfix.analysis.skeleton import method_number, same_skeleton
from robotfix.api import check_source
from robotfix.config import Config
from robotfix.ros.catalog import MsgCatalog
from robotfix.smt.memo import ProofMemo


def main(folder: Path, edits: int, kinds: tuple[str, ...]) -> None:
    catalog = MsgCatalog([])
    config = Config()
    compared = mismatches = files = hits = misses = 0
    for path in sorted(folder.rglob("*.py")):
        try:
            text = path.read_text(encoding="utf-8")
            if not _parses(text):
                continue
        except (OSError, UnicodeDecodeError, ValueError):
            continue
        files += 1
        rng = random.Random(zlib.crc32(str(path).encode()))
        memo = ProofMemo(max_entries=0)  # the units alone (see the test)
        check_source(text, str(path), config, catalog, memo=memo)
        done = 0
        chosen = None
        if kinds == ("blanked",):
            chosen = _blanked(text, rng, edits)
        elif kinds == ("comment",):
            chosen = _commented(text, rng, edits)[::-1]  # popped in their order
        elif kinds == ("method",):
            chosen = _method_number(text, rng, edits)[::-1]
        if chosen is not None:  # recorded: a skeleton is, once checked twice
            check_source(text, str(path), config, catalog, memo=memo)
        for _ in range(edits * 3):
            if done >= edits or chosen == []:
                break
            try:
                new = chosen.pop() if chosen else edit(text, rng, kinds)
            except (SyntaxError, ValueError, UnicodeError, IndexError):
                continue
            if new is None or new == text or not _parses(new):
                continue
            kept = repr(check_source(new, str(path), config, catalog, memo=memo))
            fresh = repr(check_source(new, str(path), config, catalog))
            done += 1
            if kept != fresh:
                mismatches += 1
                print(f"MISMATCH {path}", flush=True)
        compared += done
        units = memo.units  # None: no check analysed the file (skipped)
        hits += getattr(units, "hits", 0)
        misses += getattr(units, "misses", 0)
    print(
        json.dumps(
            {
                "files": files,
                "edits_compared": compared,
                "mismatches": mismatches,
                "unit_hits": hits,
                "unit_misses": misses,
            }
        )
    )


def _blanked(text: str, rng: random.Random, edits: int) -> list[str]:
    """Up to `edits` edits of a number the skeleton blanks (none in a file without
    a class)."""
    if "class " not in text:
        return []
    found = [e for e in _number_edits(text) if same_skeleton(ast.parse(e), text, e)]
    return rng.sample(found, min(edits, len(found)))


def _method_number(text: str, rng: random.Random, edits: int) -> list[str]:
    """A chain of up to `edits` texts, each `text` with the same number, one the
    skeleton keeps inside a method (`method_number`), made another value (of
    another length at times; none in a file without a class)."""
    if "class " not in text:
        return []
    lines = text.splitlines(keepends=True)
    places = set()
    for edited in _number_edits(text):
        found = method_number(ast.parse(edited), text, edited)
        if found is not None:
            places.add(found[:2])
    numbers = [
        n
        for n in ast.walk(ast.parse(text))
        if isinstance(n, ast.Constant) and (n.lineno, n.col_offset) in places
    ]
    if not numbers:
        return []
    node = rng.choice(numbers)
    chain = []
    for step in range(edits):
        new = _replace(lines, node, repr(_bumped(node.value, step)))
        if new is not None:
            chain.append(new)
    return chain


def _bumped(value: float, step: int) -> float:
    return value + (step + 1) * (0.125 if type(value) is float else 1)


NOTES = ("note", "TODO 2", "x = 1", "the node", "Annotated", "setattr", ":=", "")


def _commented(text: str, rng: random.Random, edits: int) -> list[str]:
    """A chain of up to `edits` texts, each the one before with one line that held
    a comment or blanks only made another comment (none without a class)."""
    lines = text.splitlines(keepends=True)
    spots = [i for i, line in enumerate(lines) if line.strip()[:1] in ("", "#")]
    if "class " not in text or not spots:
        return []
    chain = []
    for _ in range(edits):
        at = rng.choice(spots)
        indent = re.match(r"[ \t]*", lines[at]).group(0)  # type: ignore[union-attr]
        end = lines[at][len(lines[at].rstrip("\r\n")) :] or "\n"
        lines[at] = f"{indent}# {rng.choice(NOTES)} {rng.randrange(100)}{end}"
        chain.append("".join(lines))
    return chain


if __name__ == "__main__":
    main(
        Path(sys.argv[1]),
        int(sys.argv[2]) if len(sys.argv) > 2 else 3,
        tuple(sys.argv[3:4])
        if sys.argv[3:4] in (["literal"], ["blanked"], ["comment"], ["method"])
        else KINDS,
    )
