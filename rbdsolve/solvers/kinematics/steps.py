"""The worked solution of a kinematics question: each point's position in the scene,
its velocity and acceleration by the chain rule, then the state put in; each body's
angular velocity and acceleration."""

from __future__ import annotations

import sympy as sp

from rbdsolve.form.arrange import along_axes, arranged
from rbdsolve.form.display import Math, Relation
from rbdsolve.form.tidy import tidy
from rbdsolve.model.build import Model
from rbdsolve.report import steps as st
from rbdsolve.solvers.kinematics.answers import KinematicsAnswers, NumericKinematicsAnswers


def _row(vector) -> sp.ImmutableMatrix:
    return sp.ImmutableMatrix([list(vector)]).T


def _vector(vector, model: Model) -> Math:
    """Along the scene's axes, each component collected in the rates as Lagrange's
    equations are (q̈, then q̇²…): a_B = (… θ̈ − … θ̇²) eₓ + …"""
    reading = model.reading()
    return along_axes(vector, lambda x: arranged(tidy(x), reading))


def _state_symbol(key: str, model: Model) -> sp.Expr:
    """'dot(theta)' as θ̇, 'theta' as θ: the state's names as the equations show them."""
    s = model.state
    for names, order in ((s.qdd, "ddot({})"), (s.qd, "dot({})"), (s.q, "{}")):
        for name, symbol in zip(s.names, names):
            if key == order.format(name):
                return model.to_time(symbol)
    return sp.Symbol(key)


def exact_steps(answers: KinematicsAnswers, general: dict, model: Model) -> tuple[st.Step, ...]:
    steps = []
    if answers.at:
        steps.append(st.given("The state:", *(Relation(_state_symbol(k, model), v) for k, v in answers.at.items())))
    for name in general:
        r, v, a = (_vector(m, model) for m in general[name])
        steps.append(st.equation(
            f"Point {name}: its position in the scene's axes, and by the chain rule "
            "v = Σ ∂r/∂q q̇ + ∂r/∂t, a = dv/dt:",
            Relation(sp.Symbol(f"r_{name}"), r), Relation(sp.Symbol(f"v_{name}"), v),
            Relation(sp.Symbol(f"a_{name}"), a)))
    for p in answers.points:
        steps.append(st.result(
            f"Point {p.point}" + (" at the state:" if answers.at else ":"),
            Relation(sp.Symbol(f"r_{p.point}"), _row(p.position)),
            Relation(sp.Symbol(f"v_{p.point}"), _row(p.velocity)),
            Relation(sp.Symbol(f"a_{p.point}"), _row(p.acceleration)),
            Relation(sp.Symbol(f"|v_{p.point}|"), p.speed)))
    for d in answers.distances:
        a, b = d.between
        steps.append(st.result(f"The distance {a}{b} = |r_{b} − r_{a}|, and its rate (Δr·Δv)/|Δr|:",
                               Relation(sp.Symbol(f"|{a}{b}|"), d.distance),
                               Relation(sp.Symbol(f"d|{a}{b}|/dt"), d.rate)))
    for b in answers.bodies:
        steps.append(st.result(f"Body {b.body}" + (" at the state" if answers.at else "") + ": its angular velocity "
                               "ω (α̇ e_z for a body turned by its angle α) and angular acceleration α = dω/dt:",
                               Relation(sp.Symbol(f"omega_{b.body}"), _row(b.angular_velocity)),
                               Relation(sp.Symbol(f"alpha_{b.body}"), _row(b.angular_acceleration))))
    for x in answers.lines:
        a, b = x.through
        steps.append(st.result(f"The line {a}{b} turns at φ̇ = (Δr × Δv)_z/|Δr|² (Δr = r_{b} − r_{a}, φ its angle), "
                               "with angular acceleration φ̈ = dφ̇/dt:",
                               Relation(sp.Symbol(f"omega_{a}{b}"), x.rate),
                               Relation(sp.Symbol(f"alpha_{a}{b}"), x.acceleration)))
    return tuple(steps)


def numeric_steps(answers: NumericKinematicsAnswers) -> tuple[st.Step, ...]:
    def show(x):
        return sp.nan if x is None else sp.Float(x, 15)

    steps = [st.result(f"Point {p.point} at the parameter values (floating point):",
                       Relation(sp.Symbol(f"r_{p.point}"), _row(map(show, p.position))),
                       Relation(sp.Symbol(f"v_{p.point}"), _row(map(show, p.velocity))),
                       Relation(sp.Symbol(f"a_{p.point}"), _row(map(show, p.acceleration))))
             for p in answers.points]
    steps += [st.result(f"The distance {d.between[0]}{d.between[1]}:",
                        Relation(sp.Symbol(f"|{d.between[0]}{d.between[1]}|"), show(d.distance)))
              for d in answers.distances]
    steps += [st.result(f"Body {b.body} at the parameter values (floating point):",
                        Relation(sp.Symbol(f"omega_{b.body}"), _row(map(show, b.angular_velocity))),
                        Relation(sp.Symbol(f"alpha_{b.body}"), _row(map(show, b.angular_acceleration))))
              for b in answers.bodies]
    steps += [st.result(f"The line {x.through[0]}{x.through[1]} at the parameter values (floating point):",
                        Relation(sp.Symbol(f"omega_{x.through[0]}{x.through[1]}"), show(x.rate)),
                        Relation(sp.Symbol(f"alpha_{x.through[0]}{x.through[1]}"), show(x.acceleration)))
              for x in answers.lines]
    return tuple(steps)
