"""A scene with values for every parameter but one: an inverted rod (mass m, length L, a
mass M at its top) on a pivot, held by two horizontal springs k of natural length d at
the height a, to walls at ±d; k left open. By hand, θ from the upward vertical, each
spring's length s with s² = 2a² + d² ∓ 2 a d sin θ − 2 a² cos θ, S = √(4a² + d²) at θ = π:

    V = g L (m/2 + M) cos θ + Σ ½ k (s − d)²,
    K(π) = ∂²V/∂θ² = g L (m/2 + M) + 2 k a² (d²/S² − (S − d)(S² + d²)/S³),
    M(π) = (m/3 + M) L²,   λ = K/M,

with the values (m, M, L, a, d, g) = (2, 1, 1, 0.5, 1, 9.81): K = 19.62 + 0.0303… k, a
sum of positive terms for every k > 0, so hanging down is stable whatever k, though
sympy sees 3 k − 2√2 k as terms of mixed sign. Expected values from this derivation."""

from __future__ import annotations

import math

import pytest
import sympy as sp

from rbdsolve.solvers.conditions.signs import coefficient_sign

SCENE = """\
title: an inverted rod held by two springs, their stiffness open
parameters: {m: mass, M: mass, L: length, a: length, d: length, g: acceleration, k: stiffness}
values: {m: 2 kg, M: 1 kg, L: 1 m, a: 50 cm, d: 1 m, g: 9.81 m/s^2}
coordinates: [theta]
gravity: [0, -g]
points:
  G: L/2 * [sin(theta), cos(theta)]
  T: L * [sin(theta), cos(theta)]
  A: a * [sin(theta), cos(theta)]
  W1: [-d, a]
  W2: [d, a]
bodies:
  rod: {shape: rod, mass: m, length: L, at: G, angle: -theta, axis: y}
  top: {shape: particle, mass: M, at: T}
springs:
  left: {stiffness: k, between: [W1, A], natural_length: d}
  right: {stiffness: k, between: [A, W2], natural_length: d}
questions:
  - equilibria
  - modes
"""

m, M, L, a, d, g = 2.0, 1.0, 1.0, 0.5, 1.0, 9.81


def _hand_lambda(k: float) -> float:
    S = math.sqrt(4 * a * a + d * d)
    K = g * L * (m / 2 + M) + 2 * k * a * a * (d * d / S ** 2 - (S - d) * (S * S + d * d) / S ** 3)
    return K / ((m / 3 + M) * L * L)


@pytest.fixture(scope="module")
def solved(tmp_path_factory):
    import rbdsolve

    path = tmp_path_factory.mktemp("rod") / "rod.yaml"
    path.write_text(SCENE)
    return rbdsolve.solve(path, budget=1200.0)  # a budget far from the work


def test_hanging_down_is_stable_for_every_stiffness(solved):
    (hanging,) = [e for e in solved[0].answers.equilibria if e.at["theta"] == sp.pi]
    assert hanging.stability.value == "stable"


def test_modes_take_the_hanging_rod_with_the_hand_eigenvalue(solved):
    """The upright rod is stable only for k past its critical value, the hanging one
    for every k: plain 'modes' takes that one (it said "no stable equilibrium found")."""
    modes = solved[1].answers
    assert modes.about == {"theta": sp.pi}
    (lam,) = modes.eigenvalues
    (k,) = [s for s in lam.free_symbols if s.name == "k"]
    table = {"m": m, "M": M, "L": L, "a": a, "d": d, "g": g}
    given = {s: table[s.name] for s in lam.free_symbols if s.name in table}
    for stiffness in (0.5, 1.0, 500.0, 1e4):
        got = float(lam.xreplace({**given, k: stiffness}))
        assert math.isclose(got, _hand_lambda(stiffness), rel_tol=1e-12), stiffness


def test_a_sum_of_positive_monomials_in_numbers_is_positive():
    k, c = sp.symbols("k c", positive=True)
    r2 = sp.sqrt(2)
    assert coefficient_sign(3 * k - 2 * r2 * k + sp.Rational(981, 100)) == 1
    assert coefficient_sign(-(3 * k - 2 * r2 * k + 1) / (k + c)) == -1
    assert coefficient_sign((2 * r2 - 3) * k + 1) is None  # of either sign, by k
    assert coefficient_sign(k * c - 2 * r2 * k + 3 * k) == 1  # k c + (3 − 2√2) k
    assert coefficient_sign(k * c - 2 * k) is None  # k (c − 2): of either sign, by c
    x = sp.Symbol("x", real=True)
    assert coefficient_sign(x + 1) is None  # x may be negative
    assert coefficient_sign(sp.sqrt(k) + 1) is None  # not a polynomial in k
