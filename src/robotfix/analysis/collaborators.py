"""What an expression evaluator works with besides the path's state: the checks
that report diagnostics, the lookups of names and types, the parameter calls and
the libraries' stubs, as one set per file."""

from __future__ import annotations

from robotfix.analysis.checks import Checker
from robotfix.analysis.context import FileContext
from robotfix.analysis.fieldchecks import FieldChecker
from robotfix.analysis.library import Libraries
from robotfix.analysis.lookups import Lookups
from robotfix.analysis.param_eval import ParameterCalls
from robotfix.analysis.program import Program
from robotfix.analysis.refined import RefinedChecker


class Collaborators:
    """What an evaluator works with besides the path's state. None keeps anything
    of one body (what they keep is the file's, in its context and program), so
    the evaluators of one file's bodies share one set (`analyze_module` makes it),
    not one per body run. Held by the evaluators only: kept by the context or the
    program, they would make a cycle that waits for the collector with the tree.
    (A plain class: a dataclass compiles its methods when the module is imported.)"""

    __slots__ = ("check", "fields", "libraries", "lookups", "params", "refined")

    def __init__(self, ctx: FileContext, program: Program) -> None:
        # the checks that report diagnostics: the scalar checks, those of
        # messages, and those of values that reach a refined target
        self.check = Checker(ctx)
        self.fields = FieldChecker(self.check)
        self.refined = RefinedChecker(self.check, self.fields)
        # what a type, attribute, constant or element read stands for
        self.lookups = Lookups(ctx, program, self.check)
        self.params = ParameterCalls(ctx)  # parameter calls and their handles
        # calls into libraries and objects of stub classes, as their stubs say
        self.libraries = Libraries(ctx, program, self.check, self.refined, self.lookups)
