"""Conditions on the parameters as a worked solution writes them: Ω < Ω_c with the
critical value by name (Ω_c = √(g/R)), or r < R where the critical value is another
parameter; shared by every family that answers case by case."""

from __future__ import annotations

import sympy as sp

from rbdsolve.form.display import Relation
from rbdsolve.report import steps as st


def _named(value: sp.Expr) -> bool:
    """Whether a critical value gets a name (Ω_c = √(g/R)); another parameter (r < R) or
    a number (θ < π/2) reads as itself."""
    return not isinstance(value, sp.Symbol) and bool(value.free_symbols)


def critical_steps(critical, where: str = "where an equilibrium appears or its stability changes") -> list[st.Step]:
    """The critical values by name: Ω_c = √(g/R)."""
    named = [c for c in critical if _named(c.value)]
    if not named:
        return []
    return [st.result("Critical value" + ("s" if len(named) > 1 else "") + f", {where}:",
                      *[Relation(sp.Symbol(f"{c.parameter}_c"), c.value) for c in named])]


def condition_relation(condition, named: dict, lead: str = "") -> Relation:
    """p < p_c with p_c by name where it is a critical value: Ω < Ω_c."""
    ops = {sp.StrictLessThan: "<", sp.LessThan: "≤", sp.StrictGreaterThan: ">", sp.GreaterThan: "≥"}
    lhs, rhs = condition.lhs, condition.rhs
    for c in named.values():
        if isinstance(lhs, sp.Symbol) and lhs.name == c.parameter and sp.simplify(rhs - c.value) == 0 \
                and _named(c.value):
            rhs = sp.Symbol(f"{c.parameter}_c")
    return Relation(lhs, rhs, ops.get(type(condition), "?"), lead=lead)
