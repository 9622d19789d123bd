"""common_scale reads each expression's factors without sympy's factor_terms where that
gives the product back as it stands (form/tidy.py ``terms_factored``: numbers, powers of
symbols, coordinates, sines and cosines of unit sums): the scale is the one factor_terms
gives (the oracle) on both kinds."""

from __future__ import annotations

import itertools

import sympy as sp

from rbdsolve.form import arrange
from rbdsolve.form.arrange import common_scale
from rbdsolve.form.tidy import terms_factored

m, l, g = sp.symbols("m l g", positive=True)
k = sp.Symbol("k")
t = sp.Symbol("t")
th1, th2 = sp.Function("th1")(t), sp.Function("th2")(t)
a, b = sp.symbols("a b")

ENTRIES = [sp.Rational(3, 2) * l**2 * m * sp.cos(th1 - th2), -sp.Rational(7, 3) * l**2 * m,
           2 * m * l * sp.cos(2 * a - 2 * b), -g * l * m * sp.cos(a), m**2 * l * sp.Derivative(th1, t),
           k * l**sp.Rational(1, 2), sp.Float(0.5) * m * sp.cos(a - b), -m * th2, sp.Integer(-4), l,
           m * l**2 + m * a**2, sp.sqrt(2) * m * l, m * sp.sin(a - b), l**2 * m / (m + g),
           -m * l * sp.cos(th1) - m * l * sp.cos(th2)]


def _scale_by_factor_terms(exprs: list) -> sp.Expr:
    original = arrange.terms_factored
    arrange.terms_factored = sp.factor_terms
    try:
        return common_scale(exprs, {m, l, g, k})
    finally:
        arrange.terms_factored = original


def test_the_scale_is_factor_terms_scale() -> None:
    for n in (1, 2, 3):
        for exprs in itertools.combinations(ENTRIES, n):
            assert common_scale(list(exprs), {m, l, g, k}) == _scale_by_factor_terms(list(exprs)), exprs


def test_a_product_is_read_as_it_stands_and_a_sum_is_factored() -> None:
    entry = sp.Rational(3, 2) * l**2 * m * sp.cos(th1 - th2)
    assert terms_factored(entry) is entry
    assert terms_factored(m * l**2 + m * a**2) == m * (l**2 + a**2)
    assert terms_factored(m * sp.sin(a - b)) == sp.factor_terms(m * sp.sin(a - b))
