"""at_state: a value at a state, simplified (sympy's simplify: one fraction, its trigonometric forms)."""

from __future__ import annotations

import sympy as sp

from rbdsolve.solvers.lagrange.accelerations import at_state

R, a, b, g, m, theta, theta0 = sp.symbols("R a b g m theta theta0", positive=True)


def test_a_rational_function_of_the_parameters_is_one_cancelled_fraction() -> None:
    """A slab on a drum at θ = 1/10 (by hand: the sum over 2(3R²/25 + 4a² + b²), times
    25/25, is 5 g m (3 R a sin(1/10) + …)/(3R² + 100a² + 25b²))."""
    force = m * (6 * R * a * g * sp.sin(theta) / 5 + 8 * a**2 * g * sp.cos(theta) + 2 * b**2 * g * sp.cos(theta)) \
        / (2 * (3 * R**2 / 25 + 4 * a**2 + b**2))
    value = at_state(force, {theta: sp.Rational(1, 10)})
    s, c = sp.sin(sp.Rational(1, 10)), sp.cos(sp.Rational(1, 10))
    expected = 5 * g * m * (3 * R * a * s + 20 * a**2 * c + 5 * b**2 * c) / (3 * R**2 + 100 * a**2 + 25 * b**2)
    assert sp.expand(value - expected) == 0
    assert sp.fraction(value)[1] == 3 * R**2 + 100 * a**2 + 25 * b**2  # one fraction, no 3/25 left inside


def test_a_symbolic_angle_keeps_simplify_s_trigonometric_form() -> None:
    """A ladder released at θ₀: m(3 g cos²θ₀ + g)/4 is g m (3 cos²θ₀ + 1)/4."""
    value = at_state(m * (3 * g * sp.cos(theta) ** 2 + g) / 4, {theta: theta0})
    assert value == g * m * (3 * sp.cos(theta0) ** 2 + 1) / 4
