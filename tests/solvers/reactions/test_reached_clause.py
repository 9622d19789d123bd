"""The clause that says what a zero along the motion needs to be a place at all: |c| ≤ 1
where it is cos q = c or q = acos(c), written with the c itself; nothing for q = c (a new
user's pulley on a torsion spring c read "(|c| ≤ 1, and q̇² ≥ 0 there)" beside its own c)."""

from __future__ import annotations

import sympy as sp

from rbdsolve.solvers.reactions.steps import _bounded

theta, theta0, M, g, k, R, c = sp.symbols("theta theta0 M g k R c", positive=True)


def test_the_clause_names_what_must_lie_in_the_unit_interval() -> None:
    assert _bounded(sp.Eq(sp.cos(theta), 2 * sp.cos(theta0) / 3)) == "|2/3 cos(θ₀)| ≤ 1, and "
    assert _bounded(sp.Eq(theta, sp.acos(2 * sp.cos(theta0) / 3))) == "|2/3 cos(θ₀)| ≤ 1, and "
    assert _bounded(sp.Eq(theta, M * g * k**2 / (R * c))) == ""
    long = (4 * g * M * sp.cos(theta0) - 3 * R * k - 3 * k * c) / (7 * g * M)
    assert _bounded(sp.Eq(sp.cos(theta), long)) == "the right side in [−1, 1], and "
