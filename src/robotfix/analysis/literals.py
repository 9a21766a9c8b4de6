"""Terms and values of literals, made once per literal, not per occurrence.

An int literal needs a `Fraction`, a size check and a `Num`; a float literal its
exact value read from the source text (`Fraction` of a string is slow). Terms are
immutable, and what is kept by a term's identity (the encoder's and the pre-pass's
memos) answers alike for equal leaves, so a literal met again shares its term.
Values are never changed either (`values.replace` makes another), so a literal
met again shares its value too: a string's (the most frequent literal), an int's.
"""

from __future__ import annotations

import re
from fractions import Fraction
from functools import lru_cache

from robotfix.analysis import arith
from robotfix.analysis.values import Value
from robotfix.annotations import ast as A

_DECIMAL = re.compile(r"[0-9_]*\.?[0-9_]*([eE][+-]?[0-9_]+)?")


@lru_cache(maxsize=4096)
def int_term(value: int) -> A.Num | None:
    """The term of an int literal; None if too large to model."""
    exact = Fraction(value)
    return None if arith.too_large(exact) else A.Num(exact, True)


@lru_cache(maxsize=4096)
def int_value(value: int) -> Value | None:
    """The value of an int literal; None if too large to model."""
    term = int_term(value)
    return None if term is None else Value("int", term, literal=True)


@lru_cache(maxsize=128)
def str_value(text: str) -> Value:
    """The value of a string literal. (Strings repeat close together: on corpus25
    128 kept ones give 16,676 of the 20,842 hits 4,096 give, and hold about 50 kB,
    not 1.4 MB: the texts stay with them; peak memory must not grow.)"""
    return Value("str", A.Str(text))


@lru_cache(maxsize=4096)
def float_term(text: str, value: float) -> A.Num | None:
    """The term of a float literal written `text` (its source, "" if unknown) with
    the value `value`; None if too large to model. Keyed by the text: `0.1` and
    `0.1000000000000000000001` are one float and two numbers."""
    exact = _decimal(text)
    if exact is None:
        exact = Fraction(value)
    return None if arith.too_large(exact) else A.Num(exact, False)


def _decimal(text: str) -> Fraction | None:
    """Reals are exact: `3.141592653589793238` is read from the source text."""
    match = _DECIMAL.fullmatch(text) if text else None
    # the exponent bounded: Fraction("1e-999999999") computes 10**999999999
    if match and len(match.group(1) or "") < 6:
        try:
            return Fraction(text.replace("_", ""))
        except (ValueError, ZeroDivisionError):
            pass
    return None
