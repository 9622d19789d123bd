"""Contact limits: where a support stops holding, and the conditions for it to hold.

A push N (a contact) or a tension T (a string) holds while it is ≥ 0; rolling holds
while the friction it needs is within reach, |F| ≤ μ N. So

- along a motion (the forces functions of q alone), the contact is lost (the string goes
  slack) where N (T) reaches zero: the roots of its numerator, as cos q = c (or sin q = c,
  or q = c), with |c| ≤ 1 for an angle (``zeros``); where c holds parameters, such a
  point exists when |c| ≤ 1, solved for one parameter (``exists``);
- the least coefficient of friction for rolling is μ = |F|/N (``least_mu``);
- at a state, the support holds when N ≥ 0 (T ≥ 0), and rolls when μ ≥ |F|/N: where the
  parameters' signs do not decide N's, the condition solved for one parameter in the
  form of the conditions on parameters (solvers/conditions/conditions.py), "holds when ω ≤ ω_c",
  with its critical values (``holds``).
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from rbdsolve.form.tidy import tidy_fraction
from rbdsolve.model.build import Model
from rbdsolve.solvers.reactions.supports import Held, How
from rbdsolve.solvers.lagrange.accelerations import clean_fraction
from rbdsolve.model.assumptions import implies
from rbdsolve.solvers.conditions.conditions import Critical, nonnegative_where
from rbdsolve.solvers.conditions.polynomial import trig_transcendental
from rbdsolve.solvers.conditions.signs import Undecided, sign_of
from rbdsolve.form.zero import simplifies_to_zero


def zeros(value: sp.Expr, model: Model) -> list[sp.Relational] | None:
    """Where a force of q alone vanishes: cos q = c (|c| ≤ 1), sin q = c, or q = c; None
    where that has no closed form.

    |u| vanishes where u does, and |u|/u (a push along a normal that turns, ±1) nowhere:
    each |u| is taken as u before the numerator is read, so that the ±1 cancels. A
    numerator that holds q both inside and outside sin and cos (a slab rolling on a
    drum: θ³ sin θ beside θ² cos θ), or sines of incommensurate multiples of q (a
    half-disk on a drum: sin(r θ/(R + r)) beside cos θ) has no closed-form zeros: None,
    not a search by sympy's solve (minutes, issue 37). Only real roots count."""
    q = model.q[0]
    top = sp.fraction(tidy_fraction(value.replace(sp.Abs, lambda u: u)))[0]
    if not top.has(q):
        return []
    c = sp.Dummy("c", real=True)
    for f in (sp.cos, sp.sin):
        swapped = top.xreplace({f(q): c})
        if not swapped.has(q):
            roots = [r for r in _real_roots(swapped, c) if _within_one(r, model)]
            return [sp.Eq(f(model.to_time(q)), r) for r in roots]
    if trig_transcendental(top, q):
        return None
    return [sp.Eq(model.to_time(q), r) for r in _real_roots(top, q)]


def _real_roots(expr: sp.Expr, x: sp.Symbol) -> list[sp.Expr]:
    """sympy's roots of expr in x, those that may be real (no Piecewise, no i, no NaN)."""
    try:
        roots = sp.solve(expr, x)
    except NotImplementedError:
        return []
    return [r for r in roots if not r.has(sp.Piecewise, sp.I, sp.nan, sp.zoo) and r.is_real is not False]


def _within_one(r: sp.Expr, model: Model) -> bool:
    """|r| ≤ 1, where the parameters' values or signs decide it (undecided: kept)."""
    value = r.xreplace(model.decided_by) if model.decided_by else r
    if value.is_real is False:
        return False
    if value.is_number:
        z = complex(sp.N(value, 30))
        return abs(z.imag) <= 1e-20 * max(1.0, abs(z.real)) and abs(z.real) <= 1 + 1e-15
    return True


SIMPLIFY_OPS = 80  # the least μ is simplified by sympy up to this many operations


def least_mu(F: sp.Expr, N: sp.Expr, model: Model) -> sp.Expr:
    """μ ≥ |F|/N: the friction a rolling contact needs, over the normal push; |…| kept
    where neither the parameters' signs nor their values decide the sign, nor the
    assumptions, nor where the contact holds at all (N ≥ 0: a cylinder on an incline
    pushes only for α ≤ π/2, where tan α ≥ 0, so μ ≥ tan(α)/3)."""
    ratio = clean_fraction(F / N)
    if sp.count_ops(ratio) <= SIMPLIFY_OPS:  # a longer one (a slab rolling on a drum): minutes of trigsimp
        ratio = sp.simplify(ratio)
    sign = sign_of(ratio, model.decided_by)
    if isinstance(sign, Undecided):
        pushes = _nonnegative(N, model).condition if not N.has(*model.q) else sp.true
        if implies(model.assumptions, sp.Ge(ratio, 0)) or _on(pushes, sp.Ge(ratio, 0)):  # tan α ≥ 0 under 0 < α < π/2
            return ratio
        if implies(model.assumptions, sp.Le(ratio, 0)) or _on(pushes, sp.Le(ratio, 0)):
            return -ratio
        return sp.Abs(ratio)
    return ratio if sign >= 0 else -ratio


def _on(where: sp.Basic, relation: sp.Basic) -> bool:
    """Whether ``relation`` holds inside the set ``where`` allows, both in one parameter
    p (its boundary left out, where the ratio may not be defined: tan α at α = π/2)."""
    free = relation.free_symbols
    if len(free) != 1 or where in (sp.true, sp.false) or where.free_symbols != free:
        return False
    (p,) = free
    try:
        allowed = sp.Intersection(where.as_set(), sp.Interval.open(0, sp.oo) if p.is_positive else sp.S.Reals)
        inside = allowed.interior
        return not inside.is_empty and inside.is_subset(sp.solveset(relation, p, inside)) is True
    except (NotImplementedError, TypeError, ValueError):
        return False


@dataclass(frozen=True)
class Holds:
    """When one support holds at the state: the condition (true, false, or solved for one
    parameter) and the critical values it uses."""

    condition: sp.Basic
    criticals: tuple[Critical, ...]


def holds(s: Held, values: dict[str, sp.Expr], model: Model) -> Holds:
    """N ≥ 0 (T ≥ 0) for each push or tension, and μ ≥ |F|/N for a rolling contact's
    friction, at the state (``values``: component name -> value there)."""
    condition, criticals = sp.true, []
    for c in s.components:
        if c.one_sided:
            found = _nonnegative(values[str(c.symbol)], model)
            condition, criticals = sp.And(condition, found.condition), criticals + list(found.criticals)
    if s.how is How.ROLLING and condition is not sp.false:
        N, F = (values[str(c.symbol)] for c in s.components)
        if not simplifies_to_zero(N):
            condition = sp.And(condition, sp.Ge(mu(s.name), least_mu(F, N, model)))
    return Holds(condition, tuple(criticals))


def mu(name: str) -> sp.Symbol:
    return sp.Symbol(f"mu_{name}")


def _nonnegative(value: sp.Expr, model: Model) -> Holds:
    """value ≥ 0: decided by the parameters' signs, else solved for one parameter (a
    rate first), else left as it is (``nonnegative_where``)."""
    found = nonnegative_where(value, model)
    return Holds(found.condition, found.criticals)


def exists(where: sp.Relational, model: Model, rate_squared: sp.Expr) -> Holds:
    """Where the motion from rest reaches a zero cos q = c (sin q = c, q = c): |c| ≤ 1, and
    q̇² ≥ 0 there (the motion turns back before a zero where q̇² < 0 — a cylinder released
    inside a cylinder below the horizontal never leaves it); each solved for one parameter
    where the parameters' signs do not decide it."""
    parts = [_reached(where, model, rate_squared)]
    c = where.rhs
    if isinstance(where.lhs, (sp.cos, sp.sin)) and c.free_symbols and not _within(c):
        parts += [_nonnegative(1 - c, model), _nonnegative(1 + c, model)]
    return Holds(sp.And(*(h.condition for h in parts)), tuple(c for h in parts for c in h.criticals))


def _reached(where: sp.Relational, model: Model, rate_squared: sp.Expr) -> Holds:
    """q̇² ≥ 0 at the zero: q̇²(q) with cos q = c put in (sin² q = 1 − c²; likewise for
    sin q = c), or q = c; kept (true) where q̇² holds q otherwise."""
    q = model.q[0]
    side = where.lhs.xreplace({model.to_time(q): q})
    c = where.rhs
    if side == q:
        value = rate_squared.xreplace({q: c})
    else:
        other = sp.sin(q) if isinstance(side, sp.cos) else sp.cos(q)
        value = sp.expand(rate_squared).xreplace({side: c}).subs(other**2, 1 - c**2)
    if value.has(q):
        return Holds(sp.true, ())
    return _nonnegative(clean_fraction(value), model)


def _within(c: sp.Expr) -> bool:
    """|c| ≤ 1 for every value of the angles in it: each sine and cosine of a parameter
    put in as the interval [−1, 1] (interval arithmetic bounds c from outside)."""
    box = {f: sp.AccumBounds(-1, 1) for f in c.atoms(sp.sin, sp.cos)}
    bound = c.xreplace(box)
    if not isinstance(bound, sp.AccumBounds) or bound.free_symbols:
        return False
    return bool(bound.min >= -1) and bool(bound.max <= 1)
