"""The names the kinematics' worked solution prints its answers by (report/numbers.py):
the state (θ, θ̇, θ̈), each point's r_P, v_P, a_P and |v_P|, each distance |AB| and its
rate d|AB|/dt, each body's ω and α."""

from __future__ import annotations

import sympy as sp

from rbdsolve.model.build import Model
from rbdsolve.report.numbers import Named
from rbdsolve.solvers.routes.naming import coordinate


def named(question, answers, model: Model) -> tuple[Named, ...]:
    out = [Named(("at", k), coordinate(model, k)) for k in answers.at]
    for i, p in enumerate(answers.points):
        out += [Named(("points", i, "position"), sp.Symbol(f"r_{p.point}")),
                Named(("points", i, "velocity"), sp.Symbol(f"v_{p.point}")),
                Named(("points", i, "acceleration"), sp.Symbol(f"a_{p.point}")),
                Named(("points", i, "speed"), sp.Symbol(f"|v_{p.point}|"))]
    for i, d in enumerate(answers.distances):
        a, b = d.between
        out += [Named(("distances", i, "distance"), sp.Symbol(f"|{a}{b}|")),
                Named(("distances", i, "rate"), sp.Symbol(f"d|{a}{b}|/dt"))]
    for i, b in enumerate(answers.bodies):
        out += [Named(("bodies", i, "angular_velocity"), sp.Symbol(f"omega_{b.body}")),
                Named(("bodies", i, "angular_acceleration"), sp.Symbol(f"alpha_{b.body}"))]
    for i, x in enumerate(answers.lines):
        a, b = x.through
        out += [Named(("lines", i, "rate"), sp.Symbol(f"omega_{a}{b}")),
                Named(("lines", i, "acceleration"), sp.Symbol(f"alpha_{a}{b}"))]
    return tuple(out)
