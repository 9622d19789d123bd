"""What an equilibrium must satisfy, for the check before it is printed
(solvers/routes/checks.py): ∂V/∂q = 0 there, for every coordinate, wherever it exists."""

from __future__ import annotations

import sympy as sp

from rbdsolve.form.printers import unicode_name
from rbdsolve.model.build import Model
from rbdsolve.model.derivative import derivative
from rbdsolve.model.energies.energy import potential_energy
from rbdsolve.problem.schema import Question
from rbdsolve.solvers.equilibria.answers import EquilibriaAnswers, Equilibrium
from rbdsolve.solvers.routes.checks import Residual, Vanishes


def residuals(question: Question, model: Model, answers: object) -> tuple[Residual, ...]:
    """∂V/∂q_j at each equilibrium of the exact route (V as the model gives it: in a
    moving frame, the effective potential)."""
    if not isinstance(answers, EquilibriaAnswers):
        return ()
    return tuple(r for k, eq in enumerate(answers.equilibria, 1) for r in stationary(model, eq, f"equilibrium {k}"))


def stationary(model: Model, eq: Equilibrium, name: str) -> list[Residual]:
    """∂V/∂q_j = 0 at ``eq`` for each coordinate, where it exists (its condition, and
    each of its conditions ≥ 0)."""
    V = potential_energy(model).total
    at = {q: eq.at[n] for q, n in zip(model.q, model.coordinate_names()) if n in eq.at}
    where = sp.And(eq.exists_when, *(sp.GreaterThan(c, 0) for c in eq.conditions))
    return [Vanishes(f"∂V/∂{unicode_name(n)} at {name}", derivative(V, q).xreplace(at), where)
            for q, n in zip(model.q, model.coordinate_names())]
