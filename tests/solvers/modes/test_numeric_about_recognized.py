"""The numeric route names an equilibrium it recognized as exact (θ = π, within its
error bound) the same way in the modes about it as in the equilibria: the listing
printed θ = π and the modes about the same point θ = 3.14159 (a new user's trial).

A uniform rod (m, l) on a pin at its end, θ from the upward vertical, so its centre is
at (l/2)(sin θ, cos θ): by hand V = ½ m g l cos θ and T = ½ (m l²/3) θ̇², so θ = 0
(K = −½ m g l: λ = −3g/(2l), a growth) and θ = π (K = ½ m g l: λ = 3g/(2l))."""

from __future__ import annotations

import math

from click.testing import CliRunner

import rbdsolve
from rbdsolve.cli.app import main

SCENE = """\
title: a rod on a pin at its end, its angle from the upward vertical
parameters: {m: mass, l: length, g: acceleration}
values: {m: 2 kg, l: 80 cm, g: 9.81 m/s^2}
coordinates: [theta]
gravity: [0, -g]
points:
  G: l/2 * [sin(theta), cos(theta)]
bodies:
  rod: {shape: rod, mass: m, length: l, at: G, angle: theta, axis: y}
questions:
  - modes
  - modes: {about: each}
"""
G, L = 9.81, 0.8


def test_the_modes_about_a_recognized_pi_write_pi(tmp_path) -> None:
    path = tmp_path / "rod.yaml"
    path.write_text(SCENE, encoding="utf-8")
    first, each = rbdsolve.solve(path, route="numeric", budget=600.0)
    assert math.isclose(first.answers.about["theta"], math.pi, rel_tol=1e-12)
    assert math.isclose(first.answers.eigenvalues[0], 3 * G / (2 * L), rel_tol=1e-9)
    assert [math.isclose(a.eigenvalues[0], x, rel_tol=1e-9) for a, x in
            zip(each.answers.modes, (-3 * G / (2 * L), 3 * G / (2 * L)))] == [True, True]
    text = CliRunner().invoke(main, ["solve", "--route", "numeric", str(path)]).output
    assert "about the equilibrium\n    θ = π\n" in text
    assert "About equilibrium 2:\n    θ = π\n" in text and "Conditioning about θ = π:" in text
    assert "θ = 3.14159\n" not in text  # the steps; the numbers below keep 3.14159 rad (180°)
