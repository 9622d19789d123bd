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
from rbdsolve.model.frames import frame_lagrangian, frame_motion
from rbdsolve.model.tidy import collect_in, tidy
from rbdsolve.problem.schema import Question
from rbdsolve.report import steps as st
from rbdsolve.report.math import Terms
from rbdsolve.report.steps import Relation, Route, Solution
from rbdsolve.solvers.common import Options, subscript
from rbdsolve.solvers.energies import present
from rbdsolve.solvers.singular import eom_warnings


@dataclass(frozen=True)
class FrameAnswers:
    frame: str
    lagrangian: sp.Expr  # L' in the frame
    equations: tuple[sp.Expr, ...]  # its Lagrange's equations, each = 0
    total_derivative: sp.Expr  # F with L − L' = dF/dt
    equivalent: bool  # the equations agree with the scene's and L − L' − dF/dt = 0


@dataclass(frozen=True)
class EomAnswers:
    equations: tuple[sp.Expr, ...]  # each expression = 0, one per coordinate
    frames: tuple[FrameAnswers, ...] = ()  # the frames asked for
    equivalent: bool | None = None  # every frame agrees (None: no frames asked)
    total_derivative: sp.Expr | None = None  # F of the first frame asked


def lagrange_equations(model: Model, L: sp.Expr | None = None) -> tuple[sp.Expr, ...]:
    """E_i = d/dt(∂L/∂q̇_i) − ∂L/∂q_i for each coordinate, in the model's plain symbols;
    L = T − V unless given."""
    if L is None:
        L = kinetic_energy(model).total - potential_energy(model).total
    generators = [*model.qdd, *model.qd]
    out = []
    for q, qd in zip(model.q, model.qd):
        E = model.state.d_dt(sp.diff(L, qd)) - sp.diff(L, q)
        out.append(sp.Add(*[c * m for m, c in collect_in(E, generators).items()]))
    return tuple(out)


def solve(question: Question, model: Model, options: Options) -> Solution:
    equations = lagrange_equations(model)
    steps = [
        st.result(
            "Lagrange's equations, d/dt(∂L/∂q̇) − ∂L/∂q = 0 with L = T − V, one for each "
            "coordinate in turn:",
            *[Relation(_present(E, model), sp.Integer(0)) for E in equations],
        ),
    ]
    names = question.options.frames if question.options else ()
    frames = []
    for name in names:
        answer, frame_steps = _in_frame(model, model.problem.frame(name), equations)
        frames.append(answer)
        steps += frame_steps
    answers = EomAnswers(
        tuple(model.to_time(E) for E in equations),
        tuple(frames),
        all(f.equivalent for f in frames) if frames else None,
        frames[0].total_derivative if frames else None,
    )
    return Solution("eom", Route.EXACT, answers, tuple(steps), warnings=eom_warnings(model))


def _in_frame(model: Model, frame, equations: tuple[sp.Expr, ...]) -> tuple[FrameAnswers, list[st.Step]]:
    """L' in the frame, its equations, and the two checks: the same equations, and
    L − L' = dF/dt."""
    seen = frame_lagrangian(model, frame_motion(model, frame))
    primed = lagrange_equations(model, seen.L)
    agree = all(_vanishes(a - b) for a, b in zip(primed, equations))
    L = kinetic_energy(model).total - potential_energy(model).total
    derivative = _vanishes(L - seen.L - model.state.d_dt(seen.F))
    answer = FrameAnswers(frame.name, model.to_time(seen.L), tuple(model.to_time(E) for E in primed),
                          model.to_time(seen.F), agree and derivative)
    return answer, _frame_steps(model, frame, seen, primed, agree, derivative)


def _vanishes(expr: sp.Expr) -> bool:
    """Exactly zero: expanded, then tidied, then (small expressions only) simplified."""
    expr = tidy(sp.expand(expr))
    return expr == 0 or (sp.count_ops(expr) < 400 and sp.simplify(expr) == 0)


def _frame_steps(model: Model, frame, seen, primed, agree: bool, derivative: bool) -> list[st.Step]:
    def rows(terms, name):
        return [Relation(sp.Symbol(f"{name}_{i}"), present(x.value, model)) for i, x in enumerate(terms, start=1)]

    legend_T = ", ".join(f"T'{subscript(i)} {x.name}" for i, x in enumerate(seen.kinetic, start=1))
    legend_V = ", ".join(f"V'{subscript(i)} {x.name}" for i, x in enumerate(seen.potential, start=1))
    F = Relation(sp.Symbol("F"), model.to_time(seen.F))
    checks = "They are the same equations" if agree else "rbdsolve could not simplify the difference of the equations to 0"
    checks += ", and L − L' = dF/dt" if derivative else "; L − L' − dF/dt did not simplify to 0"
    return [
        st.definition(f"In frame {frame.name} (positions r' = Rᵀ (r − r_O)): kinetic parts; {legend_T}:",
                      *rows(seen.kinetic, "T'")),
        st.definition(f"Potentials, gravity and the inertial forces included; {legend_V}:",
                      *rows(seen.potential, "V'")),
        st.equation(f"The Lagrangian in frame {frame.name}:", Relation(sp.Symbol("L'"), present(seen.L, model))),
        st.result(f"Lagrange's equations in frame {frame.name}:",
                  *[Relation(_present(E, model), sp.Integer(0)) for E in primed]),
        st.result(f"{checks}, with", F) if derivative else st.note(f"{checks}.", F),
    ]


def _present(E: sp.Expr, model: Model):
    """Inertia terms (with q̈ or q̇) and the rest, each with its own scale pulled out."""
    parts = collect_in(E, [*model.qdd, *model.qd], tidied=True)
    moving = sp.Add(*[c * m for m, c in parts.items() if m != 1])
    still = parts.get(sp.Integer(1), sp.Integer(0))
    groups = [present(moving, model)] if moving != 0 else []
    if still != 0:
        groups.append(_factored(still, model))
    return groups[0] if len(groups) == 1 else Terms(tuple(groups))


def _factored(expr: sp.Expr, model: Model):
    """m l (g + ÿ_A) sin φ rather than m l [g sin φ + sin φ ÿ_A], when shorter."""
    common = sp.factor_terms(sp.expand(expr))
    pulled = [f for f in sp.Mul.make_args(common) if not f.is_Add]
    if len(pulled) < len(sp.Mul.make_args(common)) and any(f.has(*model.q) for f in pulled):
        return model.to_time(common)
    return present(expr, model)
