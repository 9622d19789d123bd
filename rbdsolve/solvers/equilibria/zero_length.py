"""Solutions of ∂V/∂q = 0 where a spring of natural length l₀ ≠ 0 would be at zero
length: no equilibria. There the spring pushes with k l₀ along a direction its ends no
longer define, and V = ½ k (|d| − l₀)² has a cone, not a stationary point, at d = 0; its
length written ±u (model/energies/spring_length.py: a declared range [0, …], a polar
distance r ≥ 0) hides the cone from ∂V/∂q. The elastic pendulum, P = r (sin θ, −cos θ)
on a spring from O: ∂V/∂θ = m g r sin θ vanishes at r = 0 for every θ, and
∂V/∂r = k (r − l₀) − m g cos θ at cos θ = −k l₀/(m g); P = O is no equilibrium."""

from __future__ import annotations

from typing import Mapping

import sympy as sp

from rbdsolve.form.printers import to_unicode, unicode_name
from rbdsolve.model.build import Model
from rbdsolve.form.zero import simplifies_to_zero


def crushed_spring(model: Model, at: Mapping[sp.Expr, sp.Expr]) -> str | None:
    """The name of a spring at zero length at ``at`` whose stretch is not zero there (it
    has a natural length), or None."""
    for spring in model.springs:
        for length in spring.lengths:
            if length.sign is None or not simplifies_to_zero(length.inside.xreplace(dict(at))):
                continue
            if not simplifies_to_zero(spring.stretch.xreplace(dict(at))):
                return spring.name
    return None


def split(model: Model, solutions) -> tuple[list, list[str]]:
    """The solutions kept, and a warning for each dropped (``crushed_spring``)."""
    kept, warnings = [], []
    names = dict(zip(model.q, model.coordinate_names()))
    for sol in solutions:
        spring = crushed_spring(model, sol)
        if spring is None:
            kept.append(sol)
            continue
        shown = ", ".join(f"{unicode_name(names[q])} = {to_unicode(v)}" for q, v in sol.items())
        warnings.append(f"{shown} solves ∂V/∂q = 0 but is not an equilibrium, not listed: spring '{spring}' would be "
                        "at zero length there, where its push (it has a natural length) has no direction")
    return kept, warnings
