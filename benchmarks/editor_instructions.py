"""Per-edit work of the editor's check, to be counted by callgrind (deterministic on a
busy machine, where `editor.py`'s CPU times move): checks WARMUP + EDITS versions of
one real node in one process, each one edit of `editor.py`'s kind, with the
document's memo (`memo`) or without (`plain`), and the settings, catalog and
module summaries the server keeps; prints the memo's hits.

Usage (the difference of two runs is what the memo costs or saves):
    valgrind --tool=callgrind --callgrind-out-file=cg.out \\
        python benchmarks/editor_instructions.py NODE.py edited_real_blanked memo 10
    callgrind_annotate cg.out | grep "PROGRAM TOTALS"
"""

from __future__ import annotations

import sys
from pathlib import Path

import editor

from robotfix import api
from robotfix.smt.memo import ProofMemo

MADE = 10  # edits made by every run (at least the EDITS checked)


def main(path: Path, kind: str, mode: str, edits: int) -> None:
    assert edits <= MADE, f"at most {MADE} edits"
    text = path.read_text()
    as_server = editor._server_inputs(path)
    make = getattr(editor, kind)
    # every run makes the same texts (making one, `ast.walk` of the node for the
    # number edits, costs about 100 M instructions on nav2's file), so that the
    # difference of two runs is the checks' alone
    sources = [make(text, n) for n in range(editor.WARMUP + MADE)]
    sources = sources[: editor.WARMUP + edits]
    memo = ProofMemo() if mode == "memo" else None
    for source in sources:
        api.check_source(source, str(path), *as_server(path), memo=memo)  # type: ignore[arg-type]
    print(getattr(getattr(memo, "units", None), "hits", 0))


if __name__ == "__main__":
    main(Path(sys.argv[1]), sys.argv[2], sys.argv[3], int(sys.argv[4]))
