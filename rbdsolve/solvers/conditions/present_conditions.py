"""Conditions on the parameters as a worked solution writes them: Ω < Ω_c with the
critical value by name (Ω_c = √(g/R)), or r < R where the critical value is another
parameter, θ < π/2 where it is a number; several critical values of one parameter are
Ω_c1 < Ω_c2 … in increasing order. Shared by every family that answers case by case."""

from __future__ import annotations

from typing import Sequence

import sympy as sp

from rbdsolve.form.display import Relation
from rbdsolve.form.printers import to_unicode
from rbdsolve.form.zero import simplifies_to_zero
from rbdsolve.report import steps as st


def _named(value: sp.Expr) -> bool:
    """Whether a critical value gets a name (Ω_c = √(g/R)); another parameter (r < R) or
    a number (θ < π/2) reads as itself."""
    return not isinstance(value, sp.Symbol) and bool(value.free_symbols)


def _size(value: sp.Expr) -> float:
    """The value with every parameter 1 (the order of Ω_c1 and Ω_c2)."""
    z = complex(sp.N(value.xreplace({s: 1 for s in value.free_symbols}), 15))
    return z.real if abs(z.imag) < 1e-12 else float("inf")


def critical_names(critical: Sequence) -> list[tuple[object, sp.Symbol]]:
    """(critical value, its name) for those that get a name: Ω_c, or Ω_c1, Ω_c2, … in
    increasing order where one parameter has several."""
    named = [c for c in critical if _named(c.value)]
    out = []
    for parameter in dict.fromkeys(c.parameter for c in named):
        own = sorted((c for c in named if c.parameter == parameter), key=lambda c: _size(c.value))
        suffixes = [""] if len(own) == 1 else [str(k) for k in range(1, len(own) + 1)]
        out += [(c, sp.Symbol(f"{parameter}_c{k}")) for c, k in zip(own, suffixes)]
    return out


def critical_steps(critical, where: str = "where an equilibrium appears or its stability changes") -> list[st.Step]:
    """The critical values by name: Ω_c = √(g/R)."""
    names = critical_names(critical)
    if not names:
        return []
    return [st.result("Critical value" + ("s" if len(names) > 1 else "") + f", {where}:",
                      *[Relation(name, c.value) for c, name in names])]


OPS = {sp.StrictLessThan: "<", sp.LessThan: "≤", sp.StrictGreaterThan: ">", sp.GreaterThan: "≥", sp.Equality: "="}
TURNED = {"<": ">", "≤": "≥", ">": "<", "≥": "≤", "=": "="}


def condition_relations(condition: sp.Basic, critical: Sequence = ()) -> list[Relation]:
    """Each part of a conjunction as ``condition_relation`` writes it, in sympy's sorted
    order of its parts (``And.args``): ``And.make_args`` gives a frozenset, whose order
    changes with string hashing from one run to the next. A part that is a union of
    pieces (k > k_c1 or k ≤ k_c2: where a pendulum held by a spring reaches the point
    where its rod goes slack) is one line a piece, led by "either" and "or" ("or" alone
    where it is the whole condition)."""
    parts = condition.args if isinstance(condition, sp.And) else (condition,)
    out = []
    for c in parts:
        if isinstance(c, sp.Or):
            first = "either" if len(parts) > 1 else ""
            out += [condition_relation(x, critical, lead="or" if i else first) for i, x in enumerate(c.args)]
        else:
            out.append(condition_relation(c, critical))
    return out


def condition_relation(condition, critical: Sequence = (), lead: str = "") -> Relation:
    """p < p_c with p_c by name where it is one of the ``critical`` values: Ω < Ω_c;
    a piece between two, Ω_c1 < Ω < Ω_c2; a union of pieces in one line, joined by
    "or" (k < k_c1 or k > k_c2)."""
    if isinstance(condition, sp.Or):
        *pieces, last = (condition_relation(x, critical) for x in condition.args)
        joined = " or ".join([*(_relation_text(r) for r in pieces), to_unicode(last.lhs)])
        return Relation(joined, last.rhs, last.op, last.more, lead=lead, more_op=last.more_op)
    if isinstance(condition, sp.And):
        above, below = sorted(condition.args, key=lambda c: OPS.get(type(c), "?") not in (">", "≥"))
        low, high = _named_side(above, critical), _named_side(below, critical)
        return Relation(low, above.lhs, TURNED.get(OPS.get(type(above)), "?"), more=(high,), lead=lead,
                        more_op=OPS.get(type(below), "?"))
    return Relation(condition.lhs, _named_side(condition, critical), OPS.get(type(condition), "?"), lead=lead)


def _named_side(condition, critical: Sequence) -> sp.Expr:
    """The right side of p < value (or |p| < value, a parameter of either sign), by name
    where it is a critical value of p."""
    lhs, rhs = condition.lhs, condition.rhs
    if isinstance(lhs, sp.Abs):
        lhs = lhs.args[0]
    for c, name in critical_names(critical):
        if isinstance(lhs, sp.Symbol) and lhs.name == c.parameter and simplifies_to_zero(rhs - c.value):
            return name
    return rhs


def _relation_text(r: Relation) -> str:
    """One relation in a sentence: Ω_c1 < Ω < Ω_c2."""
    chain = "".join(f" {r.more_op} {to_unicode(x)}" for x in r.more)
    return f"{to_unicode(r.lhs)} {r.op} {to_unicode(r.rhs)}{chain}"


def condition_text(condition: sp.Basic) -> str:
    """A condition in a sentence: Ω ≥ √(g/R), its parts joined by "and", the pieces of
    a union by "or" (in parentheses within a conjunction)."""
    parts = condition.args if isinstance(condition, sp.And) else (condition,)

    def text(c) -> str:
        if isinstance(c, sp.Or):
            joined = " or ".join(text(x) for x in c.args)
            return f"({joined})" if len(parts) > 1 else joined
        if isinstance(c, sp.And):
            return " and ".join(text(x) for x in c.args)
        return f"{to_unicode(c.lhs)} {OPS.get(type(c), '?')} {to_unicode(c.rhs)}"

    return " and ".join(text(c) for c in parts)
