"""An equation or a condition as an answer: 'cos(theta) = 2/3' where contact is lost,
'Omega > sqrt(g/R)' where an equilibrium exists, 'k > 2*m*g/L' where it is stable.

    split_relation(text) -> (left, operator, right) or None
    compare_relation(given, right, sampler) -> Verdict

An equation is a set of points: two equations are the same answer when one's sides'
difference is a nonzero constant times the other's (3 cos θ = 2 is cos θ = 2/3), or when
one solves for a name (θ = acos(2/3)) and that value satisfies the other. A condition is
a region: two conditions are the same answer when they hold at the same admissible
points (the parameters' ranges and the file's assumptions, teaching/compare.Sampler),
at RELATION_POINTS random points, so Ω² > g/R is Ω > √(g/R) for a positive Ω; < and ≤
are not told apart (they differ on the boundary only).
"""

from __future__ import annotations

import random

import sympy as sp
from sympy.core.function import AppliedUndef
from sympy.core.relational import Relational

from rbdsolve.form.printers import to_unicode
from rbdsolve.teaching.compare import SEED, Sampler, compare, value_at
from rbdsolve.teaching.verdicts import Different, Equivalent, Factor, Proof, SignDiffers, Undecided, Verdict

RELATION_POINTS = 60  # a region is told from another by where they hold: more points than an expression
OPERATORS = ("<=", ">=", "==", "≤", "≥", "<", ">", "=")
_SYMPY = {"<=": sp.Le, ">=": sp.Ge, "==": sp.Eq, "≤": sp.Le, "≥": sp.Ge, "<": sp.Lt, ">": sp.Gt, "=": sp.Eq}


def split_relation(text: str) -> tuple[str, str, str] | None:
    """('cos(theta)', '=', '2/3') for 'cos(theta) = 2/3', split at the first relational
    operator outside brackets; None where the text has none."""
    depth = 0
    for i, ch in enumerate(text):
        depth += (ch in "([") - (ch in ")]")
        if depth:
            continue
        for op in OPERATORS:
            if text.startswith(op, i):
                return text[:i], op, text[i + len(op):]
    return None


def relation(left: sp.Expr, op: str, right: sp.Expr) -> sp.Basic:
    return _SYMPY[op](left, right, evaluate=False)


def compare_relation(given: sp.Basic, right: sp.Basic, sampler: Sampler) -> Verdict:
    if isinstance(right, sp.Eq) != isinstance(given, sp.Eq):
        return Different((), to_unicode(given), to_unicode(right))  # an equation for a condition, or the reverse
    if isinstance(right, sp.Eq):
        return _same_equation(given, right, sampler)
    return _same_region(given, right, sampler)


def _same_equation(given: sp.Eq, right: sp.Eq, sampler: Sampler) -> Verdict:
    verdict = compare(given.lhs - given.rhs, right.lhs - right.rhs, sampler)
    if verdict.right or isinstance(verdict, (Factor, SignDiffers)):  # a nonzero constant factor: the same equation
        return Equivalent(Proof.SIMPLIFIED) if verdict.right else Equivalent(Proof.SAMPLED)
    for solved, other in ((given, right), (right, given)):  # θ = acos(2/3) satisfies cos θ = 2/3
        if isinstance(solved.lhs, (sp.Symbol, AppliedUndef)) and solved.lhs not in solved.rhs.free_symbols:
            there = (other.lhs - other.rhs).subs(solved.lhs, solved.rhs)
            if compare(there, sp.Integer(0), sampler).right:
                return Equivalent(Proof.SAMPLED)
    return Different((), to_unicode(given), to_unicode(right))


def _same_region(given: sp.Basic, right: sp.Basic, sampler: Sampler) -> Verdict:
    """Both hold, or both fail, at every admissible point tried."""
    plain, names = _without_functions(given, right)
    given, right = given.xreplace(plain), right.xreplace(plain)
    symbols = sorted(given.free_symbols | right.free_symbols, key=sp.default_sort_key)
    rng = random.Random(SEED)
    tried = 0
    for k in range(3 * RELATION_POINTS):
        point = sampler.draw(symbols, rng, k < 3) if symbols else {}
        if point is None:
            continue
        ours, theirs = _holds(given, point), _holds(right, point)
        if ours is None or theirs is None:
            continue
        if ours != theirs:
            shown = tuple((names.get(s, to_unicode(s)), f"{float(v):.6g}") for s, v in point.items() if s in symbols)
            return Different(shown, str(ours).lower(), str(theirs).lower())
        tried += 1
        if tried >= RELATION_POINTS or not symbols:
            return Equivalent(Proof.SAMPLED)
    return Undecided("no admissible point where both conditions have a value") if not tried else Equivalent(Proof.SAMPLED)


def _without_functions(*exprs: sp.Basic) -> tuple[dict, dict]:
    """θ(t) as a plain symbol θ, which the sampler draws like a parameter."""
    plain, names = {}, {}
    for e in exprs:
        for f in e.atoms(AppliedUndef):
            plain[f] = sp.Symbol(f.func.__name__, real=True)
            names[plain[f]] = to_unicode(sp.Symbol(f.func.__name__))
    return plain, names


def _holds(condition: sp.Basic, point: dict) -> bool | None:
    """Whether a condition (a relation, or And/Or/Not of them) holds at ``point``; None
    where a side has no real value there."""
    if isinstance(condition, sp.And):
        parts = [_holds(c, point) for c in condition.args]
        return None if None in parts else all(parts)
    if isinstance(condition, sp.Or):
        parts = [_holds(c, point) for c in condition.args]
        return None if None in parts else any(parts)
    if isinstance(condition, sp.Not):
        inner = _holds(condition.args[0], point)
        return None if inner is None else not inner
    if condition in (sp.true, sp.false):
        return bool(condition)
    if not isinstance(condition, Relational):
        return None
    value = value_at(condition.lhs - condition.rhs, point)
    if value is None or abs(value.imag) > 1e-12 * max(1.0, abs(value)):
        return None
    x = value.real
    return {"<": x < 0, "<=": x <= 0, ">": x > 0, ">=": x >= 0, "==": x == 0, "!=": x != 0}[condition.rel_op]
