"""Steady spin, the floating-point route: the principal moments J₁ ≤ J₂ ≤ J₃ and axes
of J_G in floats (numpy.linalg.eigh); a steady spin is a spin Ω about a principal axis
(Euler's equations, J ω̇ + ω × J ω = 0, need ω × J ω = 0). Linearizing about Ω e_k:

    (J_k − J_i)(J_k − J_j) > 0: stable, the perturbation turns at Ω √((J_k − J_i)(J_k − J_j)/(J_i J_j));
    (J_k − J_i)(J_k − J_j) < 0: unstable, it grows at Ω √(−(J_k − J_i)(J_k − J_j)/(J_i J_j)).

Rates are given per unit spin (Ω = 1). Moments equal to within EQUAL_TOL (relative)
are taken as equal: a symmetric body, whose spin about the symmetry axis is stable and
whose equatorial spins are neutral, or a spherical one, neutral about every axis.
"""

from __future__ import annotations

from dataclasses import fields, replace

import numpy as np
import sympy as sp

from rbdsolve.errors import UnsolvedError
from rbdsolve.model.build import Model
from rbdsolve.problem.schema import Question
from rbdsolve.report.steps import Route, Solution
from rbdsolve.solvers.inertia.numeric import principal_floats, relative_estimate
from rbdsolve.solvers.numeric.numeric_model import to_floats
from rbdsolve.solvers.routes.options import Options
from rbdsolve.solvers.routes.needed import require_values
from rbdsolve.solvers.steady_spin.answers import NumericSpin, NumericSteadySpinAnswers, Stability
from rbdsolve.solvers.steady_spin.precession import numeric_precession, precession_steps
from rbdsolve.solvers.steady_spin.steps import numeric_steps

EQUAL_TOL = 1e-9


def solve(question: Question, model: Model, options: Options) -> Solution:
    require_values(model, "the numeric route")
    name = question.options.body
    body = next(b for b in model.bodies if b.name == name)
    J, axes, absolute = principal_floats(to_floats(body.inertia, model.values))
    if np.min(J) <= EQUAL_TOL * np.max(J):
        raise UnsolvedError(f"body '{name}' has a zero principal moment: Euler's equations need three positive "
                            "moments")
    spins = tuple(_spin(k, J, axes) for k in range(3))
    asked = question.options.precession
    free = numeric_precession(asked, J, EQUAL_TOL * float(np.max(J)), model) if asked is not None else None
    answers = NumericSteadySpinAnswers(name, tuple(float(x) for x in J), spins, free)
    steps = numeric_steps(answers)
    if free is not None:  # the exact route's steps, with the numbers
        shown = {f.name: sp.Float(getattr(free, f.name), 15) for f in fields(free) if f.name != "axis"}
        steps += tuple(precession_steps(replace(free, **shown)))
    return Solution("steady_spin", Route.NUMERIC, answers, steps,
                    error_estimate=relative_estimate(J, absolute))


def _spin(k: int, J: np.ndarray, axes: np.ndarray) -> NumericSpin:
    i, j = (n for n in range(3) if n != k)
    axis, tol = tuple(float(x) for x in axes[:, k]), EQUAL_TOL * np.max(J)
    if abs(J[k] - J[i]) <= tol or abs(J[k] - J[j]) <= tol:  # equatorial spin of a symmetric body, or a sphere
        return NumericSpin(axis, float(J[k]), Stability.NEUTRAL, None)
    product = (J[k] - J[i]) * (J[k] - J[j])
    rate = float(np.sqrt(abs(product) / (J[i] * J[j])))
    if product < 0:
        return NumericSpin(axis, float(J[k]), Stability.UNSTABLE, rate)
    precession = _symmetric_axis(k, J, tol)
    return NumericSpin(axis, float(J[k]), Stability.STABLE, precession if precession is not None else rate)


def _symmetric_axis(k: int, J: np.ndarray, tol: float) -> float | None:
    """About the symmetry axis (the other two moments equal) the perturbation precesses
    at (J_k − J_i)/J_i per unit spin."""
    i, j = (n for n in range(3) if n != k)
    if abs(J[i] - J[j]) <= tol:
        return float((J[k] - J[i]) / J[i])
    return None
