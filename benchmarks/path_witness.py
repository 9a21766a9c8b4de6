"""Path questions and checks answered without z3, checked against z3 alone (issue
13 item 7; checks: issue 25).

    python benchmarks/path_witness.py /work/corpus2

Checks the tree in this process (`-j 1`, no cache), keeps every question a path
asks ("can this condition hold here?") and every check ("does the goal hold?"), and
asks z3 each one the run answered without it. A question's answer must be z3's
(possible or not); a check's verdict must be z3's, counterexample and all. Prints
how many were answered each way, any verdict z3 disagrees with (there should be
none), and how many files started a z3 session.
"""

from __future__ import annotations

import sys
from pathlib import Path

from robotfix import api
from robotfix.config import Config
from robotfix.run import check_paths
from robotfix.smt import solver
from robotfix.vc import VC, Proved, Undecided, Verdict


def main(roots: list[str]) -> int:
    asked: list[tuple[VC, Verdict, bool]] = []
    sessions = 0
    decide, start = api.Discharger._decide, solver.Session.__init__

    def deciding(self: api.Discharger, vc: VC) -> Verdict:
        self._asked = False
        verdict = decide(self, vc)
        asked.append((vc, verdict, self._asked))
        return verdict

    def starting(self: solver.Session, *args: object, **kwargs: object) -> None:
        nonlocal sessions
        sessions += 1
        start(self, *args, **kwargs)  # type: ignore[arg-type]

    api.Discharger._decide = deciding  # type: ignore[method-assign]
    solver.Session.__init__ = starting  # type: ignore[method-assign]
    result = check_paths([Path(r) for r in roots], Config(), None, 1, False)
    api.Discharger._decide, solver.Session.__init__ = decide, start  # type: ignore[method-assign]
    disagree = 0
    for question, kind in ((True, "path questions"), (False, "checks")):
        of_kind = [(vc, v, by_z3) for vc, v, by_z3 in asked if vc.question == question]
        here = [(vc, verdict) for vc, verdict, by_z3 in of_kind if not by_z3]
        for vc, verdict in here:
            alone = solver.check(vc)
            if isinstance(alone, Undecided):
                continue
            if question:
                same = isinstance(alone, Proved) == isinstance(verdict, Proved)
            else:
                same = (
                    isinstance(verdict, Proved)
                    if isinstance(alone, Proved)
                    else (verdict == alone)
                )
            if not same:
                disagree += 1
                print("DISAGREE", verdict, alone, vc)
        possible = sum(1 for _, v in here if not isinstance(v, Proved))
        print(
            f"{result.files} files, {len(of_kind)} {kind}: "
            f"{len(here)} answered without z3 ({possible} possible or failing, "
            f"{len(here) - possible} proved), {len(of_kind) - len(here)} by z3"
        )
    print(f"z3 sessions started: {sessions}; z3 disagrees with {disagree}")
    return 1 if disagree else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:] or ["tests/cases"]))
