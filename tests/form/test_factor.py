"""Factored forms for reading (rbdsolve.form.factor): the forms the seed exam's worked
solutions write, each the same expression, and no rule applied where it lengthens."""

import pytest
import sympy as sp

from rbdsolve.form.display import Product, Terms
from rbdsolve.form.factor import _splits, factored, squares_joined
from rbdsolve.form.printers import to_unicode

R, r, m, g, a, b, c, e, M = sp.symbols("R r m g a b c e M", positive=True)
l1, l2, m1, m2, m_a, th, W = sp.symbols("l1 l2 m1 m2 m_a theta Omega", positive=True)

CASES = [
    # (expression, how a worked solution writes it)
    (sp.Rational(3, 4) * m * (R**2 - 2 * R * r + r**2), "3/4 m (R − r)²"),
    (a**4 - a**2 * b**2 - a**2 * c**2 + b**2 * c**2, "(a² − b²) (a² − c²)"),
    (R * g * m - g * m * r, "g m (R − r)"),
    (l1 * m1 + l1 * m2 + l2 * m1 + l2 * m2, "(l₁ + l₂) (m₁ + m₂)"),
    (a**2 * m / 3 + b**2 * m / 12, "1/12 m (4 a² + b²)"),
    (R * g * m - a * g * m / 2, "1/2 g m (2 R − a)"),
    (-2 * g * m - g * m_a, "−g (2 m + mₐ)"),
    (3 * R**2 * m / 4 - 4 * R**2 * m * sp.cos(th) / (3 * sp.pi), "R² m (3/4 − 4 cos(θ)/(3 π))"),
    # every term negative: the sign outside the brackets
    (-R**2 * m * W**2 * sp.sin(th)**2 / 2 - R * g * m * sp.cos(th), "−1/2 R m (Ω² R sin(θ)² + 2 g cos(θ))"),
    (-sp.Rational(3, 2) * M * r**2 - e**2 * m - 2 * e * m * r - m * r**2, "−(3/2 M r² + e² m + 2 e m r + m r²)"),
]


@pytest.mark.parametrize("expr, form", CASES, ids=[f for _, f in CASES])
def test_the_exam_form_of_a_sum(expr, form):
    shown = factored(sp.expand(expr))
    assert sp.simplify(shown - expr) == 0  # the same expression
    assert to_unicode(shown) == form


@pytest.mark.parametrize("expr", [
    e + 1, a - b, g - R * W**2, 9 * sp.pi - 16,
    12 * R**2 * th**2 + 4 * a**2 + b**2,  # irreducible, nothing in common
])
def test_no_rule_that_lengthens_or_does_nothing(expr):
    assert to_unicode(factored(expr)) == to_unicode(expr)


def test_a_difference_of_squares_is_put_back_together():
    assert squares_joined((a - b) * (a + b) * (a - c) * (a + c)) == (a**2 - b**2) * (a**2 - c**2)
    assert squares_joined((a - b) * (a + c)) == (a - b) * (a + c)  # no conjugate pair: kept


def test_numbers_first_and_zero_terms_dropped():
    assert to_unicode((1 + e) * m) == "m (1 + e)"
    assert to_unicode(1 - e**2) == "1 − e²"
    terms = Terms((Product(m, (sp.Symbol("x"),)), Product(sp.Integer(0), (sp.Symbol("y"),))))
    assert to_unicode(terms) == "m x"


def test_a_coefficient_over_a_symbol_divides_the_whole():
    assert to_unicode(Product(1 / m, (sp.Symbol("lambda_A"),))) == "λ_A/m"


@pytest.mark.parametrize("expr, form", [
    (sp.sqrt(-2 * g * (sp.cos(th) - 1) / R), "√2 √g √(1 − cos(θ))/√R"),  # no leading minus under the root
    ((-a * sp.sin(th) - b * sp.sin(th + W)) * e, "−e (a sin(θ) + b sin(Ω + θ))"),  # a negative sum's sign out
    (a**2 * m * (4 - 2 * sp.pi) / sp.pi, "−a² m (2 π − 4)/π"),  # a negative number's sign out
    (-2 * g / (3 * (r - R)), "2 g/(3 (R − r))"),
    (-g * m * (R - r), "−g m (R − r)"),  # kept: the sign is outside a difference already written R − r
])
def test_signs_where_a_worked_solution_puts_them(expr, form):
    assert to_unicode(expr) == form


def test_a_coefficient_in_brackets_counts_them() -> None:
    """Before q̈ a sum prints in brackets, so 1/3 a² (M + 3m) θ̈ is no longer than
    (1/3 M a² + a² m) θ̈ — and a sum that stays a sum gains nothing."""
    assert to_unicode(factored(M * a**2 / 3 + a**2 * m, bracketed=True)) == "1/3 a² (M + 3 m)"
    assert to_unicode(factored(M * a**2 / 3 + a**2 * m)) == "1/3 M a² + a² m"


x, y, z, w = sp.symbols("x y z w")


@pytest.mark.parametrize("expr, splits", [
    (x * y + 2 * z + 3, False),  # linear in z, gcd(2, xy + 3) = 1
    (x * y + x * z, True),  # linear in y, but x divides both parts: x (y + z)
    (6 * x * y + 4 * x, True),  # 2x (3y + 2): x is a factor, the 2 is not counted
    (4 * x * y + 6 * z + 2, False),  # 2 (2xy + 3z + 1): a number alone is no factor
    (x**2 * y + x**2 + y * z**2 + z**2, True),  # (x² + z²)(y + 1): linear in y, gcd x² + z²
    (x**2 - y**2, True),  # no variable of degree 1: factored, (x − y)(x + y)
    (x**2 + y**2, False),
    ((x + 1)**2 * y, True),  # linear in y, b = 0: the gcd (x + 1)² is not a number
    (x**2 * w - 3 * y * z**2 + 7, False),  # linear in w, gcd(x², 7 − 3yz²) = 1
    (31 * x / 2 + 29 * y / 2 + 3 * z + w / 2, False),  # a = 31/2, a number: no gcd taken (a chain's V)
    (3 * x + 6 * y * z**2 + 9 * z, False),  # a = 3 divides b: the number alone is no factor
])
def test_whether_a_polynomial_splits(expr, splits):
    """By hand: a factor of a x + b of degree 0 in x divides a and b."""
    symbols = sorted(expr.free_symbols, key=sp.default_sort_key)
    assert _splits(sp.Poly(expr, *symbols)) is splits



def test_a_polynomial_of_high_degree_is_not_factored(monkeypatch) -> None:
    """Issue 39: sin⁹⁷θ + cos⁹⁹θ is two operations to count_ops, but its derivatives are
    polynomials of degree ~200 in sin θ and cos θ, which sympy's factoring took minutes
    over (7 s and more for a model that took 0.76 s). Past MAX_DEGREE nothing is factored:
    neither factor_list nor factor is called, and the expression is shown as it is."""
    from rbdsolve.form import factor as module

    def refuse(*args, **kwargs):
        raise AssertionError("factored a polynomial of high degree")

    monkeypatch.setattr(module, "_splits", refuse)
    monkeypatch.setattr(module.sp, "factor", refuse)
    s, c, m, g = sp.Symbol("s"), sp.Symbol("c"), sp.Symbol("m", positive=True), sp.Symbol("g", positive=True)
    theta = sp.Function("theta")(sp.Symbol("t"))
    high = m * g * (97 * sp.sin(theta) ** 96 * sp.cos(theta) - 99 * sp.cos(theta) ** 98 * sp.sin(theta))
    assert module.factored(high) == high
    assert module.factored_sum(sp.expand(3 * s**30 * c**2 + 6 * s * c**29)) == 3 * s * c**2 * (s**29 + 2 * c**27)
