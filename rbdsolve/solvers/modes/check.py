"""What small oscillations must satisfy, for the check before they are printed
(solvers/routes/checks.py): each eigenvalue λ makes K − λM singular, det(K − λM) = 0, and its
mode shape a solves (K − λM) a = 0, wherever the equilibrium they are about exists.
The text names λ₁ … and the equilibrium: "row 1 of (K − λ₁ M) a₁ about equilibrium 2"."""

from __future__ import annotations

import sympy as sp

from rbdsolve.model.build import Model
from rbdsolve.problem.schema import Question
from rbdsolve.solvers.modes.answers import EachModesAnswers, ModesAnswers
from rbdsolve.solvers.routes.checks import Pencil, Residual
from rbdsolve.solvers.equilibria.cases import existing_where


def residuals(question: Question, model: Model, answers: object) -> tuple[Residual, ...]:
    """The exact route's eigenvalues and shapes, about one equilibrium or each."""
    if isinstance(answers, EachModesAnswers):
        return tuple(r for k, a in enumerate(answers.modes, 1) if isinstance(a, ModesAnswers)
                     for r in eigenpairs(a, model, f" about equilibrium {k}"))
    if isinstance(answers, ModesAnswers):
        return eigenpairs(answers, model)
    return ()


def eigenpairs(a: ModesAnswers, model: Model, about: str = "") -> tuple[Residual, ...]:
    """(K − λᵢ M) aᵢ = 0 for each λᵢ (det(K − λᵢ M) = 0 where no shape is given), where
    the equilibrium exists: every radicand of its coordinates and every spring's signed
    length there ≥ 0 (``existing_where``)."""
    at = {q: a.about[n] for q, n in zip(model.q, model.coordinate_names()) if n in a.about}
    where = sp.And(*(sp.GreaterThan(c, 0) for c in existing_where(at, model)))
    shapes = tuple(a.shapes[k] if k < len(a.shapes) else None for k in range(len(a.eigenvalues)))
    return (Pencil(about, a.K, a.M, tuple(a.eigenvalues), shapes, where),)
