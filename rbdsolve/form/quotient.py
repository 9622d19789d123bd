"""A value as one quotient P/Q: sympy's ``together``, then its numerator and denominator.

Remembered, because one value is split again and again: a condition's value once for
each parameter its sign is followed along and once for each test of its sign (a plate on
a spring of natural length, six parameters: the same K split six times, 0.1 s each).
"""

from __future__ import annotations

from functools import lru_cache

import sympy as sp


@lru_cache(maxsize=2048)
def quotient(value: sp.Expr) -> tuple[sp.Expr, sp.Expr]:
    """(P, Q) with value = P/Q over one denominator: ``sp.fraction(sp.together(value))``."""
    return sp.fraction(sp.together(value))
