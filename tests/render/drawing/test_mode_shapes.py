"""Mode shapes to draw, against hand-derived eigenvectors."""

from __future__ import annotations

import math
from fractions import Fraction

import pytest

from rbdsolve.model.build import build_model
from rbdsolve.problem import load_file
from rbdsolve.render.drawing.mode_shapes import MAX_TURN, VISIBLE, mode_shapes
from rbdsolve.solvers.modes.answers import Motion

from conftest import PROBLEMS


def double_pendulum(**values):
    model = build_model(load_file(str(PROBLEMS / "examples" / "double-pendulum.yaml")))
    model = model.with_values({k: Fraction(v) for k, v in values.items()})
    return model, next(q for q in model.problem.questions if q.kind.value == "modes")


def test_double_pendulum_equal_masses_and_lengths() -> None:
    # m1 = m2 = m, l1 = l2 = l: M = m l² [[2, 1], [1, 1]], K = m g l [[2, 0], [0, 1]];
    # det(K − λM) = 0 gives λ² − 4λ + 2 = 0 (g/l = 1): λ = 2 ∓ √2, and
    # (2 − 2λ) u1 = λ u2 gives u = (1, √2) for λ = 2 − √2 and (1, −√2) for λ = 2 + √2.
    model, question = double_pendulum(m1=1, m2=1, l1=1, l2=1, g=1)
    shapes = mode_shapes(model, question)
    slow, fast = shapes.modes
    assert slow.eigenvalue == pytest.approx(2 - math.sqrt(2)) and fast.eigenvalue == pytest.approx(2 + math.sqrt(2))
    assert slow.vector == pytest.approx((1, math.sqrt(2))) and fast.vector == pytest.approx((1, -math.sqrt(2)))
    assert slow.motion is Motion.OSCILLATION and slow.title() == f"mode 1: ω₁ = {math.sqrt(2 - math.sqrt(2)):.4g}"
    assert shapes.notes == ()


def test_the_picture_is_the_displaced_configuration() -> None:
    # q = a·u/max|u|: P1 = l1 (sin θ1, −cos θ1), P2 = P1 + l2 (sin θ2, −cos θ2).
    model, question = double_pendulum(m1=1, m2=1, l1=1, l2=1, g=1)
    slow = mode_shapes(model, question).modes[0]
    theta1, theta2 = (v for _, v in slow.sketch.configuration)
    assert theta2 / theta1 == pytest.approx(math.sqrt(2))
    points = {p.name: p.at for p in slow.sketch.points}
    assert points["P1"] == pytest.approx((math.sin(theta1), -math.cos(theta1)))
    assert points["P2"] == pytest.approx((math.sin(theta1) + math.sin(theta2), -math.cos(theta1) - math.cos(theta2)))
    # the scene is 2 tall; P2 moves most, by about VISIBLE × 2 (a chord, a little less than the arc)
    assert math.hypot(points["P2"][0], points["P2"][1] + 2) == pytest.approx(VISIBLE * 2, rel=0.05)
    assert theta2 <= MAX_TURN


def test_missing_values_are_one_and_said() -> None:
    model = build_model(load_file(str(PROBLEMS / "examples" / "double-pendulum.yaml")))
    question = next(q for q in model.problem.questions if q.kind.value == "modes")
    shapes = mode_shapes(model, question)
    assert shapes.notes == ("m1 = m2 = l1 = l2 = g = 1: no values given",)
    assert shapes.modes[1].vector == pytest.approx((1, -math.sqrt(2)))
