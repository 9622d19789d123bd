"""Stand-in symbols for sin θ, cos θ, q̇ … while an expression is factored or
cancelled as a polynomial in them.

They are made in sympy's sort order of what they stand for. A polynomial's generators
are ordered by the stand-ins' creation, and that order decides the signs of the factors,
(x − y)² or (y − x)². Made while iterating a set, the order would follow the set's hash
order, and so change with PYTHONHASHSEED from one run to the next.
"""

from __future__ import annotations

from typing import Iterable

import sympy as sp


def stand_ins(atoms: Iterable[sp.Expr]) -> tuple[dict[sp.Expr, sp.Dummy], dict[sp.Dummy, sp.Expr]]:
    """{atom: a new Dummy}, made in ``default_sort_key`` order of the atoms, and the
    table back {Dummy: atom} that puts them in again."""
    table = {a: sp.Dummy() for a in sorted(atoms, key=sp.default_sort_key)}
    return table, {d: a for a, d in table.items()}
