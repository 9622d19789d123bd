"""Modes asked where there is no equilibrium at all (a new user's trial): a rod (m, l)
pivoted at l/4 from its centre, driven by a constant couple M₀. By hand, V = −M₀ θ −
(1/4) m g l cos θ, so ∂V/∂θ = (1/4) m g l sin θ − M₀ = 0 needs M₀ ≤ m g l/4 = 5.886 N·m
at m = 2 kg, l = 1.2 m. With M₀ = 7 N·m there is none, and 'modes' advised choosing one
with 'about'; now it says there is none. With M₀ = 5 N·m, about θ = asin(4 M₀/(m g l)),
K = (1/4) m g l cos θ and M = m (l²/12 + l²/16), so ω² = K/M."""

from __future__ import annotations

import math

import pytest

from conftest import solved_scene

ROD = """\
parameters: [m, l, M0, g]
values: {m: 2 kg, l: 1.2 m, M0: MOMENT N*m, g: 9.81 m/s^2}
coordinates: [theta]
gravity: [0, -g]
points:
  O: [0, 0]
  G: l/4*[sin(theta), -cos(theta)]
bodies:
  rod: {shape: rod, mass: m, length: l, at: G, angle: theta, axis: y}
couples:
  drive: {on: rod, moment: M0}
questions:
  - modes
"""


def _solved(tmp_path, moment: int):
    return solved_scene(tmp_path, ROD.replace("MOMENT", str(moment)), "rod.yaml")


def test_past_the_largest_couple_there_is_nothing_to_oscillate_about(tmp_path) -> None:
    solution = _solved(tmp_path, 7)
    assert not solution.solved
    assert "there is no equilibrium" in solution.error and "choose one" not in solution.error


def test_below_it_the_stable_one_oscillates(tmp_path) -> None:
    solution = _solved(tmp_path, 5)
    m, length, g, M0 = 2.0, 1.2, 9.81, 5.0
    theta = math.asin(4 * M0 / (m * g * length))
    omega = math.sqrt(m * g * length / 4 * math.cos(theta) / (m * (length**2 / 12 + length**2 / 16)))
    assert solution.solved
    assert solution.values["frequencies"][0] == pytest.approx(omega, rel=1e-9)
