"""Sums over coordinates numbered past nine are printed in counting order (issue 23's
16-link chain): th₁, th₂, …, th₁₀, not sympy's th₁, th₁₀, th₂; and cos(th₂ − th₁₀)."""

from __future__ import annotations

import sympy as sp

from rbdsolve.form.mathml import to_mathml
from rbdsolve.form.printers import to_latex, to_unicode

th = sp.symbols("th1:13")  # th1 … th12
t = sp.Symbol("t", real=True)


def test_a_sum_over_twelve_coordinates_counts_them_in_order() -> None:
    V = sum((13 - i) * sp.cos(q) for i, q in enumerate(th, start=1))
    shown = to_unicode(V)
    positions = [shown.index(f"cos(th{str(i).translate(str.maketrans('0123456789', '₀₁₂₃₄₅₆₇₈₉'))})")
                 for i in range(1, 13)]
    assert positions == sorted(positions)
    assert shown.startswith("12 cos(th₁) + 11 cos(th₂)") and shown.endswith("2 cos(th₁₁) + cos(th₁₂)")


def test_a_cosine_of_a_difference_takes_the_lower_number_first() -> None:
    e = sp.cos(th[9] - th[1])  # sympy keeps cos(th10 − th2)
    assert to_unicode(e) == "cos(th₂ − th₁₀)"
    latex = to_latex(e)
    assert latex.index("_{2}") < latex.index("10") and "- " in latex
    assert to_unicode(sp.cos(th[1] - th[2])) == "cos(th₂ − th₃)"  # already in order: as it was


def test_a_sine_keeps_its_sign_and_single_digits_keep_sympys_order() -> None:
    assert to_unicode(sp.sin(th[9] - th[1])) == "sin(th₁₀ − th₂)"  # sin is odd: not turned round
    a, b = sp.symbols("phi theta")
    assert to_unicode(sp.cos(a - b)) == "cos(φ − θ)"
    assert to_unicode(sp.cos(b - a)) == to_unicode(sp.cos(a - b))


def test_coordinates_of_time_and_mathml_count_the_same_way() -> None:
    q = [sp.Function(f"th{i}")(t) for i in (1, 2, 10, 11)]
    shown = to_unicode(sp.cos(q[0]) + sp.cos(q[2]) + sp.cos(q[1]) + sp.cos(q[3]))
    assert shown == "cos(th₁) + cos(th₂) + cos(th₁₀) + cos(th₁₁)"
    markup = to_mathml(sp.cos(q[2] - q[1]))
    assert markup.index("th") < markup.index("10") and markup.index(">2<") < markup.index("10")


def test_only_the_numbers_in_names_count() -> None:
    """√3, l² and 0.25 are not coordinate numbers: terms that differ in them stay in
    sympy's order (a reviewer's cases)."""
    l = sp.Symbol("l")
    shown = to_unicode(sp.sqrt(3) * sp.cos(th[0]) + sp.sqrt(2) * sp.cos(th[9]) + sp.cos(th[1]))
    assert shown.index("√3 cos(th₁)") < shown.index("√2 cos(th₁₀)")
    assert to_unicode(l * sp.cos(th[0]) + l * sp.cos(th[9]) + l * sp.cos(th[1])) == \
        "l cos(th₁) + l cos(th₂) + l cos(th₁₀)"


def test_a_complex_number_is_written_real_part_first() -> None:
    """Gyroscopic roots as a textbook writes them: the real part, then ± the imaginary
    (a new user's trial printed p₃ = 3.58118 i + 3.58404 beside p₄ = 3.58404 − 3.58118 i)."""
    from rbdsolve.form.printers import to_unicode

    assert to_unicode(sp.Float(3.58404, 15) + sp.I * sp.Float(3.58118, 15)) == "3.58404 + 3.58118 i"
    assert to_unicode(sp.Float(3.58404, 15) - sp.I * sp.Float(3.58118, 15)) == "3.58404 − 3.58118 i"
    assert to_unicode(sp.Float(-1.5, 15) + sp.I * 2) == "−1.5 + 2 i"
    assert to_unicode(sp.I * sp.Float(32.2, 15)) == "32.2 i"
    theta = sp.Symbol("theta")
    assert to_unicode(1 - sp.cos(theta) ** 2) == "1 − cos(θ)²"  # a real sum keeps the exam's order
