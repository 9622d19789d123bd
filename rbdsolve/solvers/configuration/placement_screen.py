"""Float64 screens for placement.py: the regular case without 30 digits or sympy.

placement.singularity decides the rank of J = ∂φ/∂q at 30 digits against a relative
tolerance (1e-20, or 1e-7 for a floating-point root); placement.same_placement decides
φ(a) = φ(b) by reducing the difference exactly. Nearly every point asked about is
regular, and nearly every pair of equilibria is two configurations; these screens say
so in float64 and say nothing else.

Both take one forward pass over φ's expression tree: each node carries its value, its
gradient in q, and sizes m, h that bound their rounding error (|error| ≤ K·u·m and
≤ K·u·hₖ, u the unit roundoff, K = 4 × the nodes walked: first-order error analysis,
each sum charged n × Σ of its terms' sizes so cancellation is paid for, sin and cos
charged their argument's absolute error; a coordinate's value its own rounding).

Rank: the Cholesky factorisation of JᵀJ − c·I, c = MARGIN²·‖J‖_F², must succeed; then
σ_min(J) > MARGIN·‖J‖_F ≥ MARGIN·σ_max(J). The rounding bound E = K·u·‖h‖_F must also
stay below MARGIN·‖J‖_F / 1000: by Weyl's inequality the exact J then has σ_min/σ_max
above ~MARGIN = 1e-4, a thousand times the largest tolerance, so its 30-digit rank is
full as well.

Placements: an entry of φ(a) − φ(b) larger than 1000 × its rounding bound is not zero
at these parameter values, so no identity makes the two placements equal.

Anything else (a node the pass does not know, a symbol without a number, a value that
is not finite or not real, a margin too small) answers False, and the exact or
30-digit path decides as it always did.
"""

from __future__ import annotations

import math
from typing import Mapping, Sequence

import sympy as sp

MARGIN = 1e-4
UNIT_ROUNDOFF = 2.0 ** -53
SAFETY = 1000  # how far beyond the first-order rounding bound a screen asks a number to be


class _Unscreened(Exception):
    """A node or value the float pass does not take."""


_FAILED = (_Unscreened, ArithmeticError, ValueError, TypeError)


def clearly_full_rank(entries: Sequence[sp.Expr], q: Sequence[sp.Symbol], at: Sequence[float],
                      values: Mapping[sp.Symbol, float]) -> bool:
    """Is ∂φ/∂q of φ = ``entries`` at q = ``at`` (the other symbols at ``values``) of
    full column rank by a float margin far beyond rounding error? False means: not
    shown here."""
    n = len(q)
    if n == 0 or len(entries) < n:
        return False
    try:
        rows, bound = _forward(entries, q, at, values, n)
    except _FAILED:
        return False
    J = [r[2] for r in rows]
    size = math.sqrt(sum(x * x for row in J for x in row))
    error = bound * math.sqrt(sum(x * x for r in rows for x in r[3]))
    if not (math.isfinite(size) and math.isfinite(error)) or size == 0 or error > MARGIN * size / SAFETY:
        return False
    return _positive_definite_above(_gram(J, n), (MARGIN * size) ** 2)


def clearly_different(entries: Sequence[sp.Expr], q: Sequence[sp.Symbol], a: Sequence[float],
                      b: Sequence[float], values: Mapping[sp.Symbol, float]) -> bool:
    """Does φ = ``entries`` differ between q = ``a`` and q = ``b`` (the other symbols at
    ``values``) in some entry by far more than rounding could make of equal values?
    False means: not shown here."""
    try:
        (left, bound_a), (right, bound_b) = (_forward(entries, q, x, values, 0) for x in (a, b))
    except _FAILED:
        return False
    bound = max(bound_a, bound_b)
    return any(abs(u[0] - v[0]) > SAFETY * bound * (u[1] + v[1]) for u, v in zip(left, right))


def _forward(entries, q, at, values, n: int) -> tuple[list[tuple], float]:
    """Each entry's (value, error size, gradient in the first n coordinates, gradient
    error sizes), and K·u, the factor that turns a size into an error bound."""
    walk = _Walk(n, {s: (v, abs(v), (0.0,) * n, (0.0,) * n) for s, v in values.items()})
    for k, (s, x) in enumerate(zip(q, at)):
        unit = tuple(1.0 if i == k else 0.0 for i in range(n))
        walk.memo[s] = (x, abs(x), unit, unit)
    rows = [walk.node(e) for e in entries]
    if not all(math.isfinite(r[0]) for r in rows):
        raise _Unscreened
    return rows, 4 * len(walk.memo) * UNIT_ROUNDOFF


def _gram(J: list[tuple[float, ...]], n: int) -> list[list[float]]:
    return [[sum(row[a] * row[b] for row in J) for b in range(n)] for a in range(n)]


def _positive_definite_above(G: list[list[float]], c: float) -> bool:
    """Cholesky of G − c·I: every pivot positive means every eigenvalue of G is above c."""
    n = len(G)
    L = [[0.0] * n for _ in range(n)]
    for j in range(n):
        pivot = G[j][j] - c - sum(L[j][k] ** 2 for k in range(j))
        if not pivot > 0:
            return False
        L[j][j] = math.sqrt(pivot)
        for i in range(j + 1, n):
            L[i][j] = (G[i][j] - sum(L[i][k] * L[j][k] for k in range(j))) / L[j][j]
    return True


class _Walk:
    """Forward differentiation of sympy trees in float64, each node once: (value, size
    of its rounding error, gradient, sizes of the gradient's errors)."""

    def __init__(self, n: int, memo: dict):
        self.n = n
        self.memo = memo

    def node(self, e: sp.Expr) -> tuple:
        found = self.memo.get(e)
        if found is None:
            found = self.memo[e] = self._compute(e)
        return found

    def _compute(self, e: sp.Expr) -> tuple:
        if e.is_Number or isinstance(e, sp.NumberSymbol):
            v = float(e)
            if not math.isfinite(v):
                raise _Unscreened
            return v, abs(v), (0.0,) * self.n, (0.0,) * self.n
        if e.is_Add:
            return self._add([self.node(a) for a in e.args])
        if e.is_Mul:
            out = self.node(e.args[0])
            for a in e.args[1:]:
                out = _times(out, self.node(a))
            return out
        if e.is_Pow and e.exp.is_Number:
            return _power(self.node(e.base), float(e.exp))
        if isinstance(e, (sp.sin, sp.cos)):
            return _trig(self.node(e.args[0]), isinstance(e, sp.sin))
        raise _Unscreened  # a symbol without a number, or a function this pass does not know

    def _add(self, terms: list[tuple]) -> tuple:
        # n-term float summation errs by up to (n − 1)·u·Σ|terms|: charge n × Σ sizes
        n = len(terms)
        return (sum(t[0] for t in terms), n * sum(t[1] for t in terms),
                tuple(sum(t[2][k] for t in terms) for k in range(self.n)),
                tuple(n * sum(t[3][k] for t in terms) for k in range(self.n)))


def _times(a: tuple, b: tuple) -> tuple:
    """(ab)' = a b' + b a'; the errors of a and b carried through, plus rounding."""
    (va, ma, ga, ha), (vb, mb, gb, hb) = a, b
    v = va * vb
    g = tuple(va * y + vb * x for x, y in zip(ga, gb))
    h = tuple(abs(va) * y + ma * abs(yg) + abs(vb) * x + mb * abs(xg) + abs(va * yg) + abs(vb * xg)
              for x, y, xg, yg in zip(ha, hb, ga, gb))
    return v, abs(va) * mb + abs(vb) * ma + abs(v), g, h


def _power(b: tuple, p: float) -> tuple:
    """(bᵖ)' = p bᵖ⁻¹ b'; a negative base only to an integer power (else not real)."""
    vb, mb, gb, hb = b
    if vb < 0 and not p.is_integer():
        raise _Unscreened
    v = vb ** p
    d = p * vb ** (p - 1)
    dd = abs(p * (p - 1) * vb ** (p - 2)) if p not in (0.0, 1.0) else 0.0
    g = tuple(d * x for x in gb)
    h = tuple(abs(d) * y + dd * mb * abs(x) + abs(d * x) for x, y in zip(gb, hb))
    return v, abs(d) * mb + abs(v), g, h


def _trig(a: tuple, sine: bool) -> tuple:
    """sin′ = cos, cos′ = −sin; the argument's absolute error passes through at most once
    (both are 1-Lipschitz), so a huge argument makes a huge bound, not a wrong screen."""
    va, ma, ga, ha = a
    v, d = (math.sin(va), math.cos(va)) if sine else (math.cos(va), -math.sin(va))
    g = tuple(d * x for x in ga)
    h = tuple(ma * abs(x) + y + abs(d * x) for x, y in zip(ga, ha))
    return v, ma + abs(v), g, h
