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
