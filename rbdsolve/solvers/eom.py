"""Lagrange's equations.

    d/dt (∂L/∂q̇_i) − ∂L/∂q_i = 0,   L = T − V           (e.g. Goldstein, ch. 1)

with the total time derivative written out by the chain rule,

    d/dt (∂L/∂q̇_i) = Σ_j (∂²L/∂q̇_i∂q̇_j q̈_j + ∂²L/∂q̇_i∂q_j q̇_j) + ∂²L/∂q̇_i∂t.

Each equation is an expression = 0, collected in q̈ and q̇ with each coefficient tidied,
and shown with the scales pulled out: the inertia part m r² […] and the potential part
m g r […], as an exam solution writes it.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from rbdsolve.model.build import Model
from rbdsolve.model.energy import kinetic_energy, potential_energy
from rbdsolve.model.tidy import collect_in
from rbdsolve.problem.schema import Question
from rbdsolve.report import steps as st
from rbdsolve.report.math import Terms
from rbdsolve.report.steps import Relation, Route, Solution
from rbdsolve.solvers.common import Options
from rbdsolve.solvers.energies import present


@dataclass(frozen=True)
class EomAnswers:
    equations: tuple[sp.Expr, ...]  # each expression = 0, one per coordinate


def lagrange_equations(model: Model) -> tuple[sp.Expr, ...]:
    """E_i = d/dt(∂L/∂q̇_i) − ∂L/∂q_i for each coordinate, in the model's plain symbols."""
    L = kinetic_energy(model).total - potential_energy(model).total
    generators = [*model.qdd, *model.qd]
    out = []
    for q, qd in zip(model.q, model.qd):
        E = model.state.d_dt(sp.diff(L, qd)) - sp.diff(L, q)
        out.append(sp.Add(*[c * m for m, c in collect_in(E, generators).items()]))
    return tuple(out)


def solve(question: Question, model: Model, options: Options) -> Solution:
    equations = lagrange_equations(model)
    steps = (
        st.result(
            "Lagrange's equations, d/dt(∂L/∂q̇) − ∂L/∂q = 0 with L = T − V, one for each "
            "coordinate in turn:",
            *[Relation(_present(E, model), sp.Integer(0)) for E in equations],
        ),
    )
    answers = EomAnswers(tuple(model.to_time(E) for E in equations))
    return Solution("eom", Route.EXACT, answers, steps)


def _present(E: sp.Expr, model: Model):
    """Inertia terms (with q̈ or q̇) and the rest, each with its own scale pulled out."""
    parts = collect_in(E, [*model.qdd, *model.qd], tidied=True)
    moving = sp.Add(*[c * m for m, c in parts.items() if m != 1])
    still = parts.get(sp.Integer(1), sp.Integer(0))
    groups = [present(g, model) for g in (moving, still) if g != 0]
    return groups[0] if len(groups) == 1 else Terms(tuple(groups))
