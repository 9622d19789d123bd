"""solvers/conditions/polynomial.py ``trig_transcendental``, read from the structure before
sympy's solve is asked: an equation in x with x inside sines of incommensurate multiples
of it, or x both inside and outside them, has no closed-form roots, and solve searched
for minutes (issue 37: a half-disk on a drum released from rest ran its whole budget).
The readers that use it, condition_roots.parameter_roots and reactions' zeros, answer
None there (no root claimed, the case left undecided), and still solve the ones that
have closed forms."""

from __future__ import annotations

import sympy as sp

from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.solvers.reactions.limits import zeros
from rbdsolve.solvers.conditions.condition_roots import parameter_roots
from rbdsolve.solvers.conditions.polynomial import trig_transcendental

x, k, r, R = sp.symbols("x k r R", positive=True)

SCENE = """
parameters: {m: mass, r: radius, R: radius, g: gravity}
coordinates: [x]
points: {P: [x, 0]}
bodies: {bob: {shape: particle, mass: m, at: P}}
questions: [eom]
"""


def test_which_equations_are_transcendental() -> None:
    assert trig_transcendental(sp.sin(r * x / (R + r)) - sp.cos(x), x)  # incommensurate multiples
    assert trig_transcendental(x - k * sp.sin(x), x)  # inside and outside
    assert not trig_transcendental(sp.sin(2 * x) - sp.cos(x), x)  # a polynomial in sin x, cos x
    assert not trig_transcendental(sp.sin(x / 2) - k, x)  # asin
    assert not trig_transcendental(sp.sin(r / (R + r)) - k * sp.cos(2 * r / (R + r)), r)  # one argument u(r)
    assert not trig_transcendental(x**2 - k, x)


def test_parameter_roots_claim_none_where_the_equation_is_transcendental_in_the_parameter() -> None:
    model = build_model(load_text(SCENE))
    rr, RR = model.symbols.parameters["r"], model.symbols.parameters["R"]
    both = sp.sin(rr / (10 * (RR + rr))) * sp.sin(RR / (10 * (RR + rr))) - sp.Rational(1, 100)
    assert parameter_roots(both, rr, {}, model) is None
    assert parameter_roots(rr - 2 * RR, rr, {}, model) == [2 * RR]  # by hand: r = 2R


def test_zeros_along_the_motion_are_none_where_transcendental_and_solved_where_not() -> None:
    model = build_model(load_text(SCENE))
    q = model.q[0]
    rr, RR = model.symbols.parameters["r"], model.symbols.parameters["R"]
    assert zeros(sp.sin(rr * q / (RR + rr)) - sp.cos(q) / 2, model) is None
    (found,) = zeros(2 * sp.cos(q) - 1, model)  # cos q = 1/2 by hand
    assert found.rhs == sp.Rational(1, 2)
