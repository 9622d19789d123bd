"""A difference written as an exam writes it (issue 27): the positive term first."""

from __future__ import annotations

import sympy as sp

from rbdsolve.form.printers import to_latex, to_unicode

g, R, W, a = sp.symbols("g R Omega a", positive=True)


def test_a_positive_term_leads() -> None:
    assert to_unicode(g - R * W**2) == "g − Ω² R"
    assert to_unicode(9 * sp.pi - 16) == "9 π − 16"
    assert to_unicode(sp.sqrt(a - 2 * R)) == "√(a − 2 R)"
    assert to_latex(g - R * W**2) == r"g - \Omega^{2} R"


def test_all_negative_sums_keep_their_order() -> None:
    assert to_unicode(-g - R) == "−R − g"


def test_a_sign_goes_into_a_difference() -> None:
    r = sp.Symbol("r", positive=True)
    assert to_unicode(-2 * g / (3 * (r - R))) == "2 g/(3 (R − r))"  # the seed's 2g/(3(R − r))
    assert to_latex(-2 * g / (3 * (r - R))) == r"\frac{2 g}{3 \left(R - r\right)}"
    assert to_unicode(-6 * g * (a - 2 * R)) == "6 g (2 R − a)"
    assert to_unicode(-(g + R)) == "−R − g"  # nothing to take the sign: as it was


def test_an_even_power_of_a_difference_reads_positive_first() -> None:
    r = sp.Symbol("r", positive=True)
    assert to_unicode((r - R) ** 2) == "(R − r)²"
    assert to_latex((r - R) ** 2) == r"\left(R - r\right)^{2}"


def test_a_sign_goes_into_a_difference_below_the_line() -> None:
    b, h = sp.symbols("b h", positive=True)
    # a critical rate Ω_c² = 6gh/(4h² − b²), not −6gh/(b² − 4h²)
    assert to_unicode(-6 * g * h / (b**2 - 4 * h**2)) == "6 g h/(4 h² − b²)"
    assert to_unicode(-6 * g * h / (W**2 * b**2 - 4 * W**2 * h**2)) == "6 g h/(Ω² (4 h² − b²))"
    assert to_latex(-6 * g * h / (b**2 - 4 * h**2)) == r"\frac{6 g h}{4 h^{2} - b^{2}}"
    assert to_unicode(-g * R * (a - b)) == "−R g (a − b)"  # above the line: as written


def test_two_differences_turn_together_where_the_product_keeps_its_sign() -> None:
    r, t = sp.symbols("r theta0", positive=True)
    # a disk released at θ₀ inside a cylinder: θ̇² = 4 g (1 − cos θ₀)/(3 (R − r)) at the bottom
    assert to_unicode(4 * g * (sp.cos(t) - 1) / (3 * r - 3 * R)) == "4 g (1 − cos(θ₀))/(3 (R − r))"
    assert to_unicode(g * (r - R)) == "g (r − R)"  # one difference alone keeps its sign as written


def test_a_number_taken_out_of_a_turned_difference_joins_the_coefficient() -> None:
    x, y = sp.symbols("x y", positive=True)
    assert to_unicode(g * (2 * x - 2) / (3 * y - 3)) == "2 g (1 − x)/(3 (1 − y))"  # not g 2 (1 − x)/…
    assert to_latex(g * (2 * x - 2) / (3 * y - 3)) == r"\frac{2 g \left(1 - x\right)}{3 \left(1 - y\right)}"
    assert to_unicode((x / 2 - sp.Rational(1, 2)) * (y - 1)) == "1/2 (1 − x) (1 − y)"
