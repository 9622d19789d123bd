"""Numbers in text (form/printers.py): significant digits as asked, and floats that are
zero within rounding beside their neighbours printed as 0 or left out of a sum."""

from __future__ import annotations

import sympy as sp

from rbdsolve.form.printers import float_text, significant_digits, to_latex, to_unicode, within_rounding

x, y = sp.symbols("x y")


def test_six_significant_digits_by_default() -> None:
    assert to_unicode(sp.Float(9.41760000000000, 15)) == "9.4176"
    assert to_unicode(sp.Float(2.0 / 3.0, 15)) == "0.666667"
    assert to_unicode(sp.Float(-2.5e-7, 15) * x) == "−2.5e-7 x"  # no padded exponent
    assert float_text(-1.0) == "−1"


def test_digits_as_asked() -> None:
    with significant_digits(3):
        assert to_unicode(sp.Float(3.14159265, 15) * x) == "3.14 x"
        assert to_latex(sp.Float(6.02214e23, 15)) == "6.02 \\cdot 10^{23}"
    with significant_digits(12):
        assert to_unicode(sp.Float(3.14159265358979, 15)) == "3.14159265359"
    assert to_unicode(sp.Float(3.14159265, 15)) == "3.14159"  # the default again after the block


def test_a_vector_entry_zero_within_rounding_is_zero() -> None:
    v = sp.ImmutableMatrix([[sp.Float(1.5, 15), sp.Float(-3.08148791102e-32, 15), sp.Float(1e-9, 15)]])
    assert to_unicode(v) == "(1.5, 0, 1e-9)"  # 1e-9 is a value beside 1.5, not rounding
    assert "10^{-32}" not in to_latex(v)
    assert within_rounding([sp.Float(1.0), sp.Float(1e-15), sp.Integer(0)]) == {1}
    assert within_rounding([sp.Float(1e-15)]) == set()  # alone, nothing says it is noise


def test_a_term_zero_within_rounding_leaves_the_sum() -> None:
    assert to_unicode(sp.Float(1.5, 15) * x + sp.Float(-3.08e-32, 15) * y) == "1.5 x"
    assert to_unicode(x + sp.Float(1e-20, 15) * y) == "x + 1e-20 y"  # an exact term is never judged


def test_a_negative_energy_lost_reads_as_energy_gained() -> None:
    from rbdsolve.render.numbers import numeric_lines

    assert numeric_lines({"energy_lost": -1.44}, {"energy_lost": "J"}) == [
        "energy_lost = −1.44 J (an energy gained of 1.44 J)"]
    assert numeric_lines({"energy_lost": 0.5}) == ["energy_lost = 0.5"]
