"""Units where a student copies them from the statement into the scene itself: a
spring's natural length and rest angle, and a coordinate's search range, read in SI as
a state's values are."""

from __future__ import annotations

import math

import sympy as sp

import rbdsolve
from rbdsolve.model.build import build_model
from rbdsolve.problem import load_file

SCENE = """\
title: a rod pivoted at its end, on a torsion spring that rests at 60 degrees
parameters: {m: mass, l: length, c: torsional stiffness}
values: {m: 1 kg, l: 50 cm, c: 2 N*m/rad}
coordinates:
  theta: {kind: angle, periodic: false, range: [-90 deg, 180 deg]}
points:
  G: l/2 * [sin(theta), -cos(theta)]
  A: "[0, -l]"
bodies:
  rod: {shape: rod, mass: m, length: l, at: G, angle: theta, axis: y}
springs:
  torsion: {stiffness: c, angle: theta, rest: 60 deg}
  cord: {stiffness: 0, between: [G, A], natural_length: 20 cm}
questions:
  - equilibria
  - modes: {about: each}
"""


def test_the_values_are_read_in_si(tmp_path) -> None:
    path = tmp_path / "rod.yaml"
    path.write_text(SCENE, encoding="utf-8")
    problem = load_file(path)
    scalar = build_model(problem).symbols.scalar
    (theta,) = problem.coordinates
    springs = {s.name: s for s in problem.springs}
    assert [scalar(end) for end in theta.range] == [-sp.pi / 2, sp.pi]
    assert scalar(springs["torsion"].rest) == sp.pi / 3
    assert scalar(springs["cord"].natural_length) == sp.Rational(1, 5)


def test_the_numeric_route_searches_the_range_and_finds_the_rest_angle(tmp_path) -> None:
    """No gravity: V = ½ c (θ − π/3)², so θ = π/3 is the one equilibrium, and with
    M = m l²/3 = 1/12 the mode is λ = c/M = 24 1/s² (by hand)."""
    path = tmp_path / "rod.yaml"
    path.write_text(SCENE, encoding="utf-8")
    equilibria, modes = (s.answers for s in rbdsolve.solve(path, route="numeric", budget=600.0))
    (found,) = equilibria.equilibria
    assert math.isclose(float(found.at["theta"]), math.pi / 3, rel_tol=1e-12)
    (about,) = modes.modes
    assert math.isclose(float(about.eigenvalues[0]), 24.0, rel_tol=1e-12)
