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
