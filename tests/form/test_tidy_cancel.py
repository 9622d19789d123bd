"""tidy's cancel of a quotient of polynomials as the pair (numerator, denominator) gives
the very expression sympy's ``cancel`` of the whole gives (the oracle), rational
coefficients, signs and common factors alike; a pair whose symbols all cancel once
expanded, and forms outside the pair's reach (a root of a symbol), go the whole way."""

import random

import sympy as sp

from rbdsolve.form.tidy import _cancel_over, _polynomial_quotient

a, b, c, x = sp.symbols("a b c x", positive=True)
th = sp.Dummy("theta", real=True)


def _same_as_cancel(expr):
    expr = sp.together(expr)
    assert sp.srepr(_cancel_over(expr, True, False)) == sp.srepr(sp.cancel(expr))


def test_written_quotients_match_cancel():
    for expr in [
        (2 * a**2 - 2) / (a**2 - 2 * a + 1),
        -(3 * a * b + 6 * b**2) / (9 * a * c - 12 * c**2),
        (a / 2 + b / 3) / (c / 5 - a / 7),
        (a**2 - b**2) / (-a - b),
        (x * th**2 - x) / (2 * th + 2) + a / (3 * b),
        sp.Integer(0) / (a + b) + (a - a),
        ((a + 1) ** 2 - a**2 - 2 * a) / ((b + 1) ** 2 - b**2 - 2 * b),  # a number once expanded
        ((a + 1) ** 2 - a**2 - 2 * a - 1) / (a + b),  # zero once expanded
    ]:
        _same_as_cancel(expr)


def test_random_quotients_match_cancel():
    rng = random.Random(37)
    symbols = [a, b, c, th]

    def poly():
        return sp.Add(*[sp.Rational(rng.randint(-9, 9), rng.randint(1, 4))
                        * sp.Mul(*[s ** rng.randint(0, 2) for s in symbols]) for _ in range(rng.randint(1, 4))])

    for _ in range(60):
        common = poly()
        _same_as_cancel(poly() * common / (poly() * common))


def test_roots_and_functions_are_left_to_cancel():
    assert not _polynomial_quotient(sp.sqrt(a) * b + a ** sp.Rational(3, 2))
    assert not _polynomial_quotient(sp.sin(a) / (b + 1))
    assert _polynomial_quotient((a**2 + b) / (3 * c - 1))


def test_parts_are_the_fractions_parts_once_expanded():
    from rbdsolve.form.tidy import tidy_fraction, tidy_fraction_parts

    rng = random.Random(29)
    s, co = sp.sin(th), sp.cos(th)

    def poly():
        return sp.Add(*[sp.Rational(rng.randint(-9, 9), rng.randint(1, 4))
                        * sp.Mul(*[f ** rng.randint(0, 2) for f in (a, b, s, co)]) for _ in range(rng.randint(1, 3))])

    cases = [(a / 3 + 2 * b / 3) / 5, -(a + b) / (2 * c), (s**2 + co**2) * a / (3 * b - 6 * c)]
    cases += [poly() / poly() for _ in range(40)]
    for expr in cases:
        old = [sp.expand(x) for x in sp.fraction(tidy_fraction(expr))]
        assert [sp.expand(x) for x in tidy_fraction_parts(expr)] == old, expr


def test_sums_of_fractions_cancel_as_together_then_cancel():
    from rbdsolve.form.tidy import _leading_plus, tidy_fraction

    rng = random.Random(41)

    def poly():
        return sp.Add(*[sp.Rational(rng.randint(-9, 9), rng.randint(1, 3))
                        * sp.Mul(*[s ** rng.randint(0, 2) for s in (a, b, c)]) for _ in range(rng.randint(1, 3))])

    for _ in range(40):
        common = poly()
        expr = sp.Add(*[poly() / (poly() * common) for _ in range(rng.randint(1, 3))])
        if expr.is_Rational:
            continue
        whole = _leading_plus(sp.factor_terms(sp.cancel(sp.together(expr))))  # sympy's way, the oracle
        assert sp.srepr(tidy_fraction(expr)) == sp.srepr(whole), expr
