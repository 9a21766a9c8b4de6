"""A fault of ours while one file of a run's parameter or launch stage is read or
checked: kept as that file's internal error, the other files checked. Stdlib only,
so that reading launch files for a cached run's key imports no analysis."""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path

from robotfix.diagnostics import Diagnostic


@dataclass(frozen=True)
class Fault:
    """A fault of ours while a file was read or checked (`run` reports it as
    an internal error of that file)."""

    path: str
    summary: str  # one line: the exception
    detail: str  # the traceback


@contextmanager
def guard(
    path: str | Path, out: list[Diagnostic], faults: list[Fault] | None
) -> Iterator[None]:
    """A fault of ours while one file is read or checked: that file's diagnostics
    so far are dropped, the fault is kept for the run to report (`faults`; raised
    when there is no list) and the other files are checked."""
    before = len(out)
    try:
        yield
    except Exception as err:
        if faults is None:
            raise
        import traceback  # only here: 2 ms of every start otherwise

        del out[before:]
        summary = f"{type(err).__name__}: {err}"
        faults.append(Fault(str(path), summary, traceback.format_exc()))
