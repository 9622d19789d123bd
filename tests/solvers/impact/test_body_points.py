"""An impulse at a point of a body's own (``points:`` under the body): a rod hanging
from a pivot struck at the distance d below it; by hand the pivot feels no impulse
when d = 2l/3 (the centre of percussion: P d = J_O θ̇ and P = m (l/2) θ̇)."""

from __future__ import annotations

import json

import sympy as sp

from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.render.json import report_object
from rbdsolve.solvers import solve_problem

from conftest import positive_names

STRUCK = """\
parameters: {m: mass, l: length, d: where it is struck, P: impulse}
coordinates: [theta]
points: {O: [0, 0]}
bodies:
  rod: {shape: rod, mass: m, length: l, at: "l/2*[sin(theta), -cos(theta)]", angle: theta, axis: y,
        points: {B: [0, l/2 - d]}}
questions:
  - impact: {at: {theta: 0}, impulses: {B: [P, 0]}, centre_of_percussion: d}
  - kinematics: {points: [B], at: {theta: 0, dot(theta): 1}}
"""


def test_a_rod_struck_at_its_own_point() -> None:
    impact, kinematics = json.loads(json.dumps(report_object(solve_problem(build_model(load_text(STRUCK, "p.yaml"))))))[
        "results"]
    assert impact["ok"], impact["error"]
    names = positive_names("m*l*d*P")
    rate = sp.sympify(impact["answers"]["velocities"]["theta"], locals=names)
    m, l, d, P = (names[n] for n in ("m", "l", "d", "P"))
    assert sp.simplify(rate - 3 * P * d / (m * l**2)) == 0  # (m l²/3) θ̇ = P d
    assert sp.simplify(sp.sympify(impact["answers"]["centre_of_percussion"], locals=names) - 2 * l / 3) == 0
    velocity = kinematics["answers"]["points"][0]["velocity"]
    assert sp.simplify(sp.sympify(velocity[0], locals=names) - d) == 0  # B moves at d θ̇ along x
