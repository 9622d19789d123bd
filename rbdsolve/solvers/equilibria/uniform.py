"""Equilibria where ∂V/∂q holds no coordinate: a body pushed by loads that do not change
as it moves (a spool pulled at the angle α by a string from its axle, ∂V/∂x =
F (r − R cos α)/R).

Such a gradient is the same at every configuration, so there is no equilibrium unless
it vanishes, and then every configuration is one (neutral: V is flat). Which parameter
values make it vanish is the exam's answer, "the spool does not move when cos α = r/R":
each nonzero component, less its factors of one sign, is solved for one parameter, an
angle parameter (one inside sin and cos) through its cosine or sine, any other itself:
the one the question's ``for:`` names, else the problem's only parameter without a value,
else one without a value, an angle first ("the disk on the 30° incline stays where
F = m g sin(α)/2" with ``for: F``).
"""

from __future__ import annotations

import sympy as sp

from rbdsolve.form.printers import to_unicode, unicode_name
from rbdsolve.form.tidy import tidy
from rbdsolve.model.build import Model
from rbdsolve.report import steps as st
from rbdsolve.solvers.equilibria.answers import Equilibrium, Stability


def uniform_equilibrium(model: Model, grad: tuple[sp.Expr, ...],
                        first: sp.Symbol | None = None) -> tuple[Equilibrium, str] | None:
    """Every configuration (shown at q = 0), neutral, existing where each constant
    component of ∂V/∂q vanishes; with the warning that says so. None where a component
    holds a coordinate, where none is constant, or where the values decide it is not 0."""
    nonzero = [g for g in grad if g != 0]
    if not nonzero or any(g.has(*model.q) for g in nonzero) or any(not g.free_symbols for g in nonzero):
        return None
    relations = [_vanishes(g, model, first) for g in nonzero]
    if any(r is None for r in relations):
        return None
    condition = sp.And(*relations)
    if model.values and condition.xreplace(dict(model.values)) in (sp.false, False):
        return None
    names = model.coordinate_names()
    at = {n: sp.Integer(0) for n in names}
    n = len(model.q)
    shown = "; ".join(f"∂V/∂{unicode_name(names[i])} = {to_unicode(model.readable(g))}"
                      for i, g in enumerate(grad) if g != 0)
    every = ", ".join(unicode_name(x) for x in names)
    reason = f"V is flat where it holds (∂V/∂q = 0 at every {every}): every configuration is an equilibrium"
    warning = (f"{shown}: the same at every {every}, so there is no equilibrium unless it is 0, and then every "
               f"{every} is one (shown as 0): the loads balance at every place, and the scene rests or moves "
               "on at a constant rate")
    return Equilibrium(at, Stability.NEUTRAL, sp.ImmutableMatrix(sp.zeros(n, n)), reason,
                       exists_when=condition), warning


def _vanishes(g: sp.Expr, model: Model, first: sp.Symbol | None) -> sp.Basic | None:
    """g = 0 as a relation solved for one parameter (its factors of one sign dropped),
    tried in the order of ``_preference``."""
    factors = [f for f in sp.Mul.make_args(sp.factor(g)) if f.free_symbols and not _signed(f, model)]
    if len(factors) != 1:
        return None
    (f,) = factors
    f = f.base if f.is_Pow and f.exp.is_positive else f
    for p in _preference(f, model, first):
        for trig in (sp.cos(p), sp.sin(p)) if _angle(f, p) else (p,):
            x = sp.Dummy("x")
            stand_in = f.xreplace({trig: x})
            if stand_in.has(p) or sp.degree(stand_in, x) != 1:
                continue
            (value,) = sp.solve(stand_in, x)
            return sp.Eq(trig, tidy(value))
    return None


def _preference(f: sp.Expr, model: Model, first: sp.Symbol | None) -> list[sp.Symbol]:
    """The parameters in f: the one asked for (``for:``), the problem's only one without
    a value, those without a value, then angles before the others, in the file's order."""
    order = list(model.symbols.parameters.values())
    open_ = [p for p in order if p not in model.values]
    lone = open_[0] if len(open_) == 1 else None
    return sorted(f.free_symbols & set(order),
                  key=lambda p: (p != first, p != lone, p in model.values, not _angle(f, p), order.index(p)))


def _signed(f: sp.Expr, model: Model) -> bool:
    """A factor of one sign for every value allowed (F, R, a power of them)."""
    value = f.xreplace(model.assumed) if model.assumed else f
    return bool(value.is_positive or value.is_negative)


def _angle(f: sp.Expr, p: sp.Symbol) -> bool:
    """Does p enter f only through sin and cos of it?"""
    trig = f.atoms(sp.sin, sp.cos)
    return bool(trig) and not f.xreplace({x: sp.Dummy() for x in trig if x.args[0] == p}).has(p)


def never_balanced(model: Model, grad: tuple[sp.Expr, ...], first: sp.Symbol | None = None):
    """The step that says there is no equilibrium, where a component of ∂V/∂q holds no
    coordinate and is not 0: a nonzero number at the parameter values (the block is
    pulled harder than the hanging weight: ∂V/∂θ = R (g m₂ − F) = −0.6342), or of one
    sign for every value allowed (a cart pulled by F > 0: ∂V/∂x = −F, whatever the
    pendulum on it does); None otherwise."""
    names = model.coordinate_names()
    every = ", ".join(unicode_name(x) for x in names)
    for name, g in zip(names, grad):
        if g == 0 or g.has(*model.q):
            continue
        shown = f"∂V/∂{unicode_name(name)} = {to_unicode(model.readable(g))}"
        value = g.xreplace(dict(model.values)) if model.values else g
        if value.is_number and value != 0:
            number = f"{float(value):.6g}".replace("-", "−")
            return st.note(f"At the parameter values {shown} = {number}, not 0, and the same at every {every}: the "
                           f"loads never balance, so there is no equilibrium{_balancing(g, model, first)}.")
        if _signed(g, model):
            return st.note(f"{shown} is not 0 for any value the parameters may take, and the same at every {every}: "
                           "the loads never balance, so there is no equilibrium.")
    return None


def _balancing(g: sp.Expr, model: Model, first: sp.Symbol | None) -> str:
    """'; they would balance where cos(α) = r/R (= 0.5 here)': the relation g = 0 solved
    for one parameter (the question's ``for:`` first), its side in numbers; '' where g = 0
    is solved for none."""
    relation = _vanishes(g, model, first)
    if relation is None:
        return ""
    side = relation.rhs.xreplace(dict(model.values))
    number = f" (= {float(side):.6g} here)".replace("-", "−") if side.is_number and relation.rhs.free_symbols else ""
    return f"; they would balance where {to_unicode(model.readable(relation.lhs))} = " \
           f"{to_unicode(model.readable(relation.rhs))}{number}"
