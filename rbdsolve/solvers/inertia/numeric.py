"""Inertia, the floating-point route: the tensor J (about G, or about P by the parallel
axis theorem J_P = J_G + m (|d|² 1 − d dᵀ), in the requested axes) assembled exactly
from the shape library, rounded once to floats, and its principal moments and axes by
numpy.linalg.eigh (symmetric QR; Golub & Van Loan §8.3).

Error estimate: eigh is backward stable, so each moment moves by at most about
3 ε ‖J‖₂ (Weyl): ``absolute_error``, the same for every moment. Relative to each moment,
3 ε ‖J‖₂ / |J_k|, and ``error_estimate`` is the largest of these over the moments that
are not zero within that bound (a rod's moment about its axis, a particle's: their
relative error is undefined; they have the absolute one), None if every one is.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import sympy as sp

from rbdsolve.errors import UnsolvedError
from rbdsolve.model.build import Model
from rbdsolve.model.inertia import parallel_axis
from rbdsolve.problem.options import InertiaOptions
from rbdsolve.problem.schema import Question
from rbdsolve.report.steps import Route, Solution
from rbdsolve.solvers.inertia.answers import NumericInertiaAnswers
from rbdsolve.solvers.inertia.configuration import about_point, at_configuration, substitution
from rbdsolve.solvers.inertia.exact import axis_moment, frame_matrix, in_plane
from rbdsolve.solvers.inertia.steps import numeric_steps
from rbdsolve.solvers.numeric.numeric_model import to_floats
from rbdsolve.solvers.routes.options import Options
from rbdsolve.solvers.routes.needed import require_values

EPS = float(np.finfo(float).eps)


def tensor(opts: InertiaOptions, model: Model, at: dict) -> tuple[sp.Expr, sp.Matrix]:
    """The body's mass and its exact J about the asked point, in the asked axes."""
    body = next(b for b in model.bodies if b.name == opts.body)
    J = body.inertia_in_scene()
    if opts.about is not None:
        J = J + parallel_axis(body.mass, body.position - about_point(opts, model, at))
    if opts.axes is not None:
        A = frame_matrix(opts, model)
        J = A * J * A.T
    return body.mass, J


def principal_floats(J: np.ndarray) -> tuple[np.ndarray, np.ndarray, float]:
    """Moments ascending, unit axes (columns, first nonzero component positive), and the
    bound 3 ε ‖J‖₂ on each moment's absolute error."""
    moments, axes = np.linalg.eigh((J + J.T) / 2)
    for k in range(3):
        first = next(x for x in axes[:, k] if abs(x) > 1e-12)
        axes[:, k] *= np.sign(first)
    axes += 0.0  # no −0.0 in the report
    return moments, axes, float(3 * EPS * np.max(np.abs(moments)))


def relative_estimate(moments: np.ndarray, absolute: float) -> float | None:
    """The largest absolute/|J_k| over the moments larger than ``absolute``; a moment
    within it of zero has no relative error (None if every one is)."""
    return max((absolute / abs(float(m)) for m in moments if abs(m) > absolute), default=None)


def _require_configuration(J: sp.Matrix, model: Model) -> None:
    """A tensor that still moves with the coordinates has no numbers: say which to give."""
    moving = [name for name, q in zip(model.state.names, model.q) if J.has(q)]
    if moving:
        given = ", ".join(f"{name}: …" for name in moving)
        raise UnsolvedError(f"the tensor depends on the configuration ({', '.join(moving)}): "
                            f"give 'at: {{{given}}}' for its numbers")


def solve(question: Question, model: Model, options: Options) -> Solution:
    require_values(model, "the numeric route")
    opts: InertiaOptions = question.options
    at = substitution(opts, model)
    model = at_configuration(model, at)
    mass, J = tensor(opts, model, at)
    _require_configuration(J, model)
    Jf = to_floats(J, model.values)
    J_axis = None
    scene = tensor(replace(opts, axes=None), model, at)[1]
    body = next(b for b in model.bodies if b.name == opts.body)
    if opts.axis is not None:
        _, moment = axis_moment(opts, model, scene)
        J_axis = float(to_floats(sp.Matrix([[moment]]), model.values)[0, 0])
    elif opts.about is not None and in_plane(opts, model, body, about_point(opts, model, at)):
        J_axis = float(to_floats(scene[2:, 2:], model.values)[0, 0])  # about the normal to the plane
    moments, axes, absolute = principal_floats(Jf)
    answers = NumericInertiaAnswers(float(sp.N(mass.xreplace(dict(model.values)))),
                                    tuple(tuple(float(x) for x in row) for row in Jf),
                                    tuple(float(x) for x in moments),
                                    tuple(tuple(float(x) for x in axes[:, k]) for k in range(3)), absolute, J_axis)
    return Solution("inertia", Route.NUMERIC, answers, numeric_steps(Jf, moments, axes), error_estimate=relative_estimate(moments, absolute))
