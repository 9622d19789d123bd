"""A solid ball rolling off a fixed drum, released from rest at θ₀, with only θ₀ given
(m, r, R and g open: a new user's trial). By hand, θ from the upward vertical, the
ball's centre on a circle of radius R + r, T = (7/10) m (R + r)² θ̇²:

    θ̇² = 10 g (cos θ₀ − cos θ)/(7 (R + r)),   N = m g cos θ − m (R + r) θ̇²
       = (1/7) m g (17 cos θ − 10 cos θ₀),

so the ball leaves the drum where cos θ = (10/17) cos θ₀, whatever m, r, R and g: at
θ₀ = 20°, θ = acos(10/17 cos 20°) = 0.985123 rad (56.4434°). rbdsolve gave no number
there, since 1/(R + r) was not taken for the positive factor it is.

Released at θ₀ = 100°, N = m g cos θ₀ < 0 at once: the ball leaves the drum, and no
coefficient of friction keeps it rolling. rbdsolve printed μ ≥ |F|/N = 1.62 there, with
no warning, because m and g had no values."""

from __future__ import annotations

import math

import pytest

from conftest import solved_scene

BALL = """\
parameters: [m, r, R, theta0, g]
values: {theta0: THETA0 deg}
coordinates: [theta]
gravity: [0, -g]
points:
  O: [0, 0]
bodies:
  ball: {shape: sphere, mass: m, radius: r}
contacts:
  C: {body: ball, rolls_on: {circle: {centre: O, radius: R, side: outside}}, along: theta}
questions:
  - reactions: {forces: [C], from_rest: {theta: theta0}}
"""


def _solved(tmp_path, degrees: int):
    return solved_scene(tmp_path, BALL.replace("THETA0", str(degrees)), "ball.yaml")


def test_the_ball_leaves_the_drum_at_a_number_when_only_the_release_is_given(tmp_path) -> None:
    solution = _solved(tmp_path, 20)
    expected = math.acos(10 / 17 * math.cos(math.radians(20)))
    assert solution.answers.first_zero["N_C"].lost_at["theta"] == pytest.approx(expected, abs=1e-9)
    assert solution.values["least_friction_at"]["C"] == pytest.approx(2 / 7 * math.tan(math.radians(20)), rel=1e-12)


def test_released_past_the_side_it_leaves_at_once_whatever_the_open_scales(tmp_path) -> None:
    solution = _solved(tmp_path, 100)
    (said,) = [w for w in solution.warnings if "at the state asked" in w]
    assert said.startswith(f"N_C = {math.cos(math.radians(100)):.6g} g m < 0".replace("-", "−"))
    assert "leaves it at once" in said
    assert not (solution.answers.least_friction_at or {}).get("C")
    assert not solution.answers.first_zero
