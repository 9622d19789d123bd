"""A refusal's remedy is said where it helps and left out where another route has
done it: a note that quotes the exact route's reason on auto, after the numeric route
answered, read "for modes, give the equilibrium with 'modes: {about: {...}}'" to a
file that had (a new user's trial).

A bob (m, on a light rod l) on a torsion spring c that rests at θ = 1: by hand
V = ½ c (θ − 1)² − m g l cos θ, so ∂V/∂θ = c (θ − 1) + m g l sin θ, with no root at
0, ±π/2 or π (no evident root: the exact route refuses), and about its root θ₀,
λ = (c + m g l cos θ₀)/(m l²)."""

from __future__ import annotations

import math

import mpmath

import rbdsolve

SCENE = """\
title: a bob on a torsion spring that rests at 1 rad
parameters: {m: mass, l: length, g: acceleration, c: torsional stiffness}
values: {m: 1 kg, l: 50 cm, g: 9.81 m/s^2, c: 2 N*m/rad}
coordinates: [theta]
gravity: [0, -g]
points:
  P: l * [sin(theta), -cos(theta)]
bodies:
  bob: {shape: particle, mass: m, at: P}
springs:
  hinge: {stiffness: c, angle: theta, rest: 1}
questions:
  - equilibria
  - modes: {about: {theta: 0.292598}}
"""
m, l, g, c = 1.0, 0.5, 9.81, 2.0


def test_the_exact_routes_remedies_are_said_alone_and_left_out_on_auto(tmp_path) -> None:
    path = tmp_path / "torsion.yaml"
    path.write_text(SCENE, encoding="utf-8")
    equilibria, modes = rbdsolve.solve(path, route="exact", budget=600.0)
    assert equilibria.error.endswith("for modes, give the equilibrium with 'modes: {about: {...}}'")
    assert modes.error.endswith("with a value for every parameter, the numeric route refines it to the "
                                "equilibrium near it")
    _, modes = rbdsolve.solve(path, budget=600.0)
    note = next(w for w in modes.warnings if w.startswith("the exact route could not answer"))
    assert "not exactly an equilibrium" in note
    assert "for modes, give" not in note and "refines it to" not in note
    theta0 = float(mpmath.findroot(lambda x: c * (x - 1) + m * g * l * mpmath.sin(x), 0.3))
    assert math.isclose(modes.answers.about["theta"], theta0, rel_tol=1e-12)
    assert math.isclose(modes.answers.eigenvalues[0], (c + m * g * l * math.cos(theta0)) / (m * l**2), rel_tol=1e-9)
