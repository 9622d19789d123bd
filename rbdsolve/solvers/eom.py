"""Lagrange's equations.

    d/dt (∂L/∂q̇_i) − ∂L/∂q_i = 0,   L = T − V           (e.g. Goldstein, ch. 1)

Each equation is written as an expression = 0, its terms collected in q̈ and q̇ with
each coefficient tidied on its own, and shown with the scales pulled out: the inertia
part m r² […] and the potential part m g r […], as an exam solution writes it.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from rbdsolve.model.build import Model
from rbdsolve.model.energy import kinetic_energy, potential_energy
from rbdsolve.model.symbols import t
from rbdsolve.model.tidy import collect_in
from rbdsolve.problem.schema import Question
from rbdsolve.report import steps as st
from rbdsolve.report.math import Terms
from rbdsolve.report.steps import Relation, Route, Solution
from rbdsolve.solvers.common import Options, ordered_sum, scaled_sum


@dataclass(frozen=True)
class EomAnswers:
    equations: tuple[sp.Expr, ...]  # each expression = 0, one per coordinate


def lagrange_equations(model: Model) -> tuple[sp.Expr, ...]:
    """E_i = d/dt(∂L/∂q̇_i) − ∂L/∂q_i for each coordinate, tidied."""
    L = kinetic_energy(model).total - potential_energy(model).total
    generators = [*model.qdd, *model.qd]
    out = []
    for q, qd in zip(model.q, model.qd):
        E = sp.diff(sp.diff(L, qd), t) - sp.diff(L, q)
        parts = collect_in(E, generators)
        out.append(sp.Add(*[c * m for m, c in parts.items()]))
    return tuple(out)


def solve(question: Question, model: Model, options: Options) -> Solution:
    equations = lagrange_equations(model)
    shown = [Relation(_present(E, model), sp.Integer(0)) for E in equations]
    names = ", ".join(model.coordinate_names())
    steps = (
        st.definition(
            "Lagrange's equations, d/dt(∂L/∂q̇) − ∂L/∂q = 0 with L = T − V, "
            f"one for each coordinate ({names}):",
            *shown,
        ),
    )
    return Solution("eom", Route.EXACT, EomAnswers(equations), steps)


def _present(E: sp.Expr, model: Model):
    """Inertia terms (with q̈ or q̇) and the rest, each with its own scale pulled out."""
    generators = [*model.qdd, *model.qd]
    parts = collect_in(E, generators)
    symbols = set(model.symbols.parameters.values())
    moving = {m: c for m, c in parts.items() if m != 1}
    still = {m: c for m, c in parts.items() if m == 1}
    groups = [scaled_sum(ordered_sum(g, generators), symbols) for g in (moving, still) if g]
    if len(groups) == 1:
        return groups[0]
    return Terms(tuple(groups))
