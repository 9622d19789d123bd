"""form/mathml.py: the exam's conventions in MathML, and markup an XML parser reads."""

from __future__ import annotations

import xml.etree.ElementTree as ET

import pytest
import sympy as sp

from rbdsolve.form.display import Along, Label, Product, Relation, Scaled, Terms
from rbdsolve.form.mathml import relation_mathml, to_mathml
from rbdsolve.model.state import t, user_function

g, r, m, l = sp.symbols("g r m l", positive=True)
theta, phi = user_function("theta")(t), user_function("phi")(t)
x_f = user_function("x_f")(t)


def tree(markup: str) -> ET.Element:
    return ET.fromstring(markup)  # raises on markup that is not well-formed


def texts(element: ET.Element) -> list[str]:
    return [e.text for e in element.iter() if e.text]


def test_a_coordinate_is_its_letter_and_its_rates_carry_dots() -> None:
    assert to_mathml(theta) == "<mi>θ</mi>"
    one, two = tree(to_mathml(sp.Derivative(theta, t))), tree(to_mathml(sp.Derivative(phi, (t, 2))))
    assert one.tag == two.tag == "mover" and one.get("accent") is None  # a script: clear above (test_html)
    assert texts(one) == ["θ", "\u02d9"] and texts(two) == ["φ", "\u00a8"]
    squared = tree(to_mathml(sp.Derivative(theta, t) ** 2))  # θ̇², no brackets
    assert squared.tag == "msup" and squared[0].tag == "mover" and "(" not in texts(squared)
    sub = tree(to_mathml(sp.Derivative(x_f, t)))  # ẋ_f: the dot over x, f below after it
    assert sub.tag == "msub" and sub[0].tag == "mover" and texts(sub) == ["x", "\u02d9", "f"]


def test_fractions_roots_and_names() -> None:
    omega = tree(to_mathml(2 * sp.sqrt(6) * sp.sqrt(g) / (5 * sp.sqrt(r))))
    assert omega.find(".//mfrac") is not None and len(omega.findall(".//msqrt")) == 3
    lead = tree(to_mathml(sp.Rational(7, 4) * m * r**2 * sp.Derivative(theta, (t, 2))))
    assert lead[0].tag == "mfrac" and texts(lead[0]) == ["7", "4"]  # 7/4 in front, as the exam writes it
    assert tree(to_mathml(sp.Symbol("omega0"))).tag == "msub"
    assert texts(tree(to_mathml(sp.Symbol("lamda")))) == ["λ"]


def test_minus_signs_are_minus_signs() -> None:
    for value in (g - r, sp.Integer(-2), -sp.Rational(1, 2), sp.Float(-2.5), -g * m):
        markup = to_mathml(value)
        assert "−" in markup and "<mo>-</mo>" not in markup and "-2" not in markup, markup


def test_matrices_and_vectors_are_tables() -> None:
    matrix = tree(to_mathml(sp.Matrix([[sp.Rational(7, 4), 1], [1, sp.Rational(1, 3)]])))
    assert [texts(matrix)[0], texts(matrix)[-1]] == ["[", "]"] and len(matrix.findall(".//mtr")) == 2
    assert len(matrix.findall(".//mtd")) == 4 and len(matrix.findall(".//mfrac")) == 2
    vector = tree(to_mathml(sp.Matrix([1, -3])))
    assert [texts(vector)[0], texts(vector)[-1]] == ["(", ")"] and len(vector.findall(".//mtr")) == 2


def test_display_values_keep_their_arrangement() -> None:
    scaled = tree(to_mathml(Scaled(m * r**2, Terms((sp.Rational(7, 8) * sp.Derivative(theta, t) ** 2,
                                                     -sp.Rational(1, 6) * sp.Derivative(phi, t) ** 2)))))
    words = texts(scaled)
    assert words[:3] == ["m", "\u2062", "r"] and "[" in words and "−" in words and "+" not in words
    product = tree(to_mathml(Product(-sp.Integer(1), (sp.cos(phi - theta), sp.Derivative(theta, t)))))
    assert texts(product)[0] == "−" and "cos" in texts(product)
    assert texts(tree(to_mathml(Along(sp.Integer(-1), sp.Symbol("e_x"))))) == ["−", "e", "x"]


def test_text_is_escaped_and_entities_are_characters() -> None:
    markup = relation_mathml(Relation(Label("a <b> & c", "a"), sp.pi / 2 * g, lead="stable when"))
    math = tree(markup)
    assert math.tag == "math" and "a <b> & c" in texts(math) and "π" in texts(math)
    assert "&InvisibleTimes;" not in markup and "&pi;" not in markup


@pytest.mark.parametrize("value", [
    sp.Integral(sp.Derivative(theta, t) ** 2, t), sp.Derivative(sp.Symbol("V"), sp.Symbol("theta")),
    sp.Derivative(user_function("alpha_long")(t), (t, 4)), sp.exp(-g * t) * sp.atan2(g, r), sp.Abs(g - r),
    sp.Float(1.5e20), sp.oo, sp.I * g, sp.Piecewise((g, r > 1), (0, True)),
])
def test_whatever_sympy_prints_is_well_formed(value) -> None:
    tree(relation_mathml(Relation(sp.Symbol("y"), value)))


def test_a_subscripted_power_and_a_word_in_a_product() -> None:
    """ω₀² with the 2 over the 0 (msubsup); r·spin with a thin space, not 'rspin'."""
    power = tree(to_mathml(sp.Symbol("omega0") ** 2))
    assert power.tag == "msubsup" and texts(power) == ["ω", "0", "2"]
    product = tree(relation_mathml(Relation(sp.Symbol("x"), sp.Symbol("r") * sp.Symbol("spin"))))
    assert product.find(".//mspace") is not None


def test_a_float_holds_the_digits_asked_as_in_the_other_formats() -> None:
    """The HTML key's numeric block printed θ = 3.14159265358979 and θ = 0.0 (sympy's
    own printer, all 15 digits); a float is now to --digits, a small one as 2.5·10⁻⁷."""
    from rbdsolve.form.printers import significant_digits

    assert texts(tree(to_mathml(sp.Float(3.14159265358979)))) == ["3.14159"]
    assert texts(tree(to_mathml(sp.Float(0.0)))) == ["0"]
    with significant_digits(3):
        assert texts(tree(to_mathml(sp.Float(-2.71828)))) == ["−", "2.72"]
    small = tree(to_mathml(sp.Float(2.5e-7)))
    assert texts(small) == ["2.5", "·", "10", "−7"] and small.find("msup") is not None
