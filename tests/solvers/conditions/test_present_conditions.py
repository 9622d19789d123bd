"""Conditions as a worked solution writes them (solvers/conditions/present_conditions.py):
a union of pieces (k > k₁ or k ≤ k₂) is written, never taken for one relation (issue
38: "'Or' object has no attribute 'lhs'", exit 3)."""

from __future__ import annotations

import sympy as sp

from rbdsolve.form.printers import to_unicode
from rbdsolve.solvers.conditions.present_conditions import condition_relation, condition_relations, condition_text

k, g, h, m, a = sp.symbols("k g h m a", positive=True)
UNION = sp.Or(sp.Gt(k, g * m / h), sp.Le(k, a))


def _line(r) -> str:
    return " ".join(filter(None, [r.lead, to_unicode(r.lhs), r.op, to_unicode(r.rhs),
                                  *(f"{r.more_op} {to_unicode(x)}" for x in r.more)]))


def test_a_union_alone_is_one_line_a_piece() -> None:
    lines = [_line(r) for r in condition_relations(UNION)]
    assert sorted(lines) == sorted(["k ≤ a", "or k > g m/h"]) or sorted(lines) == sorted(["k > g m/h", "or k ≤ a"])


def test_a_union_within_a_conjunction_reads_either_or() -> None:
    lines = [_line(r) for r in condition_relations(sp.And(UNION, sp.Gt(h, a)))]
    assert len(lines) == 3 and "h > a" in lines
    assert sum(x.startswith("either ") for x in lines) == 1 and sum(x.startswith("or ") for x in lines) == 1


def test_a_union_in_one_line_and_in_a_sentence() -> None:
    assert _line(condition_relation(UNION, lead="when")) in ("when k ≤ a or k > g m/h", "when k > g m/h or k ≤ a")
    assert condition_text(UNION) in ("k ≤ a or k > g m/h", "k > g m/h or k ≤ a")
    pieces = ("(k ≤ a or k > g m/h)", "(k > g m/h or k ≤ a)")
    assert condition_text(sp.And(UNION, sp.Gt(h, a))) in [*(f"{p} and h > a" for p in pieces),
                                                          *(f"h > a and {p}" for p in pieces)]
