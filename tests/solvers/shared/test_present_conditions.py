"""Conditions written as a worked solution writes them (solvers/shared/present_conditions.py):
a union of intervals (sympy's Or) is written alternative by alternative, never as one
relation (an Or has no sides: exit 3 once, tests/oracles/neighbours_found/
spring-pendulum-reactions-or.yaml)."""

from __future__ import annotations

import sympy as sp

from rbdsolve.solvers.shared.present_conditions import condition_relations, condition_text

k, x = sp.symbols("k x", real=True)


def test_a_union_alone_is_written_alternative_by_alternative() -> None:
    relations = condition_relations(sp.Or(k < 1, k > 2))
    assert sorted((str(r.lhs), r.op, str(r.rhs)) for r in relations) == [("k", "<", "1"), ("k", ">", "2")]
    assert [r.lead for r in relations] == ["", "or"]


def test_a_union_inside_a_conjunction_is_led_by_either() -> None:
    relations = condition_relations(sp.And(x > 0, sp.Or(k < 1, k > 2)))
    assert sorted((str(r.lhs), r.op, str(r.rhs)) for r in relations) == [("k", "<", "1"), ("k", ">", "2"),
                                                                          ("x", ">", "0")]
    leads = [r.lead for r in relations if str(r.lhs) == "k"]
    assert leads == ["either", "or"]
    text = condition_text(sp.And(x > 0, sp.Or(k < 1, k > 2)))
    assert sorted(text.split(" and ")) == sorted(["x > 0", "(k > 2 or k < 1)"]) or \
        sorted(text.split(" and ")) == sorted(["x > 0", "(k < 1 or k > 2)"]), text
