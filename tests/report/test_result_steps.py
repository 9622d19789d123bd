"""report/steps.py: a result's values in the factored form that reads no longer."""

from __future__ import annotations

import sympy as sp

from rbdsolve.form.display import Along, Relation, Terms
from rbdsolve.form.printers import to_unicode
from rbdsolve.report import steps as st


def test_a_vector_along_its_basis_is_factored_component_by_component() -> None:
    """A rod struck at depth d by a ball that bounces (restitution e): the pivot's
    impulse M l m v₀ (3de + 3d − 2el − 2l)/(2 (M l² + 3 d² m)) along eₓ, whose sum is
    (1 + e)(3d − 2l) by hand."""
    M, l, m, v0, d, e = sp.symbols("M l m v_0 d e", positive=True)
    ex, ey = sp.symbols("e_x e_y")
    x = M * l * m * v0 * (3 * d * e + 3 * d - 2 * e * l - 2 * l) / (2 * (M * l**2 + 3 * d**2 * m))
    (alone,) = st.result("", Relation(sp.Symbol("P"), Along(x, ex))).math
    assert to_unicode(alone.rhs.component) == "M l m v₀ (3 d − 2 l) (1 + e)/(2 (M l² + 3 d² m))"
    (both,) = st.result("", Relation(sp.Symbol("P"), Terms((Along(x, ex), Along(2 * x, ey))))).math
    assert all("(3 d − 2 l) (1 + e)" in to_unicode(part.component) for part in both.rhs.items)
