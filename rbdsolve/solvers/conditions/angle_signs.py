"""Signs proved over an angle parameter's range: a parameter that a condition holds only
through sines and cosines of whole multiples of it is studied over (0, π) when positive
(docs/format.md, "Conditions"), and there sin α > 0. Put in as a positive symbol, it
decides signs sympy's assumptions cannot, for every value of the range, never by
samples (docs/failure-edges.md §55)."""

from __future__ import annotations

import sympy as sp

from rbdsolve.form.tidy import tidy
from rbdsolve.model.assumptions import implies
from rbdsolve.solvers.conditions.condition_roots import angle_parameters
from rbdsolve.solvers.conditions.signs import sign_of


def angle_sign(f: sp.Expr, model) -> int | None:
    """f's sign for every value the parameters' signs and the assumptions allow, each
    positive angle parameter α taken in (0, π), where its conditions are studied
    (``angle_parameters``): there sin α > 0, put in as a positive symbol (cos α keeps no
    sign, nor sin 2α), so a sign decided is proved, never sampled. g m sin α + 6 k r > 0
    and −r (g m sin α + 18 k r/5) < 0 for every incline; −R m (Ω² R cos α + g) cos α
    stays undecided (it changes sign past α = π/2), unless the assumptions bound α on
    one side of π/2 (then cos α has that side's sign too). None where it is not decided
    so, or where a value given puts α outside (0, π)."""
    values = dict(model.values)
    signed = {}
    for p, (low, high) in angle_parameters(f).items():
        value = values.get(p)
        inside = value is None or bool(sp.And(value > low, value < high))
        if low == 0 and high == sp.pi and inside:
            signed[sp.sin(p)] = sp.Dummy(f"sin_{p}", positive=True)
            if implies(model.assumptions, sp.StrictLessThan(p, sp.pi / 2)):  # [alpha < pi/2]: cos α > 0 too
                signed[sp.cos(p)] = sp.Dummy(f"cos_{p}", positive=True)
            elif implies(model.assumptions, sp.StrictGreaterThan(p, sp.pi / 2)):
                signed[sp.cos(p)] = -sp.Dummy(f"cos_{p}", positive=True)
    if not signed:
        return None
    sign = sign_of(tidy(f).xreplace(signed), model.assumed)
    return sign if isinstance(sign, int) else None
