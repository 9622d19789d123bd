"""Square roots of squares, as an exam writes them: √(h² + 2 h l + l²) = h + l.

A radicand that factors as F² gives |F| (sympy's own √(F²) = |F| for a real F), which
the assumptions turn into F or −F where they decide its sign (h, l > 0: h + l), and
which stays |l − h| where they do not. Where such radicands come from: a spring's
length √(h² + 2 h l cos θ + l²) put at θ = 0, a Hessian at a root found by squaring."""

from __future__ import annotations

from functools import lru_cache

import sympy as sp

from rbdsolve.form.tidy import square_root

RADICAND_OPS = 200  # a longer radicand is left as written: factoring it can take minutes


def roots_as_absolute(expr: sp.Expr) -> sp.Expr:
    """Each square root √X (X^(k/2) alike) with X a square F² once factored written |F|."""
    return expr.replace(lambda p: square_root(p) and bool(p.base.free_symbols) and sp.count_ops(p.base) <= RADICAND_OPS,
                        lambda p: absolute_root(p.base) ** (2 * p.exp))


@lru_cache(maxsize=1024)  # one radicand recurs in every entry of a Hessian, and in each residual
def absolute_root(base: sp.Expr) -> sp.Expr:
    """√X with X over one denominator and factored: |F| where X = F²."""
    return sp.sqrt(sp.factor(sp.cancel(sp.together(base))))
