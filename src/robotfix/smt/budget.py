"""The solver's work budgets, apart from z3: the `Discharger` counts the work of
kept verdicts (`smt.memo`) against them before z3 is imported."""

# Work budgets, not wall-clock time: the same input stops at the same point on any
# machine. Linear problems of a node take a few thousand units. RLIMIT bounds one
# question, FILE_RLIMIT all the questions of one file (a few seconds of z3 at most).
RLIMIT = 2_000_000
FILE_RLIMIT = 20_000_000
