"""A zero's condition of being reached, written in no parameter and too long to read, is
said at the values when every value is given (my own next-door scene: twenty lines of
radicals, where the answer at the values is a yes or a no).

A disk (m = 2 kg, r = 0.1 m) rolls on a 25° incline, its centre x along the slope; a
spring (k = 60 N/m, natural length l₀ = 0.3 m) joins the centre to W, h = 0.5 m above
the line of centres at x = 0. By hand: N = m g cos α − k h (s − l₀)/s with s = √(h² + x²),
zero where s = l₀/(1 − m g cos α/(k h)), x = ±0.5409; released at x₀ = 0.4 m,
V(x) = m g sin α x + ½ k (s − l₀)² is below V(x₀) at −0.5409 (reached) and above it at
+0.5409 (not: ẋ² < 0 there)."""

from __future__ import annotations

import math

import pytest

from conftest import solved_scene

DISK = """\
parameters: [m, r, k, l0, h, alpha, x0, g]
values: {m: 2 kg, r: 0.1 m, k: 60 N/m, l0: 0.3 m, h: 0.5 m, alpha: 25 deg, x0: 0.4 m, g: 9.81 m/s^2}
coordinates: [x]
gravity: [0, -g]
points:
  W: "r*[-sin(alpha), cos(alpha)] + h*[-sin(alpha), cos(alpha)]"
bodies:
  disk: {shape: disk, mass: m, radius: r}
contacts:
  C: {body: disk, rolls_on: {line: {through: [0, 0], angle: alpha}}, along: x}
springs:
  s: {stiffness: k, between: [disk, W], natural_length: l0}
questions:
  - reactions: {forces: [C], from_rest: {x: x0}}
"""


def _potential(x: float) -> float:
    m, k, l0, h, alpha, g = 2.0, 60.0, 0.3, 0.5, math.radians(25), 9.81
    return m * g * math.sin(alpha) * x + 0.5 * k * (math.hypot(h, x) - l0) ** 2


def test_each_zero_is_said_reached_or_not_at_the_values(tmp_path) -> None:
    solution = solved_scene(tmp_path, DISK, "disk.yaml")
    m, k, l0, h, alpha, g = 2.0, 60.0, 0.3, 0.5, math.radians(25), 9.81
    s = l0 / (1 - m * g * math.cos(alpha) / (k * h))
    zero = math.sqrt(s * s - h * h)
    notes = [step.text for step in solution.steps if "too long to read here" in step.text]
    assert len(notes) == 2
    expected = ["holds" if _potential(x) <= _potential(0.4) else "does not" for x in (-zero, zero)]
    assert [n.rsplit("it ", 1)[1].rstrip(".") for n in notes] == expected == ["holds", "does not"]
    assert solution.answers.first_zero["N_C"].lost_at["x"] == pytest.approx(-zero, rel=1e-6)
