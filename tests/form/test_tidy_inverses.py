"""tidy writes sin and cos of a multiple of an inverse function out in its argument
(form/tidy.py ``_of_inverses``). By hand (Chebyshev): cos 2θ = 2 cos²θ − 1 and
sin 2θ = 2 sin θ cos θ with cos θ = c, sin θ = √(1 − c²) at θ = acos c; cos 3θ = 4c³ − 3c;
at θ = asin s, cos 2θ = 1 − 2s²; at θ = atan u, sin 2θ = 2u/(1 + u²). Each also checked
at random numbers against the unexpanded form (mpmath, 30 digits)."""

from __future__ import annotations

import random

import sympy as sp

from rbdsolve.form.tidy import tidy

c, r, e = sp.symbols("c r e", positive=True)


def _same_at_random(a: sp.Expr, b: sp.Expr, symbols) -> bool:
    rng = random.Random(5)
    for _ in range(5):
        point = {s: sp.Rational(rng.randint(1, 99), 100) for s in symbols}
        if abs(sp.N(a.xreplace(point), 30) - sp.N(b.xreplace(point), 30)) > 1e-25:
            return False
    return True


def test_multiples_of_an_inverse_are_written_in_its_argument() -> None:
    cases = {
        sp.cos(2 * sp.acos(c)): 2 * c**2 - 1,
        sp.sin(2 * sp.acos(c)): 2 * c * sp.sqrt(1 - c**2),
        sp.cos(3 * sp.acos(c)): 4 * c**3 - 3 * c,
        sp.cos(2 * sp.asin(c)): 1 - 2 * c**2,
        sp.sin(2 * sp.atan(c)): 2 * c / (1 + c**2),
    }
    for built, by_hand in cases.items():
        assert sp.simplify(tidy(built) - by_hand) == 0, built
        assert not tidy(built).has(sp.acos, sp.asin, sp.atan)
        assert _same_at_random(built, by_hand, [c])


def test_an_equilibrium_at_acos_put_into_a_form_in_two_angles() -> None:
    """A K about φ₀ = acos(r/(2e)) of the form A − B cos 2φ: the double angle goes."""
    phi0 = sp.acos(r / (2 * e))
    K = 3 * r**2 - 4 * e**2 * sp.cos(2 * phi0)
    tidied = tidy(K)
    assert not tidied.has(sp.acos)
    assert sp.simplify(tidied - (3 * r**2 - 4 * e**2 * (r**2 / (2 * e**2) - 1))) == 0


def test_an_inverse_alone_or_a_fraction_of_it_is_left() -> None:
    assert tidy(sp.acos(c)) == sp.acos(c)
    half = sp.cos(sp.acos(c) / 2)
    assert tidy(half).has(sp.acos)  # a half angle would bring a radical of a radical: kept
