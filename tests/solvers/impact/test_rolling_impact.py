"""A body rolling on a plane through an impact (problems/contacts/ball-struck-on-table):
the laws the answer must obey rather than its formula — the ball's point at C is at rest
just after, the table's impulse lies in the table, and the momentum and the angular
momentum about C change by the cue's impulse and its moment alone (the table's impulse
acts at C) — and the steps a worked solution shows."""

from __future__ import annotations

import pytest
import sympy as sp

from rbdsolve.model.build import build_model
from rbdsolve.problem import load_file
from rbdsolve.solvers import solve_problem

from conftest import PROBLEMS

BALL = PROBLEMS / "contacts" / "ball-struck-on-table.yaml"


@pytest.fixture(scope="module")
def solved():
    model = build_model(load_file(BALL))
    (solution,) = solve_problem(model).solutions
    assert solution.error is None, solution.error
    return model, solution


def test_the_ball_rolls_just_after_and_the_table_pushes_along_itself(solved) -> None:
    model, solution = solved
    p = model.symbols.parameters
    m, r, h, P = (p[k] for k in ("m", "r", "h", "P"))
    v = {n: solution.answers.velocities[n] for n in ("x", "y", "a", "b", "c")}
    omega = sp.Matrix([v["a"], v["b"], v["c"]])  # the turns' rates at a = b = c = 0
    velocity = sp.Matrix([v["x"], v["y"], 0])
    assert sp.simplify(velocity + omega.cross(sp.Matrix([0, 0, -r]))) == sp.zeros(3, 1)  # v_C = 0
    F = sp.Matrix(solution.answers.sticking_impulses["C"])
    assert F[2] == 0
    assert sp.simplify(m * velocity - (sp.Matrix([P, 0, 0]) + F)) == sp.zeros(3, 1)  # momentum
    # angular momentum about C: (2/5) m r² ω + r_CG × m v = r_CQ × P (F has no moment about C)
    L_C = sp.Rational(2, 5) * m * r**2 * omega + sp.Matrix([0, 0, r]).cross(m * velocity)
    assert sp.simplify(L_C - sp.Matrix([0, 0, r + h]).cross(sp.Matrix([P, 0, 0]))) == sp.zeros(3, 1)


def test_the_solution_shows_the_rolling_condition_and_the_table_s_impulse(solved) -> None:
    _, solution = solved
    texts = [step.text for step in solution.steps]
    assert any(x.startswith("Rolling without slipping on the plane goes on") for x in texts)
    assert any(x.startswith("The impulse of the plane, along it, at each rolling contact") for x in texts)
