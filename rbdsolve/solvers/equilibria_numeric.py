"""Equilibria, the floating-point route: ∂V/∂q = 0 by Newton's method from a grid of
starts (``numeric_model.find_numeric``: the strategy and its limits are stated there),
each root classified by the eigenvalues of the Hessian of V there (all positive:
stable; one negative: unstable; else neutral to second order).

Error estimate: one more Newton step, |H⁻¹ ∂V/∂q|, relative to max(|q|, 1), plus
cond(H) ε for the rounding of the gradient itself.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Mapping

import numpy as np
import sympy as sp

from rbdsolve.errors import UnsolvedError
from rbdsolve.model.build import Model
from rbdsolve.problem.schema import Question
from rbdsolve.report import steps as st
from rbdsolve.report.steps import Relation, Route, Solution
from rbdsolve.solvers.common import Options, configuration, require_values
from rbdsolve.solvers.equilibria import Stability, require_static
from rbdsolve.solvers.numeric_model import MAX_STARTS, compiled_gradient, find_numeric

EPS = float(np.finfo(float).eps)


@dataclass(frozen=True)
class NumericEquilibrium:
    at: Mapping[str, float]
    stability: Stability
    curvatures: tuple[float, ...]  # eigenvalues of the Hessian of V there, ascending


@dataclass(frozen=True)
class NumericEquilibriaAnswers:
    equilibria: tuple[NumericEquilibrium, ...]
    starts: int  # Newton starts on the grid


def solve(question: Question, model: Model, options: Options) -> Solution:
    require_values(model, "the numeric route")
    require_static(model, "the equilibria")
    found = find_numeric(model)
    if not found.equilibria:
        raise UnsolvedError(f"Newton's method from {found.starts} starts found no equilibrium")
    g, H = compiled_gradient(model)
    names = model.coordinate_names()
    equilibria, errors = [], []
    for point, kind in found.equilibria:
        x = np.array(point)
        hess = np.asarray(H(x), dtype=float)
        curvatures = np.linalg.eigvalsh((hess + hess.T) / 2)
        equilibria.append(NumericEquilibrium(dict(zip(names, point)), Stability(kind),
                                             tuple(float(c) for c in curvatures)))
        errors.append(_error(x, np.asarray(g(x), dtype=float), hess))
    answers = NumericEquilibriaAnswers(tuple(equilibria), found.starts)
    warning = (f"numeric search: Newton's method from {found.starts} grid starts (at most {MAX_STARTS}) over "
               "angles in (−π, π] and lengths within ±10 × the largest parameter value; an equilibrium whose "
               "basin misses every start would be missed")
    return Solution("equilibria", Route.NUMERIC, answers, _steps(answers, model), warnings=(warning,),
                    error_estimate=float(max(errors)))


def _error(x: np.ndarray, gradient: np.ndarray, hess: np.ndarray) -> float:
    try:
        step = np.linalg.solve(hess, gradient)
        condition = np.linalg.cond(hess)
    except np.linalg.LinAlgError:
        return float("inf")
    return float(np.max(np.abs(step)) / max(np.max(np.abs(x)), 1.0) + condition * EPS)


def _steps(a: NumericEquilibriaAnswers, model: Model) -> tuple[st.Step, ...]:
    steps = [st.equation(f"Equilibria solve ∂V/∂q = 0; Newton's method from {a.starts} starts on a grid finds:")]
    for i, eq in enumerate(a.equilibria, 1):
        where = configuration(model.state.functions(), [sp.Float(v, 12) for v in eq.at.values()])
        curv = Relation(sp.Symbol("eig(H)"), sp.ImmutableMatrix([[sp.Float(c, 6) for c in eq.curvatures]]))
        steps.append(st.result(f"Equilibrium {i}: {eq.stability.value} (eigenvalues of ∂²V/∂q∂q there):",
                               where, curv))
    return tuple(steps)
