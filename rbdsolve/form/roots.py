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


def over_one_root(expr: sp.Expr) -> sp.Expr:
    """A sum holding one square root √X of a sum (its powers X^(k/2) alike) over one
    denominator, as an exam writes a slider's velocity with ℓ = √(l² − (r sin θ − e)²):
    −r θ̇ (ℓ sin θ + (r sin θ − e) cos θ)/ℓ, not three terms over ℓ, and its acceleration
    over ℓ³, not over ℓ (e² − 2 e r sin θ − l² + r² sin² θ). √X stands in as s and X as
    Y while the terms are put over one denominator (sympy's together); then each power
    of s and each factor X of a coefficient are gathered, s² = Y (``_gathered``). An
    expression with no such root, or two, is returned as it is."""
    bases = {w.base for w in expr.atoms(sp.Pow) if square_root(w) and w.base.is_Add}
    if len(bases) != 1:
        return expr
    (X,) = bases
    s, Y = sp.Dummy("s", positive=True), sp.Dummy("Y", positive=True)
    swapped = expr.replace(lambda w: square_root(w) and w.base == X, lambda w: s ** (2 * w.exp))
    if swapped.has(X):
        return expr  # X also stands outside the root: left as it is
    top, bottom = sp.fraction(sp.together(swapped))
    gathered = _gathered(top, X, s, Y) / _gathered(bottom, X, s, Y)
    return gathered.xreplace({Y: X, s: sp.sqrt(X)})  # rebuilt at once: X·√X is X^(3/2)


def _gathered(p: sp.Expr, X: sp.Expr, s: sp.Dummy, Y: sp.Dummy) -> sp.Expr:
    """p, a polynomial in s, as Σ cₖ Y^(k//2) s^(k%2), each coefficient's factors X
    (exact division by X written out) moved into the powers of s."""
    plain = sp.expand(X)
    out = sp.Integer(0)
    for (k,), c in sp.Poly(sp.expand(p), s).terms():
        while True:
            quotient, remainder = sp.div(c, plain)
            if remainder != 0 or quotient == 0:
                break
            c, k = quotient, k + 2
        out += sp.factor_terms(c) * Y ** (k // 2) * s ** (k % 2)
    return sp.factor_terms(out)
