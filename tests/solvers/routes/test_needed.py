"""Which values a route needs: the applied loads count. A couple M₀ or a force P left
without a value was filled with 1 on the numeric route (a new user's trial: a ladder
pushed by P gave the forces for P = 1 N, exit 0), since the parameters the answer
depends on were read from T, V and the question, not from the loads.

By hand, a uniform disk (m, r) rolling up an incline α driven by a couple M₀ the way it
rolls: (3/2) m ẍ = M₀/r − m g sin α."""

from __future__ import annotations

import math

import pytest
import sympy as sp

from conftest import PROBLEMS
from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.solvers import solve_problem
from rbdsolve.solvers.routes.options import Options, RouteChoice

WHEEL = (PROBLEMS / "forces" / "wheel-driven-by-couple.yaml").read_text(encoding="utf-8")
PUSHED = """\
parameters: {m: mass, P: push, g: gravity}
values: {m: 2, g: 9.81}
coordinates: [x]
gravity: [0, -g]
points:
  G: [x, 0]
bodies:
  block: {shape: particle, mass: m, at: G}
forces:
  push: {at: G, on: block, force: [P, 0]}
questions:
  - eom
"""


def _numeric(text: str, values: str):
    text = text.replace("coordinates:", f"values: {{{values}}}\ncoordinates:", 1) if values else text
    return solve_problem(build_model(load_text(text, "scene.yaml")), Options(route=RouteChoice.NUMERIC)).solutions


@pytest.mark.parametrize("text, values, missing", [(WHEEL, "m: 1, r: 1, alpha: 0.3, g: 9.81", "M0"),
                                                    (PUSHED, "", "P")])
def test_a_load_left_without_a_value_is_named_not_filled(text: str, values: str, missing: str) -> None:
    for solution in _numeric(text, values):
        assert solution.error is not None and f"give {missing} " in solution.error


def test_with_the_couple_given_the_numeric_acceleration_is_the_hand_one() -> None:
    eom = _numeric(WHEEL, "m: 1, r: 1, alpha: 0.3, g: 9.81, M0: 5")[0]
    assert eom.error is None
    (equation,) = eom.answers.equations
    (xdd,) = [d for d in equation.atoms(sp.Derivative) if d.derivative_count == 2]
    (acceleration,) = sp.solve(equation, xdd)
    assert float(acceleration) == pytest.approx(2 / 3 * (5 - 9.81 * math.sin(0.3)), rel=1e-12)
