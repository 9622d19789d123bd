"""The numeric route's reactions at a state that names a parameter (from_rest: {x: x0},
x0 given a value): the value was not put into the state, so x0 stayed a symbol and the
route said the forces "still depend on x0 (the scene changes with time …)" — a new
user's disk on an incline. By hand, a uniform disk (m, r) rolling on a 30° incline, x up
the slope, its centre tied by a spring (k, zero length) to A, where the centre is at
x = 0: the pull is k (0 − x) along the slope, so (3/2) m ẍ = −m g sin 30° − k x (the
friction up the slope, −m ẍ/2, turns it), N = m g cos 30°, and F_C, counted along
e_z × n (down the slope), is m ẍ/2."""

from __future__ import annotations

import math

import pytest

import rbdsolve

DISK = """\
parameters: {m: mass, r: radius, k: stiffness, x0: release, g: acceleration of gravity}
values: {m: 2 kg, r: 10 cm, k: 40 N/m, x0: 1 m, g: 9.81 m/s^2}
coordinates: [x]
gravity: [0, -g]
points:
  A: "r*[-sin(pi/6), cos(pi/6)]"
bodies:
  disk: {shape: disk, mass: m, radius: r}
contacts:
  C: {body: disk, rolls_on: {line: {through: [0, 0], angle: pi/6}}, along: x}
springs:
  s: {stiffness: k, between: [disk, A]}
questions:
  - reactions: {forces: [C], from_rest: {x: x0}}
"""


def test_the_numeric_route_puts_the_parameters_value_into_the_state(tmp_path) -> None:
    path = tmp_path / "disk.yaml"
    path.write_text(DISK)
    (solution,) = rbdsolve.solve(path, route="numeric", budget=1200.0)  # a budget far from the work
    at = solution.answers.at["C"]
    xdd = (-2 * 9.81 * 0.5 - 40 * 1.0) / (1.5 * 2)
    assert solution.answers.accelerations["x"] == pytest.approx(xdd, rel=1e-12)
    assert at["N_C"] == pytest.approx(2 * 9.81 * math.cos(math.pi / 6), rel=1e-12)
    assert at["F_C"] == pytest.approx(2 * xdd / 2, rel=1e-12)
