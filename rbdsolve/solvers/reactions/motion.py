"""Along the motion released from rest: the speed by conservation of energy, the forces
as functions of the coordinate, and the contact limits.

With one coordinate q, no time in the scene and only conservative forces (gravity,
springs; ideal supports do no work), T + V is constant:

    ½ M(q) q̇² + V(q) = V(q₀)   ⇒   q̇² = 2 (V(q₀) − V(q)) / M(q),

and every force found by Newton–Euler, a function of q and q̇² (the accelerations of a
planar body carry q̇ only squared), becomes a function of q alone. Then

- a push N (or a string's tension T) is lost where it reaches zero: the roots of its
  numerator, as cos q = c (or sin q = c, or q = c) with |c| ≤ 1 for an angle;
- rolling needs μ ≥ |F|/N at every instant, the least coefficient of friction.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from rbdsolve.form.tidy import tidy_fraction
from rbdsolve.model.build import Model
from rbdsolve.model.energy import kinetic_energy, potential_energy
from rbdsolve.solvers.reactions.balances import clean
from rbdsolve.solvers.shared.signs import Undecided, sign_of


@dataclass(frozen=True)
class Energy:
    T: sp.Expr
    V: sp.Expr
    start: sp.Expr  # V(q₀)
    rate_squared: sp.Expr  # q̇² as a function of q


def energy(model: Model, start: dict[sp.Symbol, sp.Expr]) -> Energy | None:
    """q̇²(q) from T + V = V(q₀), or None where it does not apply (several coordinates,
    time in the scene, T not ½ M q̇²)."""
    if len(model.q) != 1 or model.depends_on_time():
        return None
    q, qd = model.q[0], model.qd[0]
    T, V = kinetic_energy(model).total, potential_energy(model).total
    M = sp.diff(T, qd, 2)
    if sp.expand(T - M * qd**2 / 2) != 0 or M.has(qd):
        return None
    V0 = sp.simplify(V.xreplace({q: start[q]}))
    return Energy(T, V, V0, clean(2 * (V0 - V) / M))


def along(value: sp.Expr, model: Model, e: Energy) -> sp.Expr | None:
    """A force of q and q̇ as a function of q alone, q̇² from the energy (None: q̇ left)."""
    qd = model.qd[0]
    w = sp.Dummy("w")
    replaced = sp.expand(value).subs(qd**2, w)
    if replaced.has(qd):
        return None
    return clean(replaced.xreplace({w: e.rate_squared}))


def zeros(value: sp.Expr, model: Model) -> list[sp.Relational]:
    """Where a force of q alone vanishes: cos q = c (|c| ≤ 1), sin q = c, or q = c."""
    q = model.q[0]
    top = sp.fraction(tidy_fraction(value))[0]
    if not top.has(q):
        return []
    c = sp.Dummy("c", real=True)
    for f in (sp.cos, sp.sin):
        swapped = top.xreplace({f(q): c})
        if not swapped.has(q):
            roots = [r for r in sp.solve(swapped, c) if _within_one(r, model)]
            return [sp.Eq(f(model.to_time(q)), r) for r in roots]
    try:
        roots = sp.solve(top, q)
    except NotImplementedError:
        return []
    return [sp.Eq(model.to_time(q), r) for r in roots if r.is_real is not False]


def _within_one(r: sp.Expr, model: Model) -> bool:
    """|r| ≤ 1, where the parameters' values or signs decide it (undecided: kept)."""
    value = r.xreplace(model.decided_by) if model.decided_by else r
    if value.is_real is False:
        return False
    if value.is_number:
        return bool(abs(value) <= 1)
    return True


def least_mu(F: sp.Expr, N: sp.Expr, model: Model) -> sp.Expr:
    """μ ≥ |F|/N: the friction a rolling contact needs, over the normal push; |…| kept
    where neither the parameters' signs nor their values decide the sign."""
    ratio = sp.simplify(clean(F / N))
    sign = sign_of(ratio, model.decided_by)
    if isinstance(sign, Undecided):
        return sp.Abs(ratio)
    return ratio if sign >= 0 else -ratio

