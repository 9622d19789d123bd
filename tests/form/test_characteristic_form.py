"""A characteristic polynomial highest power first (``arrange.descending``): a
coefficient whose terms share one denominator is written over it once. The polynomial's
own expansion divides each term by the denominator written out: an inverted rod's
K = (A √S + B k)/(2 S^(3/2)), S = 4a² + d², came as a sum of terms each over
8a²√S + 2d²√S."""

from __future__ import annotations

import sympy as sp

from rbdsolve.form.arrange import descending
from rbdsolve.form.printers import to_unicode


def test_a_shared_denominator_is_written_once():
    """K as the inverted rod has it at θ = π (long enough that factoring is not tried)."""
    L, M, a, d, g, k, lam, m = sp.symbols("L M a d g k lamda m", positive=True)
    S = 4 * a**2 + d**2
    top = (8 * L * M * a**2 * g * sp.sqrt(S) + 2 * L * M * d**2 * g * sp.sqrt(S) + 4 * L * a**2 * g * m * sp.sqrt(S)
           + L * d**2 * g * m * sp.sqrt(S) + 16 * a**4 * d * k - 16 * a**4 * k * sp.sqrt(S) + 8 * a**2 * d**3 * k
           - 4 * a**2 * d**2 * k * sp.sqrt(S))
    K = top / (2 * S ** sp.Rational(3, 2))
    poly = sp.Poly(K - lam * m, lam)
    constant = poly.all_coeffs()[-1]
    assert constant.is_Add and to_unicode(constant).count(")/(") >= 4  # each term over the denominator
    shown = to_unicode(descending(poly))
    assert shown.count(")/(") == 1 and shown.endswith("/(2 (4 a² + d²)^(3/2))"), shown


def test_a_polynomial_coefficient_is_left_as_it_was():
    R, g, lam, m, r = sp.symbols("R g lamda m r", positive=True)
    poly = sp.Poly(-sp.Rational(3, 2) * m * (R - r) ** 2 * lam + g * m * (R - r), lam)
    assert to_unicode(descending(poly)) == "−3/2 m (R − r)² λ + g m (R − r)"
