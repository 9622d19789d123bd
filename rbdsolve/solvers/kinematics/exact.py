"""A point's kinematics, the exact route: from its position r(q, t) in the scene,

    v = dr/dt = Σ ∂r/∂q_j q̇_j + ∂r/∂t,     a = dv/dt,     |v| = √(v·v),

then the state of the question put in (q, q̇, q̈ as given; the rest stays symbolic).
A distance between two points is d = |r_B − r_A| = √(Δr·Δr), its rate ḋ = (Δr·Δv)/d.
A body's angular velocity is ω = α̇ e_z for a planar body turned by its angle α(q, t)
(in 3D, from its rotation: model/build.py), its angular acceleration dω/dt. The line
through A and B turns at φ̇ = (Δr × Δv)_z/(Δr·Δr) (φ the angle of Δr = r_B − r_A), and
φ̈ = [(Δr × Δa)_z (Δr·Δr) − 2 (Δr × Δv)_z (Δr·Δv)]/(Δr·Δr)².
"""

from __future__ import annotations

from typing import Mapping

import sympy as sp

from rbdsolve.errors import UnsolvedError
from rbdsolve.form.roots import over_one_root
from rbdsolve.form.tidy import has_root, tidy
from rbdsolve.form.zero import simplifies_to_zero
from rbdsolve.model.build import Model
from rbdsolve.problem.options import KinematicsOptions
from rbdsolve.problem.schema import Question
from rbdsolve.report.steps import Route, Solution
from rbdsolve.solvers.kinematics.answers import BodyMotion, Distance, KinematicsAnswers, LineTurning, PointMotion
from rbdsolve.solvers.kinematics.steps import exact_steps
from rbdsolve.solvers.routes.options import Options

RATE_NAMES = {0: "{}", 1: "dot({})", 2: "ddot({})"}


def solve(question: Question, model: Model, options: Options) -> Solution:
    answers, general = kinematics(question.options, model)
    return Solution("kinematics", Route.EXACT, answers, exact_steps(answers, general, model))


def kinematics(opts: KinematicsOptions, model: Model,
               values: Mapping[sp.Symbol, sp.Expr] | None = None) -> tuple[KinematicsAnswers, dict]:
    """The answers at the state, and each point's r, v, a in general (for the steps);
    with ``values`` (the floating-point route), the parameters' values put in with the
    state, before anything is expanded or tidied: a four-bar's B, where two circles meet,
    is a root of the lengths whose second derivative, written out in them, took minutes."""
    put = dict(values or {})
    state = {**{k: v.xreplace(put) for k, v in state_values(opts, model).items()}, **put}  # (θ = θ₁, θ₁ = π/2)
    general = {name: motion(name, model) for name in asked_points(opts)}
    at = {RATE_NAMES[sv.order].format(sv.coordinate): value
          for sv, value in zip(opts.at, (model.symbols.scalar(sv.value) for sv in opts.at))}
    points = tuple(_at_state(name, general[name], state, model) for name in opts.points)
    distances = tuple(_distance(a, b, general, state, model) for a, b in opts.distances)
    bodies = tuple(_turning(name, state, model) for name in opts.bodies)
    lines = tuple(_line(a, b, general, state, model) for a, b in opts.lines)
    return KinematicsAnswers(at, points, distances, bodies, lines), general


ROOT_OPS = 40  # a point past this size with a root of the coordinates: its exact acceleration takes minutes


def partial(question, model: Model) -> str | None:
    """The route choice's check (solvers/routes/routes.py), from the structure: a point
    asked whose position holds a root of the coordinates and is long (a four-bar's B,
    where two circles meet, 144 operations: its second derivative written out in the
    lengths took the whole budget), so the floating-point route answers, the values put
    in first. A slider-crank's B (11 operations) stays exact."""
    for name in asked_points(question.options):
        if not model.has_point(name) or not has_root(r := model.point(name), tuple(model.q)):
            continue
        size = sum(sp.count_ops(x) for x in r)
        if size > ROOT_OPS:
            return (f"point '{name}' is placed by a root of the coordinates ({size} operations long), so its "
                    "exact acceleration would take minutes to write out")
    return None


def asked_points(opts: KinematicsOptions) -> tuple[str, ...]:
    """The points the question names, each once: those asked, the ends of the distances
    and the points the lines go through."""
    return tuple(dict.fromkeys([*opts.points, *(p for pair in (*opts.distances, *opts.lines) for p in pair)]))


def state_values(opts: KinematicsOptions, model: Model) -> dict[sp.Symbol, sp.Expr]:
    """q, q̇, q̈ -> their values in the question's ``at``."""
    s = model.state
    index = {name: k for k, name in enumerate(s.names)}
    table = (s.q, s.qd, s.qdd)
    return {table[sv.order][index[sv.coordinate]]: model.symbols.scalar(sv.value) for sv in opts.at}


def motion(name: str, model: Model) -> tuple[sp.Matrix, sp.Matrix, sp.Matrix]:
    """r, v, a of a point in general (functions of q, q̇, q̈ and t)."""
    if not model.has_point(name):
        raise UnsolvedError(f"point '{name}' has no position (it is given by its velocity at one instant)")
    r = model.point(name)
    v = model.state.d_dt(r)
    return r, v, model.state.d_dt(v)


def _vector(m: sp.Matrix, state: dict, model: Model) -> tuple[sp.Expr, sp.Expr, sp.Expr]:
    """Each component at the state, tidied, one square root's terms over one denominator."""
    return tuple(model.to_time(over_one_root(tidy(sp.expand(x.xreplace(state))))) for x in m)  # type: ignore[return-value]


def _square(m: sp.Matrix, state: dict) -> sp.Expr:
    """m·m at the state, tidied (sin² + cos² = 1) so that √(l²) is l."""
    return tidy(sp.expand(m.dot(m).xreplace(state)))


def _norm(m: sp.Matrix, state: dict) -> sp.Expr:
    """√(m·m), the square tidied first."""
    return sp.sqrt(_square(m, state))


def _at_state(name: str, rva, state: dict, model: Model) -> PointMotion:
    r, v, a = rva
    return PointMotion(name, _vector(r, state, model), _vector(v, state, model), _vector(a, state, model),
                       model.to_time(_speed(v, state)))


def _speed(v: sp.Matrix, state: dict) -> sp.Expr:
    """|v| = √(v·v), the square tidied and, where it holds one root, over one denominator."""
    return sp.sqrt(over_one_root(_square(v, state)))


def _turning(name: str, state: dict, model: Model) -> BodyMotion:
    """ω and α = dω/dt of a body, at the state."""
    w = next(b for b in model.bodies if b.name == name).angular_velocity(model.state)
    return BodyMotion(name, _vector(w, state, model), _vector(model.state.d_dt(w), state, model))


def _line(a: str, b: str, general: dict, state: dict, model: Model) -> LineTurning:
    """φ̇ and φ̈ of the line from A to B (the module's formulas), at the state; in the
    x-y plane only (a line in space turns about no one axis)."""
    if not all(simplifies_to_zero(general[p][0][2]) for p in (a, b)):
        raise UnsolvedError(f"the line {a}{b} leaves the x-y plane: its turning is answered for points in the plane "
                            "(a line in space turns about no one axis; ask a body's angular velocity, 'bodies:')")
    dr, dv, da = (general[b][k] - general[a][k] for k in range(3))
    square, turn = dr.dot(dr), dr.cross(dv)[2]  # the points are 3-vectors with z = 0
    rate = turn / square
    acceleration = (dr.cross(da)[2] * square - 2 * turn * dr.dot(dv)) / square**2
    return LineTurning((a, b), *(model.to_time(tidy(sp.cancel(sp.expand(x.xreplace(state)))))
                                 for x in (rate, acceleration)))


def _distance(a: str, b: str, general: dict, state: dict, model: Model) -> Distance:
    dr = general[b][0] - general[a][0]
    dv = general[b][1] - general[a][1]
    d = _norm(dr, state)
    rate = tidy(sp.expand(dr.dot(dv).xreplace(state))) / d if d != 0 else sp.nan
    return Distance((a, b), model.to_time(tidy(d)), model.to_time(tidy(rate)))
