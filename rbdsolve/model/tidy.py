"""Targeted, bounded simplification.

No blind global ``simplify``: each small coefficient of a quadratic form or of an
equation is tidied on its own (trigonometric identities such as
cos θ cos φ + sin θ sin φ = cos(φ − θ)), and anything larger than a size limit is left
expanded rather than risk a long simplification.
"""

from __future__ import annotations

import sympy as sp

MAX_OPS = 120  # larger coefficients are expanded but not trigsimp'ed


def tidy(expr: sp.Expr) -> sp.Expr:
    """A short form of one coefficient: expand, then trigonometric identities if small."""
    expr = sp.expand(expr)
    if expr.is_number or not expr.has(sp.sin, sp.cos, sp.tan):
        return sp.factor_terms(expr) if expr.count_ops() <= MAX_OPS else expr
    if expr.count_ops() > MAX_OPS:
        return expr
    short = sp.trigsimp(expr)
    return sp.factor_terms(short) if sp.count_ops(short) <= sp.count_ops(expr) else expr


def tidy_matrix(matrix: sp.Matrix) -> sp.Matrix:
    return matrix.applyfunc(tidy)


def collect_in(expr: sp.Expr, generators: list[sp.Expr]) -> dict[sp.Expr, sp.Expr]:
    """Split ``expr`` into monomials in ``generators`` (q̇, q̈) with tidied coefficients.

    Returns {monomial: coefficient}; the monomial 1 holds the part free of generators.
    """
    dummies = [sp.Dummy() for _ in generators]
    plain = sp.expand(expr.subs(dict(zip(generators, dummies))))
    poly = sp.Poly(plain, *dummies) if dummies else None
    if poly is None:
        return {sp.Integer(1): tidy(expr)}
    back = dict(zip(dummies, generators))
    out: dict[sp.Expr, sp.Expr] = {}
    for powers, coeff in poly.terms():
        monomial = sp.Mul(*[g**p for g, p in zip(generators, powers)])
        value = tidy(coeff.subs(back))
        if value != 0:
            out[monomial] = value
    return out
