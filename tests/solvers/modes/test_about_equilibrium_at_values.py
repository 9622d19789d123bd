"""Modes about a point that is an equilibrium at the values given, not for every value
(a new user's trial). A bob of mass m on a light rod l from a pivot, tied by a spring k
of natural length L₀ to W = (d, −l), to the side of its lowest point. By hand, with s the
spring's length, s² = (l sin θ − d)² + l² (1 − cos θ)²: at θ = 0, s = d, s' = −l and
s'' = l²/d − l²/d = 0, so

    ∂V/∂θ = k (s − L₀) s' = k l (L₀ − d),   K = k (s'² + (s − L₀) s'') + m g l = l (g m + k l),
    M = m l²,   λ = (g m + k l)/(l m).

With d = L₀ given, θ = 0 is an equilibrium; rbdsolve refused it ("not an equilibrium:
∂V/∂θ = k l (L₀ − d) there, give values for the parameters").
"""

from __future__ import annotations

import sympy as sp

import rbdsolve

SCENE = """\
title: a bob on a spring to the side, its natural length the distance
parameters: [m, l, d, L0, k, g]
values: {m: 1, l: 1, d: 1, L0: 1, g: 9.81}
coordinates: [theta]
gravity: [0, -g]
points:
  P: l*[sin(theta), -cos(theta)]
  W: [d, -l]
bodies:
  bob: {shape: particle, mass: m, at: P}
springs:
  s: {stiffness: k, between: [P, W], natural_length: L0}
questions:
  - modes: {about: {theta: 0}}
"""


def test_an_equilibrium_at_the_values_given_is_taken_with_a_note(tmp_path) -> None:
    path = tmp_path / "bob.yaml"
    path.write_text(SCENE)
    (solution,) = rbdsolve.solve(path, budget=1200.0)  # a budget far from the work
    assert solution.error is None, solution.error
    (lam,) = solution.answers.eigenvalues
    names = {s.name: s for s in lam.free_symbols}
    m, l, g, k = (names[n] for n in "mlgk")
    assert sp.simplify(lam - (g * m + k * l) / (l * m)) == 0
    assert any("at the values given" in w and "k l (L₀ − d)" in w for w in solution.warnings)


def test_a_point_off_the_equilibrium_at_the_values_asks_for_the_missing_ones(tmp_path) -> None:
    """With d = 2 ≠ L₀ = 1, ∂V/∂θ = k l (L₀ − d) = −k at θ = 0: no equilibrium; only k
    lacks a value, so only k is asked for."""
    path = tmp_path / "bob.yaml"
    path.write_text(SCENE.replace("d: 1,", "d: 2,"))
    (solution,) = rbdsolve.solve(path, budget=1200.0)
    assert "not an equilibrium" in solution.error
    assert "give a value for k to have a nearby equilibrium found" in solution.error
