"""Exact roots of one equation f(q) = 0 that mixes q with sin and cos of it (θ = k sin θ),
where a bound proves them.

f is strictly monotone on the whole line when f′ keeps one sign: written as
f′ = A + Σ cᵢ tᵢ(q), A and cᵢ free of q and each tᵢ a product of sines and cosines
(|tᵢ| ≤ 1), f′ ≥ A − Σ |cᵢ| > 0 (or f′ ≤ A + Σ |cᵢ| < 0). A strictly monotone f has at
most one root, so a simple value where f vanishes exactly (0, ±π/2, ±π) is the only one:
θ − k sin θ with |k| < 1 has only θ = 0, since its derivative is 1 − k cos θ ≥ 1 − |k| > 0.
The signs are decided as the rest of the exact route decides them (the parameters'
signs, else their values or assumptions: ``Model.decided_by``).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Mapping

import sympy as sp

from rbdsolve.form.tidy import tidy
from rbdsolve.solvers.conditions.signs import Undecided, sign_of

CANDIDATES = (sp.Integer(0), sp.pi / 2, -sp.pi / 2, sp.pi, -sp.pi)


@dataclass(frozen=True)
class MonotoneRoot:
    root: sp.Expr
    derivative: sp.Expr  # f′
    bound: sp.Expr  # A − Σ|cᵢ| (or A + Σ|cᵢ|), with the signs of the cᵢ put in
    increasing: bool


def monotone_root(f: sp.Expr, q: sp.Symbol, decided_by: Mapping) -> MonotoneRoot | None:
    """The only root of f on the whole line when f is proved strictly monotone and it
    is one of CANDIDATES; None when that is not proved (the caller refuses as before)."""
    derivative = tidy(sp.diff(f, q))
    split = _split(sp.expand(derivative), q)
    if split is None:
        return None
    constant, coefficients = split
    signs = [sign_of(c, decided_by) for c in coefficients]
    if any(isinstance(s, Undecided) for s in signs):
        return None
    spread = sp.Add(*[s * c for s, c in zip(signs, coefficients)])  # Σ |cᵢ|
    for increasing, bound in ((True, tidy(constant - spread)), (False, tidy(constant + spread))):
        if sign_of(bound, decided_by) == (1 if increasing else -1):
            root = next((c for c in CANDIDATES if tidy(sp.expand_trig(f.xreplace({q: c}))) == 0), None)
            return None if root is None else MonotoneRoot(root, derivative, bound, increasing)
    return None


def _split(derivative: sp.Expr, q: sp.Symbol) -> tuple[sp.Expr, list[sp.Expr]] | None:
    """f′ = A + Σ cᵢ tᵢ(q) with |tᵢ| ≤ 1; None if a term holds q otherwise (bare, or in a
    function other than sin and cos)."""
    constant, coefficients = sp.Integer(0), []
    for term in sp.Add.make_args(derivative):
        if not term.has(q):
            constant += term
            continue
        coefficient, part = term.as_independent(q, as_Add=False)
        if not all(isinstance(b, (sp.sin, sp.cos)) and (e.is_Integer and e > 0)
                   for b, e in (factor.as_base_exp() for factor in sp.Mul.make_args(part))):
            return None
        coefficients.append(coefficient)
    return constant, coefficients
