"""A conjunction of bounds on parameters, tightened: a bound that another on the same
side implies, or an alternative that a bound beside it rules out, is left out — for
every value the assumptions allow (conditions.py's ``exists_when`` writes one condition
per radicand, and two of them often bound one parameter twice)."""

from __future__ import annotations

import sympy as sp

from rbdsolve.solvers.conditions.signs import sign_of

_UPPER, _LOWER = (sp.LessThan, sp.StrictLessThan), (sp.GreaterThan, sp.StrictGreaterThan)


def tightest_bounds(exists: sp.Basic, model) -> tuple[sp.Basic, frozenset]:
    """The conjunction with a bound that another on the same side implies left out
    (Ω ≤ √(k/m) and Ω ≤ √(k (L + d)/(d m)): the second follows from the first, for every
    value the assumptions allow), and the values of the bounds left out; first, each
    alternative a bound of the conjunction rules out (``_without_contradicted``)."""
    exists, ruled_out = _without_contradicted(exists, model)
    parts = list(sp.And.make_args(exists))
    dropped = set()
    for side in (_UPPER, _LOWER):
        bounds = [r for r in parts if isinstance(r, side) and r.lhs.is_Symbol]
        for a in bounds:
            for b in bounds:
                if a is b or a in dropped or b in dropped or a.lhs != b.lhs:
                    continue
                order = _compared(a.rhs, b.rhs, model)
                if order is not None and (order < 0 if side is _UPPER else order > 0):
                    dropped.add(b)  # a is the tighter bound: b follows from it
    if not dropped:
        return exists, ruled_out
    return sp.And(*[r for r in parts if r not in dropped]), ruled_out | frozenset(r.rhs for r in dropped)


def _without_contradicted(exists: sp.Basic, model) -> tuple[sp.Basic, frozenset]:
    """Each alternative of an "either … or" that a plain bound beside it rules out, left
    out: k > g m/(4 a) and (k ≥ g m/(3 a) or k ≤ g m/(5 a)) is k > g m/(4 a) and k ≥ g m/(3 a),
    since g m/(5 a) < g m/(4 a) for every value allowed (a rod on a wall spring, its pair of
    equilibria); and the values of the alternatives left out."""
    parts = list(sp.And.make_args(exists))
    bounds = [r for r in parts if isinstance(r, (*_UPPER, *_LOWER)) and r.lhs.is_Symbol]
    ruled_out, out = set(), []
    for part in parts:
        if not isinstance(part, sp.Or):
            out.append(part)
            continue
        kept = [b for b in part.args if not any(_contradicts(a, b, model) for a in bounds)]
        ruled_out |= {b.rhs for b in part.args if b not in kept}
        out.append(sp.Or(*kept))
    return (sp.And(*out), frozenset(ruled_out)) if ruled_out else (exists, frozenset())


def leaves_no_room(exists: sp.Basic, model) -> bool:
    """Whether a conjunction holds at one value at most: a lower bound on a parameter at or
    above an upper bound on it (θ₀ ≥ π/2 and θ₀ ≤ π/2), for every value the assumptions allow."""
    parts = list(sp.And.make_args(exists))
    lower = [r for r in parts if isinstance(r, _LOWER) and r.lhs.is_Symbol]
    upper = [r for r in parts if isinstance(r, _UPPER) and r.lhs.is_Symbol]
    return any(a.lhs == b.lhs and sign_for_every_value(a.rhs - b.rhs, model) in (0, 1) for a in lower for b in upper)


def _contradicts(bound: sp.Relational, other: sp.Basic, model) -> bool:
    """Whether no value satisfies both: p > a beside p ≤ c with c < a (or the mirror),
    the order of a and c decided for every value the assumptions allow."""
    if not isinstance(other, (*_UPPER, *_LOWER)) or other.lhs != bound.lhs:
        return False
    if isinstance(bound, _LOWER) and isinstance(other, _UPPER):
        order = _compared(other.rhs, bound.rhs, model)
        return order is not None and order < 0
    if isinstance(bound, _UPPER) and isinstance(other, _LOWER):
        order = _compared(other.rhs, bound.rhs, model)
        return order is not None and order > 0
    return False


def _compared(a: sp.Expr, b: sp.Expr, model) -> int | None:
    """The sign of a − b for every value the assumptions allow, where it is decided (two
    bounds that are not negative compared by their squares, √(k/m) against
    √(k (L + d)/(d m))); None where it is not, or where they are equal."""
    sign = sign_for_every_value(a - b, model)
    if sign is None and all(sign_for_every_value(x, model) in (0, 1) for x in (a, b)):
        sign = sign_for_every_value(a**2 - b**2, model)
    return sign or None


def sign_for_every_value(x: sp.Expr, model) -> int | None:
    """x's sign under the assumptions alone, x over one denominator (``symbolic_sign``
    factors it where it is short enough)."""
    found = sign_of(sp.cancel(sp.together(x)), model.assumed)
    return found if isinstance(found, int) else None
