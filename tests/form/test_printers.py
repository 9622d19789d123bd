"""form/printers.py: how names are written in prose on a typeset page."""

from __future__ import annotations


# A subscripted name in prose (v_C: unicode has no subscript capitals) is set as a
# subscript on a typeset page; a file's own name in quotes, or one inside a word
# (long_rod), stays as written.
def test_prose_pieces_find_the_subscripted_names_only() -> None:
    from rbdsolve.form.printers import prose_pieces

    pieces = prose_pieces("at C: v_C = 0, J_Gz and a_O' · r', body 'k_1', long_rod")
    assert [(base, sub) for _, base, sub in pieces if base] == [("v", "C"), ("J", "Gz"), ("a", "O")]
    assert "".join(before + (f"{base}_{sub}" if base else "") for before, base, sub in pieces) == \
        "at C: v_C = 0, J_Gz and a_O' · r', body 'k_1', long_rod"


def test_a_typeset_page_writes_v_c_with_its_subscript() -> None:
    from rbdsolve.render.html import _prose
    from rbdsolve.render.latex import prose

    assert _prose("v_C = 0 ⇒") == "<i>v</i><sub>C</sub> = 0 ⇒"
    assert prose("v_C = 0, J_Gz") == r"\ensuremath{v_{C}} = 0, \ensuremath{J_{\mathrm{Gz}}}"


def test_a_minus_after_an_absolute_value_or_a_bracket_is_the_minus_sign() -> None:
    """'|cos θ| − g m', not the ASCII hyphen '- g m' (a ladder's reactions printed it)."""
    import sympy as sp

    from rbdsolve.form.printers import to_unicode

    a, b = sp.symbols("alpha b", real=True)
    assert to_unicode(b * sp.Abs(a) - 4) == "b |α| − 4"
    assert to_unicode(12 * sp.pi * sp.sin(a) * sp.Abs(sp.sin(a)) - 4 * b) == "12 π sin(α) |sin(α)| − 4 b"
    assert " - " not in to_unicode(sp.Abs(a) / sp.cos(a) - sp.Abs(b) / sp.sin(a))


def test_latex_joins_a_term_whose_sign_moves_by_its_one_sign() -> None:
    """N_P cos θ − g m − k (−R cos θ − h) is N_P cos θ − g m + k (R cos θ + h); LaTeX wrote
    '- g m - - k (…)' (a bead on a spring inside a loop, its free body diagram)."""
    import sympy as sp

    from rbdsolve.form.printers import to_latex

    N, g, m, k, R, h, th = sp.symbols("N_P g m k R h theta")
    text = to_latex(N * sp.cos(th) - g * m - k * (-R * sp.cos(th) - h))
    assert "- -" not in text and "+ -" not in text
    assert text.endswith("- g m + k \\left(R \\cos{\\left(\\theta \\right)} + h\\right)")


def test_a_norm_s_name_is_typeset_between_bars() -> None:
    from rbdsolve.form.printers import latex_name

    # a speed's name |v_B| in the kinematics' numeric block; it was \mathrm{|v}_{\mathrm{B|}}
    assert latex_name("|v_B|") == "\\left|v_{B}\\right|"
    assert latex_name("|OB|") == "\\left|\\mathrm{OB}\\right|"
