"""The problem's ``assumptions:`` as sympy: checked against the values and against each
other, and turned into substitutions that let sympy decide signs under them.

An assumption L > R (or L ≥ R) that is linear in some parameter p with a coefficient
of known sign on the larger side (a positive coefficient), or else in a parameter of
either sign (``positive: false``) on the smaller side (k < 0: k = −δ), is solved for
p, p = p₀ + δ with δ a new positive symbol: R > r becomes R = r + δ, and any sign
that holds for every δ > 0 holds under the assumption (``decided_by``). One substitution per parameter, in the file's order; an assumption
that is not linear in a free parameter is still checked, and used by the sampling in
``solvers/conditions/conditions.py``, but decides no sign exactly. A contact's geometry adds
its own (R > r for a body rolling inside a circle, model/constraints/contacts.py), after the file's.
"""

from __future__ import annotations

import random
from dataclasses import dataclass
from typing import Mapping, TYPE_CHECKING

import sympy as sp

from rbdsolve.errors import InputError
from rbdsolve.model.symbols import Symbols
from rbdsolve.problem.schema import Problem

if TYPE_CHECKING:
    from rbdsolve.problem.scene import Assumption

SAMPLES = 400  # random points tried for a sample that satisfies the assumptions

OPS = {"<": sp.StrictLessThan, "<=": sp.LessThan, ">": sp.StrictGreaterThan, ">=": sp.GreaterThan}


@dataclass(frozen=True)
class Assumed:
    """An assumption as ``difference`` > 0 (≥ 0 when not ``strict``), with its source."""

    difference: sp.Expr
    strict: bool
    source: Assumption
    implied_by: str = ""  # a contact whose geometry needs it (R > r inside a circle), not 'assumptions:'

    @property
    def named(self) -> str:
        """'R > r' as the file wrote it, or with the contact that implies it."""
        return f"'{self.source.text}'" + (f" (implied by {self.implied_by})" if self.implied_by else "")

    @property
    def relation(self) -> sp.Basic:
        return sp.StrictGreaterThan(self.difference, 0) if self.strict else sp.GreaterThan(self.difference, 0)


def implies(assumptions: tuple[Assumed, ...], condition: sp.Basic) -> bool:
    """Whether the assumptions make a condition on one parameter hold for every value
    they allow: the interval the assumptions on that parameter leave lies within the
    condition's set (α ≤ π/2 under 0 < α < π/2). False where that is not decided so."""
    if _stated(assumptions, condition):
        return True
    free = condition.free_symbols
    if len(free) != 1 or condition in (sp.true, sp.false):
        return False
    (p,) = free
    mine = [a.relation for a in assumptions if a.relation.free_symbols == {p}]
    if not mine:
        return False
    try:
        allowed = sp.Intersection(*[r.as_set() for r in mine], sp.Interval.open(0, sp.oo) if p.is_positive else sp.S.Reals)
        holds = sp.solveset(condition, p, allowed)  # over the allowed values only (tan α ≥ 0 is periodic)
        return allowed.is_subset(holds) is True
    except (NotImplementedError, TypeError, ValueError):
        return False


def _stated(assumptions: tuple[Assumed, ...], condition: sp.Basic) -> bool:
    """Whether the condition, x > 0 (or ≥ 0), is an assumption itself up to a positive
    number: cos(a + b) > 0 under [cos(a + b) > 0], which the one-parameter test above
    cannot read (two parameters) though the file says it in as many words."""
    if not isinstance(condition, (sp.StrictGreaterThan, sp.GreaterThan)):
        return False
    x = sp.expand(condition.lhs - condition.rhs)
    for a in assumptions:
        if a.difference == 0 or (isinstance(condition, sp.StrictGreaterThan) and not a.strict):
            continue
        ratio = sp.cancel(x / a.difference)
        if ratio.is_number and ratio.is_positive:
            return True
    return False


def assumed(problem: Problem, names: Symbols) -> tuple[Assumed, ...]:
    out = []
    for a in problem.assumptions:
        left, right = names.scalar(a.lhs), names.scalar(a.rhs)
        difference = left - right if a.op in (">", ">=") else right - left
        out.append(Assumed(sp.expand(difference), a.op in ("<", ">"), a))
    return tuple(out)


def check(assumptions: tuple[Assumed, ...], values: Mapping[sp.Symbol, sp.Expr], names: Symbols) -> None:
    """Bad input, located at the assumption: one that is false whatever the values
    (0 > 1, R > R), one the values given break, and one that the others (put in as
    substitutions, R = r + δ) and the parameters' signs prove false (r > R with R > r)."""
    for a in assumptions:
        if not a.difference.free_symbols:
            if not _holds(a.difference, a.strict):
                raise InputError(f"the assumption {a.named} is false whatever the values", a.source.loc)
            continue
        number = a.difference.xreplace(dict(values))
        if number.is_number and not _holds(number, a.strict):
            given = ", ".join(f"{k} = {v}" for k, v in values.items() if k in a.difference.free_symbols)
            raise InputError(f"the values given ({given}) break the assumption {a.named}", a.source.loc)
        others = substitutions(tuple(x for x in assumptions if x is not a), names)
        value = sp.factor(a.difference.xreplace(others))
        if value.is_negative or (a.strict and value.is_nonpositive):
            implied = "".join(f"; {x.named}" for x in assumptions if x.implied_by and x is not a)
            raise InputError(f"the assumption {a.named} cannot hold with the others{implied} and the parameters' "
                             "signs", a.source.loc)


def admissible_sample(assumptions, names: Symbols, rng: random.Random, fixed: Mapping = (),
                      symbols=None, tries: int = SAMPLES, ranges: Mapping = {}) -> dict | None:
    """Random values for the parameters (positive where declared so, 10⁻³ to 10³ in a
    log-uniform draw; uniform in (a, b) where ``ranges`` gives one, an angle's)
    satisfying every assumption; None after ``tries``."""
    fixed = dict(fixed)
    symbols = [s for s in (symbols or names.parameters.values()) if s not in fixed]
    for _ in range(tries):
        point = {s: _within(ranges[s], rng) if s in ranges else _draw(s, rng) for s in symbols} | fixed
        if all(_holds(a.difference.xreplace(point), a.strict) for a in assumptions):
            return point
    return None


def _draw(s: sp.Symbol, rng: random.Random) -> sp.Expr:
    size = sp.Rational(round(10 ** rng.uniform(-3, 3) * 10**6), 10**6)
    return size if s.is_positive or rng.random() < 0.5 else -size


def _within(span, rng: random.Random) -> sp.Expr:
    low, high = span
    return low + (high - low) * sp.Rational(rng.randint(1, 999), 1000)


def _holds(number: sp.Expr, strict: bool) -> bool:
    value = complex(sp.N(number, 30))
    if abs(value.imag) > 1e-12 * max(1.0, abs(value.real)):
        return False
    return value.real > 0 if strict else value.real >= 0


def substitutions(assumptions: tuple[Assumed, ...], names: Symbols) -> dict[sp.Symbol, sp.Expr]:
    """{p: p₀ + δ} from the assumptions that are linear in a parameter (see the module)."""
    out: dict[sp.Symbol, sp.Expr] = {}
    order = list(names.parameters.values())
    for k, a in enumerate(assumptions):
        difference = a.difference.xreplace(out)
        for p in _solved_for(difference, order, out):
            coefficient = sp.diff(difference, p)
            delta = sp.Dummy(f"delta{k}", positive=True) if a.strict else sp.Dummy(f"delta{k}", nonnegative=True)
            rest = difference - coefficient * p
            out = {q: v.xreplace({p: (delta - rest) / coefficient}) for q, v in out.items()}
            out[p] = (delta - rest) / coefficient
            break
    return out


def _solved_for(difference: sp.Expr, order: list, taken: Mapping) -> list[sp.Symbol]:
    """The parameters an assumption may be solved for, in the file's order: those on its
    larger side (a positive coefficient: R > r gives R = r + δ, which keeps R > 0), then
    a parameter of either sign on its smaller side (k < 0 gives k = −δ: a sign the
    assumption itself gives)."""
    linear = [p for p in sorted(difference.free_symbols & set(order), key=order.index)
              if p not in taken and not sp.diff(difference, p).has(p) and sp.diff(difference, p) != 0]
    larger = [p for p in linear if sp.diff(difference, p).is_positive]
    smaller = [p for p in linear if sp.diff(difference, p).is_negative and not p.is_positive]
    return larger + smaller


def decided_by(substituted: Mapping[sp.Symbol, sp.Expr], values: Mapping[sp.Symbol, sp.Expr]) -> dict:
    """One mapping for sign decisions: the values, and the assumptions' substitutions for
    the parameters without a value (with the values put in them)."""
    return {**{p: v.xreplace(dict(values)) for p, v in substituted.items() if p not in values}, **values}
