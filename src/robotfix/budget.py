"""One file's work budget, counted in steps: every stage of its check spends from it.

Imports nothing of ours, so every layer may count its work here: the interpreter (a
step per statement and expression), reading refinements (a step per character of
the annotation), the solver callback (a step per VC read, and one more for every
`FACTS_PER_STEP` facts it carries), the pre-pass and the propositional search (a
step per node they visit), the witness search (a step per node it evaluates) and z3
(`ENCODE_STEPS` per term built for it, and a step per `Z3_UNITS_PER_STEP` units of
its rlimit count). Work, not time: the same file stops at the same point on any
machine and in any process (`-j 1` or `-j 2`).

A file that spends it stops there: in a solver question, RF901 at that check; in the
interpreter, RF902 at that statement. What was found before is kept, and the run goes
on with the next file.
"""

from __future__ import annotations

# What one file may spend: a generated 10,000-line annotated module takes 0.24M, the
# largest case of tests/cases 47,500, the largest file of a 532-file ROS corpus 2,600
# (docs/performance.md); about 15 s of the slowest work measured.
FILE_STEPS = 2_000_000
# z3 counts its own work (its rlimit); one question may use RLIMIT units of it, and
# each Z3_UNITS_PER_STEP units are one step of the file's budget.
RLIMIT = 2_000_000
Z3_UNITS_PER_STEP = 10
# z3's Python API takes about as long to build one term (a node of a VC encoded) as
# the interpreter takes for this many steps; a shared term is built once a session.
ENCODE_STEPS = 8
FACTS_PER_STEP = 1_024  # a VC's facts are read (copied, compared) in C: cheap per fact
# Before any work, memory: Python's parser takes about 100 bytes per character of
# source (1.3 GB for a 12.7 MB file), so a text with more code than this (comment
# lines not counted) is not parsed (RF902). The largest hand-written modules are
# under 1 MB.
MAX_PARSED_CHARS = 4_000_000


class Budget:
    """The steps one file's check has spent of its `limit`."""

    __slots__ = ("limit", "used")

    def __init__(self, limit: int | None = None) -> None:
        self.limit = FILE_STEPS if limit is None else limit
        self.used = 0

    def spend(self, steps: int) -> bool:
        """Count `steps` as spent; False when that took the file past its limit."""
        self.used += steps
        return self.used <= self.limit

    def affords(self, steps: int) -> bool:
        return self.used + steps <= self.limit

    @property
    def spent(self) -> bool:
        """Nothing is left: the next question is not asked."""
        return self.used >= self.limit

    @property
    def left(self) -> int:
        return max(0, self.limit - self.used)
