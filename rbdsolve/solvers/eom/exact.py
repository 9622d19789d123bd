"""Lagrange's equations.

    d/dt (∂L/∂q̇_i) − ∂L/∂q_i = 0,   L = T − V           (e.g. Goldstein, ch. 1)

with the total time derivative written out by the chain rule,

    d/dt (∂L/∂q̇_i) = Σ_j (∂²L/∂q̇_i∂q̇_j q̈_j + ∂²L/∂q̇_i∂q_j q̇_j) + ∂²L/∂q̇_i∂t.

Each equation is an expression = 0, collected in q̈ and q̇ with each coefficient tidied,
and shown with the scales pulled out: the inertia part m r² […] and the potential part
m g r […], as an exam solution writes it.
"""

from __future__ import annotations

import sympy as sp

from rbdsolve.form.tidy import collect_in, tidy
from rbdsolve.model.build import Model
from rbdsolve.model.derivative import derivative
from rbdsolve.model.energies.energy import kinetic_energy, memoized, potential_energy
from rbdsolve.model.energies.loads import free_forces
from rbdsolve.problem.schema import Question
from rbdsolve.report import steps as st
from rbdsolve.report.steps import Route, Solution
from rbdsolve.solvers.eom.answers import EomAnswers, FrameAnswers
from rbdsolve.solvers.eom.steps import frame_steps, instant_steps, lagrange_step, singular_step, solved_step
from rbdsolve.solvers.lagrange.accelerations import Accelerations, accelerations, at_state, state_values
from rbdsolve.solvers.lagrange.frames import refuse_loads_in_frame
from rbdsolve.solvers.routes.options import Options
from rbdsolve.solvers.configuration.singular import eom_warnings
from rbdsolve.form.zero import simplifies_to_zero


def lagrange_equations(model: Model, L: sp.Expr | None = None) -> tuple[sp.Expr, ...]:
    """E_i = d/dt(∂L/∂q̇_i) − ∂L/∂q_i − Q_i for each coordinate, in the model's plain
    symbols; L = T − V unless given, Q_i the generalized forces of the applied loads that
    have no potential (model/energies/loads.py; the others are in V)."""
    return _own_equations(model) if L is None else _equations(model, L)


@memoized  # the reactions' route and their check before printing both ask
def _own_equations(model: Model) -> tuple[sp.Expr, ...]:
    return _equations(model, kinetic_energy(model).total - potential_energy(model).total)


@memoized  # the equations of motion, the reactions and the energy's check on the way each need q̈
def general_accelerations(model: Model) -> Accelerations:
    """q̈ = −M⁻¹ h from the model's own Lagrange equations, no state put in
    (``accelerations``), once per model."""
    return accelerations(lagrange_equations(model), model)


def _equations(model: Model, L: sp.Expr) -> tuple[sp.Expr, ...]:
    Q = free_forces(model) or (0,) * len(model.q)
    generators = [*model.qdd, *model.qd]
    out = []
    for q, qd, Qi in zip(model.q, model.qd, Q):
        E = model.state.d_dt(derivative(L, qd)) - derivative(L, q) - Qi
        out.append(sp.Add(*[c * m for m, c in collect_in(E, generators).items()]))
    return tuple(out)


def solve(question: Question, model: Model, options: Options) -> Solution:
    equations = lagrange_equations(model)
    steps = [lagrange_step(equations, model)]
    names = question.options.frames if question.options else ()
    frames = []
    for name in names:
        answer, frame_steps = _in_frame(model, model.problem.frame(name), equations)
        frames.append(answer)
        steps += frame_steps
    solved, at, acceleration_steps, M = _accelerations(question, model, equations)
    answers = EomAnswers(
        tuple(model.to_time(E) for E in equations),
        tuple(frames),
        all(f.equivalent for f in frames) if frames else None,
        frames[0].total_derivative if frames else None,
        solved,
        at,
    )
    steps[1:1] = acceleration_steps  # right after Lagrange's equations, before the frames
    return Solution("eom", Route.EXACT, answers, tuple(steps), warnings=eom_warnings(model, M))


def _accelerations(question: Question, model: Model, equations):
    """q̈ = −M⁻¹ h, and at the state asked for (``at:``, ``from_rest:``), with its steps;
    and M(q) = ∂E/∂q̈. ``equations`` are the model's own (``lagrange_equations``)."""
    found = general_accelerations(model)
    names = model.coordinate_names()
    steps = [solved_step(found.solved, model)] if found.solved is not None else [singular_step(found)]
    solved = {n: model.to_time(a) for n, a in zip(names, found.solved)} if found.solved is not None else None
    instant = question.options.instant if question.options else None
    if instant is None:
        return solved, None, steps, found.M
    there = accelerations(equations, model, state_values(model, instant))
    if there.solved is None:
        return solved, None, steps + [singular_step(there)], found.M
    at = tuple(at_state(a, {}) for a in there.solved)
    steps += instant_steps(instant, at, model)
    return solved, dict(zip(names, at)), steps, found.M


def _in_frame(model: Model, frame, equations: tuple[sp.Expr, ...]) -> tuple[FrameAnswers, list[st.Step]]:
    """L' in the frame, its equations, and the two checks: the same equations, and
    L − L' = dF/dt."""
    refuse_loads_in_frame(model, frame.name)
    # a frame's machinery, loaded only where a frame is asked
    from rbdsolve.model.energies.frames import frame_lagrangian, frame_motion

    seen = frame_lagrangian(model, frame_motion(model, frame))
    primed = lagrange_equations(model, seen.L)
    agree = all(_vanishes(a - b) for a, b in zip(primed, equations))
    L = kinetic_energy(model).total - potential_energy(model).total
    derivative = _vanishes(L - seen.L - model.state.d_dt(seen.F))
    answer = FrameAnswers(frame.name, model.to_time(seen.L), tuple(model.to_time(E) for E in primed),
                          model.to_time(seen.F), agree and derivative)
    return answer, frame_steps(model, frame, seen, primed, agree, derivative)


def _vanishes(expr: sp.Expr) -> bool:
    """Exactly zero: expanded, then tidied, then (small expressions only) simplified."""
    expr = tidy(sp.expand(expr))
    return expr == 0 or (sp.count_ops(expr) < 400 and simplifies_to_zero(expr))
