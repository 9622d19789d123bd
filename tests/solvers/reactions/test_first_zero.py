"""Where a push first reaches zero along a motion from rest (solvers/reactions/first_zero.py),
on forces whose zeros and turning points are known by hand."""

import math

import sympy as sp

from rbdsolve.solvers.reactions.first_zero import FirstZero, first_zero

q, g, R, q0 = sp.symbols("q g R q0")
VALUES = {g: sp.Rational(981, 100), R: sp.Rational(6, 5)}


def test_a_particle_leaves_a_sphere_where_cos_q_is_two_thirds_of_its_start():
    # outside a sphere, q from the top: R q̇² = 2 g (cos q0 − cos q), N/m = g cos q − R q̇²
    push = g * (3 * sp.cos(q) - 2 * sp.cos(q0))
    rate_squared = 2 * g * (sp.cos(q0) - sp.cos(q)) / R
    found = first_zero(push, rate_squared, q, q0, "q", {**VALUES, q0: sp.Rational(1, 10)})
    assert found.turns_at is None
    assert math.isclose(found.lost_at["q"], math.acos(2 / 3 * math.cos(0.1)), rel_tol=1e-12)


def test_inside_a_track_below_its_middle_the_motion_turns_back_at_minus_the_start():
    # inside, q from the lowest point: R q̇² = 2 g (cos q − cos q0), N/m = g cos q + R q̇²
    push = g * (3 * sp.cos(q) - 2 * sp.cos(q0))
    rate_squared = 2 * g * (sp.cos(q) - sp.cos(q0)) / R
    found = first_zero(push, rate_squared, q, q0, "q", {**VALUES, q0: sp.pi * 4 / 9})
    assert found.lost_at is None
    assert math.isclose(found.turns_at["q"], -4 * math.pi / 9, rel_tol=1e-12)


def test_released_at_an_equilibrium_it_stays_there():
    push = g * (3 * sp.cos(q) - 2)
    rate_squared = 2 * g * (1 - sp.cos(q)) / R  # the top of the sphere: q̈ = 0 there
    assert first_zero(push, rate_squared, q, sp.Integer(0), "q", VALUES) == FirstZero(None, None)


def test_a_push_that_does_not_hold_at_the_release_gives_no_answer():
    push = g * (3 * sp.cos(q) - 2 * sp.cos(q0))  # inside a track above its middle: N(q0) = g cos q0 < 0
    rate_squared = 2 * g * (sp.cos(q) - sp.cos(q0)) / R
    assert first_zero(push, rate_squared, q, q0, "q", {**VALUES, q0: sp.pi * 2 / 3}) is None


def test_a_sign_change_through_a_pole_is_not_a_zero():
    push = 1 / (sp.cos(q) - sp.Rational(1, 2))  # +∞ → −∞ at q = π/3, never 0
    rate_squared = q - sp.Rational(1, 10)  # from rest at q = 0.1 it sets off forward and never turns back
    assert first_zero(push, rate_squared, q, sp.Rational(1, 10), "q", {}) is None


def test_a_motion_that_is_not_periodic_and_meets_nothing_in_a_turn_gives_no_answer():
    push = 1 + q**2
    rate_squared = q  # from q = 0 it sets off forward and speeds up for ever
    assert first_zero(push, rate_squared, q, sp.Integer(0), "q", {}) is None


def test_the_answer_does_not_depend_on_mpmath_s_working_precision_elsewhere():
    import mpmath

    push = g * (3 * sp.cos(q) - 2 * sp.cos(q0))
    rate_squared = 2 * g * (sp.cos(q0) - sp.cos(q)) / R
    values = {**VALUES, q0: sp.Rational(1, 10)}
    with mpmath.workdps(40):  # as the oracle's tests leave it, for one
        found = first_zero(push, rate_squared, q, q0, "q", values)
    assert math.isclose(found.lost_at["q"], math.acos(2 / 3 * math.cos(0.1)), rel_tol=1e-12)
