"""The float64 screens (solvers/configuration/placement_screen.py): a point is let through as
regular only where ∂φ/∂q has full column rank by a wide margin, two placements are
called different only where rounding cannot explain the difference; anything else is
"not shown", left to the 30-digit or exact test.

Hand derivations. φ = l (sin θ cos ψ, sin θ sin ψ, −cos θ), a spherical pendulum:
∂φ/∂θ = l (cos θ cos ψ, cos θ sin ψ, sin θ), ∂φ/∂ψ = l sin θ (−sin ψ, cos ψ, 0); the
two columns are orthogonal, of lengths l and l |sin θ|: full rank for sin θ ≠ 0, the
ratio of the singular values |sin θ|; at θ = 0 the second column vanishes (the pole).
φ = (c x, y) with c = P − Q − 1, P = 10²⁰, Q = 10²⁰ − 1: exactly c = 0, rank 1; in
float64 Q rounds to 10²⁰ and c comes out −1, which a float-only test would call full
rank.
φ = (l sin x, l cos² x) takes the same value at x = 0 and x = π (sin π = 0, cos² π = 1),
though float64 gives sin π ≈ 1.2e-16; l cos x does not (l and −l).
"""

from __future__ import annotations

import math

import sympy as sp

from rbdsolve.solvers.configuration.placement_screen import clearly_different, clearly_full_rank

th, ps, l, x, y, P, Q = sp.symbols("theta psi l x y P Q", real=True)
SPHERE = [l * sp.sin(th) * sp.cos(ps), l * sp.sin(th) * sp.sin(ps), -l * sp.cos(th)]


def test_a_regular_point_is_let_through() -> None:
    assert clearly_full_rank(SPHERE, [th, ps], [1.0, 0.4], {l: 2.0})


def test_the_pole_is_not_let_through() -> None:
    assert not clearly_full_rank(SPHERE, [th, ps], [0.0, 0.4], {l: 2.0})


def test_a_point_near_the_pole_is_left_to_the_30_digit_test() -> None:
    # σ_min/σ_max = sin θ ≈ 1e-6: regular at 30 digits, but inside the screen's margin
    assert not clearly_full_rank(SPHERE, [th, ps], [1e-6, 0.4], {l: 2.0})


def test_cancellation_beyond_float_accuracy_is_not_trusted() -> None:
    phi = [sp.Mul(sp.Add(P, -Q, -1, evaluate=False), x, evaluate=False), y]
    values = {P: float(sp.Integer(10) ** 20), Q: float(sp.Integer(10) ** 20 - 1)}
    assert not clearly_full_rank(phi, [x, y], [0.5, 0.5], values)


def test_what_the_pass_does_not_know_is_not_let_through() -> None:
    t = sp.Symbol("t")
    assert not clearly_full_rank([sp.Abs(x), y], [x, y], [1.0, 1.0], {})  # a function it does not take
    assert not clearly_full_rank([x * sp.cos(t), y], [x, y], [1.0, 1.0], {})  # a symbol without a number
    assert not clearly_full_rank([sp.sqrt(x), y], [x, y], [-1.0, 1.0], {})  # not real
    assert not clearly_full_rank([sp.sqrt(x ** 2 + y ** 2), x], [x, y], [0.0, 0.0], {})  # no derivative


def test_fewer_entries_than_coordinates_is_never_full_rank() -> None:
    assert not clearly_full_rank([x + y], [x, y], [1.0, 2.0], {})


def test_placements_equal_up_to_rounding_are_not_called_different() -> None:
    assert not clearly_different([l * sp.sin(x), l * sp.cos(x) ** 2], [x], [0.0], [math.pi], {l: 2.0})


def test_placements_that_differ_are_called_different() -> None:
    assert clearly_different([l * sp.sin(x), l * sp.cos(x)], [x], [0.0], [math.pi], {l: 2.0})


def test_placements_the_pass_cannot_evaluate_are_not_called_different() -> None:
    assert not clearly_different([sp.Abs(x)], [x], [1.0], [2.0], {})
