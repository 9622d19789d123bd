"""render/numbers.py: the numeric block's lines under their headings."""

from __future__ import annotations

import sympy as sp

from rbdsolve.form.display import Relation
from rbdsolve.render.numbers import groups
from rbdsolve.report.numbers import Number


def _n(name: str, group: str) -> Number:
    return Number(Relation(sp.Symbol(name), sp.Float(1.0)), group=group)


# A steady motion's answers list Ω for each solution, then ω for each: each solution's
# numbers stand under one heading, in the order met; lines without a heading stay put.
def test_a_heading_met_again_joins_its_first_place() -> None:
    numbers = (_n("x", ""), _n("Omega", "Solution 1"), _n("Omega", "Solution 2"), _n("omega", "Solution 1"),
               _n("omega", "Solution 2"), _n("y", ""))
    got = [(heading, [str(n.relation.lhs) for n in lines]) for heading, lines in groups(numbers)]
    assert got == [("", ["x"]), ("Solution 1", ["Omega", "omega"]), ("Solution 2", ["Omega", "omega"]), ("", ["y"])]
