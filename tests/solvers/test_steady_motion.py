"""Steady motion and steady spin at their edges: what is refused, and what another
body in the scene does not change. Expected values are the seed's (problem 3)."""

from __future__ import annotations

import pytest
import sympy as sp

from conftest import PROBLEMS
from rbdsolve.errors import InputError
from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.solvers import solve_problem

RING = (PROBLEMS / "sg2150-2015-10-29" / "p3-rolling-ring.yaml").read_text(encoding="utf-8")
g, R, r, theta = sp.symbols("g R r theta", positive=True)
SEED = 2 * g * sp.sin(theta) / (sp.cos(theta) * (4 * R + r * sp.sin(theta)))


def solve(text: str):
    return solve_problem(build_model(load_text(text, "scene.yaml"))).solutions[0]


def test_another_body_does_not_change_the_ring_s_balance() -> None:
    text = RING.replace("bodies:\n", "bodies:\n  bob: {shape: particle, mass: m, at: G + r*e2}\n").replace(
        "{about: C, rolling_at: C,", "{about: C, rolling_at: C, body: ring,")
    solution = solve(text)
    assert solution.error is None, solution.error
    (value,) = solution.answers.solved.values()
    assert sp.simplify(value - SEED) == 0


@pytest.mark.parametrize(
    "old, new, words",
    [
        ("{about: C, rolling_at: C,", "{about: G, rolling_at: C,", "take moments about that point"),
        ("gravity: [0, 0, -g]", "gravity: [0, -g, 0]", "not a steady motion"),
    ],
)
def test_what_steady_motion_refuses(old, new, words) -> None:
    solution = solve(RING.replace(old, new))
    assert solution.error is not None and words in solution.error


def test_a_body_given_by_its_velocity_has_no_steady_motion() -> None:
    text = RING.replace("ring: {shape: ring, mass: m, radius: r, at: G, axis: x, orientation: [T, [x, spin*t]]}",
                        "ring: {shape: ring, mass: m, radius: r, velocity: [R*omega0, 0, 0], "
                        "angular_velocity: [0, 0, omega0]}")
    with pytest.raises(InputError, match="needs the position of body 'ring'"):
        load_text(text, "scene.yaml")


def test_steady_spin_needs_three_positive_moments() -> None:
    text = """
parameters: {m: mass, l: length}
bodies:
  rod: {shape: rod, mass: m, length: l, at: [0, 0, 0]}
questions: [steady_spin]
"""
    solution = solve(text)
    assert solution.error is not None and "zero principal moment" in solution.error
