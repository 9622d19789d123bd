"""A matrix in LaTeX prints an entry that recurs (a symmetric M's mirrored entries)
once and sets it in each of its places: the text is the entries printed one by one
(the oracle), floats at different precisions included."""

from __future__ import annotations

import sympy as sp

from rbdsolve.form.printers import _TEX, to_latex

x, y = sp.symbols("x y")


def test_a_matrix_with_recurring_entries_prints_each_in_place() -> None:
    M = sp.ImmutableMatrix([[x**2, sp.cos(x - y), sp.Float(0.5)], [sp.cos(x - y), y / 2, sp.Float(0.5, 30)],
                            [sp.Float(0.5), sp.Float(0.5, 30), x**2]])
    rows = " \\\\ ".join(" & ".join(_TEX.doprint(e) for e in row) for row in M.tolist())
    assert to_latex(M) == f"\\begin{{bmatrix}} {rows} \\end{{bmatrix}}"
    assert to_latex(M).count(r"\cos") == 2


def test_a_column_with_recurring_entries_prints_each_in_place() -> None:
    column = sp.ImmutableMatrix([x**2, x**2, y])
    items = " \\\\ ".join(_TEX.doprint(e) for e in column)
    assert to_latex(column) == f"\\begin{{pmatrix}} {items} \\end{{pmatrix}}"
