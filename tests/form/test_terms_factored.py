"""terms_factored is sympy's factor_terms (the oracle), form for form: on the products it
returns as they stand (rationals, powers of symbols, coordinates and their derivatives,
sines and cosines of unit sums: every entry of a chain's M(q)) and on everything else,
which it hands to factor_terms."""

from __future__ import annotations

import itertools
import random

import sympy as sp

from rbdsolve.form.tidy import _kept_as_it_is, terms_factored

t = sp.Symbol("t")
m, l, g = sp.symbols("m l g", positive=True)
a, b, c = sp.Dummy("a", real=True), sp.Dummy("b", real=True), sp.Symbol("c")
th1, th2, th3 = (sp.Function(f"th{i}")(t) for i in (1, 2, 3))
ANGLES = [a, th1, a - b, b - a, th1 - th2, th2 - th1 + th3, a + b - c, -a + c]
COEFFICIENTS = [sp.Integer(1), sp.Integer(-1), sp.Rational(3, 2), sp.Rational(-7, 12), sp.Integer(4)]
PARAMETERS = [sp.Integer(1), m, l**2 * m, g * l * m, m**2 / l, l ** sp.Rational(1, 2)]
RATES = [sp.Integer(1), sp.Derivative(th1, t), sp.Derivative(th1, t) * sp.Derivative(th2, t), th3]


def test_the_products_kept_are_factor_terms_own() -> None:
    kept = 0
    for C, P, angle, rate in itertools.product(COEFFICIENTS, PARAMETERS, ANGLES, RATES):
        for f in (sp.cos, sp.sin):
            e = C * P * f(angle) * rate
            assert sp.srepr(terms_factored(e)) == sp.srepr(sp.factor_terms(e)), e
            kept += all(_kept_as_it_is(x) for x in sp.Mul.make_args(e))
    assert kept > 1000  # the shortcut was taken, not only factor_terms


def test_other_forms_go_to_factor_terms() -> None:
    rng = random.Random(23)
    forms = [m * sp.cos(2 * a - 2 * b), m * sp.cos(m * a - m * b), -m * sp.sin(-a - b), m * l + m * g,
             sp.sqrt(2) * m, sp.cos(a) ** 2 * m, m * sp.exp(-a - 2), m / (l + g), sp.Float(0.5) * m * sp.cos(a - b),
             sp.Function("f")(a + b) * m, 2 * m * sp.cos(2 * th1 - 2 * th2)]
    for _ in range(3):
        rng.shuffle(forms)
        for e in forms:
            assert sp.srepr(terms_factored(e)) == sp.srepr(sp.factor_terms(e)), e
    assert not _kept_as_it_is(sp.cos(2 * a - 2 * b)) and not _kept_as_it_is(sp.sin(-a - b))
    assert terms_factored(m * l + m * g) == m * (l + g)
