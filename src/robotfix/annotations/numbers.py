"""Named numbers that code and annotations may use: `math.pi`, `math.tau`, `math.e`,
`math.inf` and numpy's, as exact fractions; `errno`'s codes, as integers.

`pi` is the double Python computes with (3.141592653589793...), not the real number:
that is the value a program compares against, and what `math.atan2` stays within.
Infinity is a number above every double (10**400): the solver's reals have none, and
every finite float is below it.
"""

from __future__ import annotations

import errno
import math
import sys
from fractions import Fraction

INFINITY = Fraction(10) ** 400
LARGEST_FLOAT = Fraction(sys.float_info.max)  # beyond it, a double is inf
NUMBERS = {
    "pi": Fraction(math.pi),
    "tau": Fraction(math.tau),
    "e": Fraction(math.e),
    "inf": INFINITY,
}
# Modules whose attributes of those names are those numbers (`np.pi`, `numpy.inf`).
MODULES = frozenset({"math", "numpy"})


def shown_as_infinity(value: Fraction) -> str | None:
    """ "inf" or "-inf" for a number no double reaches (what the program holds)."""
    if abs(value) > LARGEST_FLOAT:
        return "inf" if value > 0 else "-inf"
    return None


def named_number(qualified: str) -> Fraction | None:
    """`math.pi` -> its value; None for any other name."""
    module, _, name = qualified.rpartition(".")
    return NUMBERS.get(name) if module in MODULES else None


def named_code(qualified: str) -> int | None:
    """`errno.ECONNREFUSED` -> the code this Python's `errno` gives it (what a
    program running on this kind of system compares against; on every system a
    positive integer); None for any other name. A retry loop's `code =
    -errno.ECONNREFUSED` is then known to be negative where the code tests it."""
    module, _, name = qualified.rpartition(".")
    if module != "errno" or not name.startswith("E"):
        return None
    value = getattr(errno, name, None)
    return value if type(value) is int else None
