"""The roots λ of a characteristic polynomial with symbols in its coefficients, found
once per polynomial: the equilibria ±θ₀ of a pendulum share one K, and a second question
about them asks again (a plate on a spring of natural length, 0.2 s a root)."""

from __future__ import annotations

import sympy as sp

from rbdsolve.solvers.modes import exact

from conftest import counted_calls


def test_the_eigenvalues_of_one_polynomial_are_found_once(monkeypatch) -> None:
    """−(2/3) a² m λ + k (h − a)²: by hand λ = 3 k (h − a)²/(2 a² m). A second polynomial
    equal to the first (built anew, as for the other equilibrium) is not solved again."""
    a, m, k, h = sp.symbols("a m k h", positive=True)
    lam = exact.LAMBDA
    calls = counted_calls(monkeypatch, exact.sp, "roots")
    exact._roots.cache_clear()
    first = exact._roots(sp.Poly(-sp.Rational(2, 3) * a**2 * m * lam + k * (h - a) ** 2, lam), lam)
    again = exact._roots(sp.Poly(k * (h - a) ** 2 - sp.Rational(2, 3) * a**2 * m * lam, lam), lam)
    assert len(first) == 1 and sp.simplify(first[0] - 3 * k * (h - a) ** 2 / (2 * a**2 * m)) == 0
    assert again == first
    assert len(calls) == 1


def test_a_quadratic_gives_both_roots_with_multiplicity() -> None:
    """m² λ² − 5 k m λ + 4 k² = (m λ − k)(m λ − 4 k): λ = k/m and 4k/m; (λ − k/m)² twice."""
    m, k = sp.symbols("m k", positive=True)
    lam = exact.LAMBDA
    quadratic = sp.Poly(m**2 * lam**2 - 5 * k * m * lam + 4 * k**2, lam)
    assert set(exact._roots(quadratic, lam)) == {k / m, 4 * k / m}
    assert exact._roots(sp.Poly((m * lam - k) ** 2, lam), lam) == (k / m, k / m)
