"""The applied loads' work in the energy question, against the work by hand: a pendulum
turned by a constant couple M0 (W = M0 θ) from rest hanging, and the speed the energy
gives at θ = π/2."""

from __future__ import annotations

import json

import sympy as sp

from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.render.json import report_object
from rbdsolve.solvers import solve_problem

from conftest import positive_names

TURNED = """\
parameters: {m: mass, l: length, g: gravity, M0: couple}
coordinates: [theta]
gravity: [0, -g]
points: {O: [0, 0]}
bodies:
  rod: {shape: rod, mass: m, length: l, at: "l/2*[sin(theta), -cos(theta)]", angle: theta, axis: y,
        points: {B: [0, -l/2]}}
couples:
  drive: {on: rod, moment: M0}
questions:
  - energy: {from_rest: {theta: 0}, to: {theta: pi/2}, points: [B]}
"""


def test_a_couple_s_work_and_the_speed_it_gives() -> None:
    """(m l²/6) θ̇² = M0 θ − (m g l/2)(1 − cos θ); at θ = π/2: θ̇² = 3 (π M0 − m g l)/(m l²),
    and the rod's end B moves at l θ̇."""
    (result,) = json.loads(json.dumps(report_object(solve_problem(build_model(load_text(TURNED, "p.yaml"))))))[
        "results"]
    answers = result["answers"]
    m, l, g, M0 = sp.symbols("m l g M0", positive=True)
    theta = sp.Function("theta")(sp.Symbol("t", real=True))
    names = {**positive_names("m*l*g*M0"), "theta": sp.Function("theta")}
    assert sp.simplify(sp.sympify(answers["work"]["drive"], locals=names) - M0 * theta) == 0
    there = answers["there"]
    assert sp.simplify(sp.sympify(there["work"]["drive"], locals=names) - M0 * sp.pi / 2) == 0
    rate2 = 3 * (sp.pi * M0 - m * g * l) / (m * l**2)
    assert sp.simplify(sp.sympify(there["rate_squared"]["theta"], locals=names) - rate2) == 0
    assert sp.simplify(sp.sympify(there["speed"]["B"], locals=names) ** 2 - l**2 * rate2) == 0
