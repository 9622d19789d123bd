"""Equilibria whose existence or stability depends on the parameters, as exams state
them: "exists when Ω ≥ Ω_c", "stable when Ω < Ω_c, unstable when Ω > Ω_c", with
Ω_c = √(g/R) (``solvers/shared/conditions.py`` finds the critical value and the sign
on each side).

Existence: each condition c ≥ 0 (a radicand, 1 − x² under acos) that the parameters'
signs do not decide, split at its critical value, holds on the sides where c > 0,
boundary included. Stability: the quantity whose
sign decides it (``signs.matrix_inertia``'s undecided expression) is split, and on each
side where the equilibrium exists the Hessian is classified again with the parameter
put in as p_c (1 + δ)^{±1}, δ > 0. What cannot be split stays as before: undetermined,
with the conditions as they were.
"""

from __future__ import annotations

from dataclasses import replace

import sympy as sp

from rbdsolve.model.build import Model
from rbdsolve.solvers.equilibria.answers import Equilibrium, Stability, StabilityCase
from rbdsolve.solvers.shared.conditions import Critical, Side, exists_when, on_side, split
from rbdsolve.form.printers import to_unicode
from rbdsolve.form.tidy import tidy
from rbdsolve.solvers.shared.signs import Undecided, matrix_inertia


def with_cases(found: Equilibrium, model: Model, values) -> tuple[Equilibrium, tuple[Critical, ...]]:
    """The equilibrium with ``exists_when`` and ``stability_cases`` where they depend on
    the parameters (``values``: its coordinates, real only where ``real_where`` holds),
    and the critical values used. Found from the symbols, whatever values are given:
    with values the stability itself is decided by them, and the cases say where that
    holds."""
    existence = exists_when(values, model)
    if existence is None:
        return found, ()
    exists, criticals, sides = existence.condition, existence.criticals, existence.sides
    found = replace(found, exists_when=exists)
    inertia = matrix_inertia(found.hessian, model.assumed)
    if not isinstance(inertia, Undecided):
        return found, tuple(criticals)
    s = split(_boundary(found.hessian), model)
    if s is None or (criticals and not s.critical.same_as(criticals[0])):
        return found, tuple(criticals)
    cases = tuple(StabilityCase(s.critical.when(side), _stability_on(found.hessian, s.critical, side))
                  for side in Side if side in sides)
    # with values for what decides it, the values decide (at the boundary itself: undetermined)
    decided = bool(model.values) and not inertia.expr.xreplace(dict(model.values)).free_symbols
    p, named = to_unicode(s.critical.parameter), to_unicode(s.critical.name)
    if len(cases) == 1:
        where = f"{p} {cases[0].when.rel_op} {named}"
        reason = found.reason if decided else f"the Hessian of V keeps one sign where it exists ({where})"
        return replace(found, stability=found.stability if decided else cases[0].stability,
                       reason=reason), (*criticals, s.critical)
    if decided:  # the values decide; the cases say where that holds
        return replace(found, stability_cases=cases), (*criticals, s.critical)
    what = "the Hessian of V changes sign" if found.hessian.rows == 1 else "an eigenvalue of the Hessian of V changes sign (det K = 0)"
    return (replace(found, stability=Stability.DEPENDS, stability_cases=cases,
                    reason=f"{what} at {p} = {named}"), (*criticals, s.critical))


def _boundary(H: sp.Matrix) -> sp.Expr:
    """What vanishes where the stability can change: det K, zero exactly where an
    eigenvalue of K crosses zero (the trace or an entry changing sign decides nothing
    alone: a double pendulum's K₁₁ changes sign above where it stops being stable)."""
    return sp.factor(tidy(sp.Matrix(H).det()))


def _stability_on(H: sp.Matrix, critical: Critical, side: Side) -> Stability:
    value, _ = on_side(sp.Matrix(H), critical, side)
    inertia = matrix_inertia(value.applyfunc(sp.factor), {})
    if isinstance(inertia, Undecided):
        return Stability.UNDETERMINED
    if inertia.negative:
        return Stability.UNSTABLE
    if inertia.zero:
        return Stability.UNDETERMINED
    return Stability.STABLE
