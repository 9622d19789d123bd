"""Is a student's expression the right answer? Symbolic first, random evaluation decides.

    compare(given, right, sampler, angle=False) -> Verdict

1. The difference given − right simplifies to 0: Equivalent (simplified). sympy's
   ``simplify`` proves much but not all (nested radicals, trigonometric identities past
   its rules), so a difference it leaves is not yet a "different".
2. Both are evaluated, to 30 digits, at admissible random parameter values (positive
   where declared so, satisfying the file's ``assumptions:``; a few small integers first,
   so that a point shown to the student reads well; where the answer is real, when
   there are such points): equal at every point is
   Equivalent (sampled). Two different expressions of this size agreeing at 8 random
   points to 12 digits is not a risk worth naming.
3. Otherwise the values say how they differ: a constant ratio given/right is a sign or
   a factor (2, 2π between ω and f, 180/π for degrees); given = right² a missing square
   root, given² = right an extra one; an angle that differs by whole turns (2π k) is
   the same angle. Else, where the difference's numerator is a polynomial of low degree
   in a parameter, the values of that parameter where they agree (EqualFor); else the
   first point where they differ (Different).
"""

from __future__ import annotations

import random
from dataclasses import dataclass
from typing import Callable, Mapping, Sequence, TypeVar

import sympy as sp
from sympy.core.function import AppliedUndef

from rbdsolve.form.printers import to_unicode
from rbdsolve.solvers.routes.budget import Allowance, OutOfTime, within
from rbdsolve.teaching.verdicts import (FACTOR_SLIPS, Different, EqualFor, Equivalent, Factor, Proof, Root,
                                        SignDiffers, Slip, Undecided, Verdict)

DIGITS = 30  # evaluation precision
CLOSE = 1e-12  # relative agreement that counts as equal at 30 digits
NICE_POINTS = 3  # small integers first: a point the student can evaluate by hand
RANDOM_POINTS = 5  # then log-uniform draws from 10⁻³ to 10³ (model.assumptions.admissible_sample)
MAX_OPS = 300  # simplify and polynomial solving only below this size: they can take long past it
MAX_ROOT_OPS = 2  # ... and names a value as short as 'm = 1', 'l = g/2': a longer one says little
MAX_DEGREE = 4  # EqualFor solves a numerator polynomial of at most this degree in one parameter
SIMPLIFY_SECONDS = 3.0  # each step's time: a hostile expression makes the step inconclusive
EVALUATE_SECONDS = 10.0
SOLVE_SECONDS = 3.0
SEED = 25  # the points are drawn from a fixed seed: the same answer gets the same verdict

Point = Mapping[sp.Symbol, sp.Expr]
T = TypeVar("T")


@dataclass(frozen=True)
class Sampler:
    """Admissible parameter values for a set of symbols: ``draw(symbols, rng, nice)``
    returns a point satisfying the problem's assumptions, or None. ``names`` gives each
    symbol's name as shown to the student; ``parameters`` are the symbols an EqualFor
    may solve for, in the file's order."""

    draw: Callable[[Sequence[sp.Symbol], random.Random, bool], dict | None]
    names: Mapping[sp.Symbol, str]
    parameters: tuple[sp.Symbol, ...]

    def within(self, conditions: Sequence[sp.Basic]) -> Sampler:
        """The same points, kept only where every condition holds: where the answer
        exists (an equilibrium that exists for Ω² R > g is compared at such Ω only; the
        two forms of a wrong answer may agree, or a right one be complex, past it)."""
        conditions = [c for c in conditions if c is not sp.true]
        if not conditions:
            return self
        extra = sorted(set().union(*(c.free_symbols for c in conditions)), key=str)

        def draw(symbols: Sequence[sp.Symbol], rng: random.Random, nice: bool) -> dict | None:
            wanted = list(dict.fromkeys([*symbols, *extra]))
            for _ in range(WITHIN_TRIES):
                point = self.draw(wanted, rng, nice)
                if point is None:
                    return None
                if all(holds_at(c, point) for c in conditions):
                    return point
            return None

        return Sampler(draw, self.names, self.parameters)


WITHIN_TRIES = 40  # draws per point that must also satisfy an answer's existence conditions


def holds_at(condition: sp.Basic, point: Point) -> bool:
    """Whether a condition (a relation, And, Or of them) holds at ``point``, its sides
    evaluated to DIGITS digits; False where a side has no real value there."""
    if condition in (sp.true, sp.false):
        return condition is sp.true
    if isinstance(condition, sp.And):
        return all(holds_at(c, point) for c in condition.args)
    if isinstance(condition, sp.Or):
        return any(holds_at(c, point) for c in condition.args)
    if isinstance(condition, sp.Not):
        return not holds_at(condition.args[0], point)
    difference = value_at(condition.lhs - condition.rhs, point) if hasattr(condition, "rel_op") else None
    if difference is None or abs(difference.imag) > CLOSE * max(1.0, abs(difference.real)):
        return False
    x = difference.real
    return {"<": x < 0, "<=": x <= 0, ">": x > 0, ">=": x >= 0, "==": abs(x) <= CLOSE, "!=": abs(x) > CLOSE}[
        condition.rel_op]


def compare(given: sp.Expr, right: sp.Expr, sampler: Sampler, angle: bool = False,
            run: Allowance = Allowance(None)) -> Verdict:
    """The verdict on ``given`` against ``right`` (see the module docstring), each step
    within its own time and within what is left of the ``run``'s budget (a check's)."""
    given, right, names = _plain(given, right, sampler.names)
    if _timed(_step(SIMPLIFY_SECONDS, run), "simplifying", lambda: _simplifies_to_zero(given - right), False):
        return Equivalent(Proof.SIMPLIFIED)
    symbols = sorted(given.free_symbols | right.free_symbols, key=str)
    seconds = _step(EVALUATE_SECONDS, run)
    values = _timed(seconds, "evaluating", lambda: _values(given, right, symbols, sampler), None)
    if values is None:
        return Undecided(f"evaluating the answers took more than {seconds:.3g} s"
                         + ("" if seconds == EVALUATE_SECONDS else ", what was left of the budget"))
    if not values:
        return Undecided("no admissible parameter values where both have a finite value")
    if all(_close(a, b) for _, a, b in values):
        return Equivalent(Proof.SAMPLED)
    return _how_different(given, right, values, sampler, names, angle, run)


def _step(seconds: float, run: Allowance) -> float:
    """A step's time: its own, or less where the run has less left."""
    left = run.left()
    return seconds if left is None else min(seconds, left)


def _how_different(given: sp.Expr, right: sp.Expr, values: list, sampler: Sampler,
                   names: Mapping[sp.Symbol, str], angle: bool, run: Allowance) -> Verdict:
    if angle and _whole_turns([a - b for _, a, b in values]):
        return Equivalent(Proof.ANGLE)
    factor = _constant_ratio(values)
    if factor is not None:
        verdict = _factor(factor)
        constant = not (given.free_symbols | right.free_symbols)
        if not constant or not isinstance(verdict, Factor) or verdict.slips:
            return verdict  # 3/4 for 4/3 is a different number, not "a factor 9/16"
    if all(_close(a, b * b) for _, a, b in values):
        return Root(missing=True)
    if all(_close(a * a, b) for _, a, b in values):
        return Root(missing=False)
    condition = _timed(_step(SOLVE_SECONDS, run), "solving", lambda: _equal_where(given, right, sampler), None)
    if condition is not None:
        return EqualFor(condition)
    point, a, b = next((p, a, b) for p, a, b in values if not _close(a, b))
    used = given.free_symbols | right.free_symbols
    shown = tuple((names.get(s, str(s)), _number(complex(v))) for s, v in point.items() if s in used)
    return Different(shown, _number(a), _number(b))


# --- symbols -------------------------------------------------------------------------


def _plain(given: sp.Expr, right: sp.Expr, names: Mapping[sp.Symbol, str]):
    """Both expressions with q(t), q̇(t), q̈(t) (and given functions of time) as plain
    real symbols, the same in both, and the names to show them by (θ, θ̇)."""
    table: dict = {}
    shown = dict(names)
    for expr in (given, right):
        for d in sorted(expr.atoms(sp.Derivative) | expr.atoms(AppliedUndef), key=sp.default_sort_key):
            if d not in table:
                table[d] = sp.Dummy(str(d), real=True)
                shown[table[d]] = to_unicode(d)
    return given.xreplace(table), right.xreplace(table), shown


def _timed(seconds: float, what: str, work: Callable[[], T], otherwise: T) -> T:
    """``work()``, or ``otherwise`` when it runs past ``seconds`` or sympy fails on it:
    a student's expression can be one that sympy's simplification expands without end
    (sin(10**40*g)) or that overflows mpmath (exp(exp(exp(exp(10))))); neither is a
    verdict, and the other steps still decide."""
    try:
        with within(seconds, what):
            return work()
    except OutOfTime:
        return otherwise
    except Exception:  # noqa: BLE001 - sympy's own failure on a hostile expression: inconclusive
        return otherwise


def _simplifies_to_zero(difference: sp.Expr) -> bool:
    if difference == 0:
        return True
    if sp.count_ops(difference) > MAX_OPS:
        return False
    return sp.simplify(difference) == 0


# --- values at admissible points -----------------------------------------------------


def _values(given: sp.Expr, right: sp.Expr, symbols: list[sp.Symbol], sampler: Sampler
            ) -> list[tuple[Point, complex, complex]]:
    """(point, given there, right there) at admissible points where both are finite,
    preferring points where the answer is real: where it is not (a frequency past a
    critical value), two right forms may sit on different branches of a square root."""
    if not symbols:
        a, b = value_at(given, {}), value_at(right, {})
        return [] if a is None or b is None else [({}, a, b)]
    rng = random.Random(SEED)
    wanted = NICE_POINTS + RANDOM_POINTS
    real, other = [], []
    for k in range(3 * wanted):
        point = sampler.draw(symbols, rng, k < NICE_POINTS)
        a, b = (None, None) if point is None else (value_at(given, point), value_at(right, point))
        if a is not None and b is not None:
            (real if abs(b.imag) <= CLOSE * abs(b) else other).append((point, a, b))
        if len(real) >= wanted:
            break
    return real if len(real) >= NICE_POINTS else real + other[: wanted - len(real)]


def value_at(expr: sp.Expr, point: Point) -> complex | None:
    """``expr`` at ``point`` to DIGITS digits, or None where it has no finite value."""
    try:
        value = complex(expr.evalf(DIGITS, subs=dict(point)))
    except Exception:  # noqa: BLE001 - no number there (zoo, nan, an overflow in mpmath)
        return None
    if value != value or abs(value) == float("inf"):
        return None
    return value


def _close(a: complex, b: complex) -> bool:
    return abs(a - b) <= CLOSE * max(abs(a), abs(b)) + 1e-25


def _number(value: complex) -> str:
    if abs(value.imag) <= CLOSE * max(1.0, abs(value.real)):
        return f"{value.real:.6g}"
    return f"{value.real:.6g} {'+' if value.imag >= 0 else '−'} {abs(value.imag):.6g} i"


# --- how they differ -----------------------------------------------------------------


def _whole_turns(differences: list[complex]) -> bool:
    """Every difference the same whole number of turns, 2π k."""
    turns = [d / (2 * 3.141592653589793) for d in differences]
    k = round(turns[0].real)
    return all(_close(t, complex(k)) for t in turns)


def _constant_ratio(values: list) -> complex | None:
    """given/right where it is the same at every point (and right is not zero there)."""
    ratios = [a / b for _, a, b in values if b != 0]
    if len(ratios) < len(values) or not ratios:
        return None
    return ratios[0] if all(_close(r, ratios[0]) for r in ratios) else None


def _factor(ratio: complex) -> Verdict:
    if abs(ratio.imag) > CLOSE * abs(ratio):
        return Factor(sp.Float(ratio.real, 6) + sp.I * sp.Float(ratio.imag, 6))
    for exact, slips in FACTOR_SLIPS:
        if _close(ratio, complex(exact)):
            return SignDiffers() if slips == (Slip.SIGN,) else Factor(exact, slips)
    return Factor(_exact(ratio.real))


def _exact(value: float) -> sp.Expr:
    """A rational with a small denominator, a multiple of π, or the square root of a
    rational (±√(25/24)) when the value is one to 12 digits, else the value to 6 digits."""
    for base in (sp.Integer(1), sp.pi, 1 / sp.pi):
        scaled = sp.Rational(value / float(base)).limit_denominator(1000)
        if _close(complex(float(scaled * base)), complex(value)):
            return scaled * base
    root = sp.sign(value) * sp.sqrt(sp.Rational(value * value).limit_denominator(1000))
    return root if _close(complex(float(root)), complex(value)) else sp.Float(value, 6)


def _equal_where(given: sp.Expr, right: sp.Expr, sampler: Sampler) -> str | None:
    """'m = 1': where the numerator of given − right, a polynomial of low degree in one
    parameter, vanishes at an admissible value (real; positive for a positive parameter)."""
    difference = sp.together(given - right)
    if sp.count_ops(difference) > MAX_OPS:
        return None
    numerator, denominator = sp.fraction(difference)
    for p in sampler.parameters:
        if not numerator.has(p):
            continue
        try:
            poly = sp.Poly(numerator, p)
        except (sp.PolynomialError, sp.GeneratorsNeeded):
            continue
        if not 1 <= poly.degree() <= MAX_DEGREE:
            continue
        roots = [r for r in sp.roots(poly) if sp.count_ops(r) <= MAX_ROOT_OPS
                 and _admissible_root(r, p, denominator, right)]
        if roots:
            name = sampler.names.get(p, str(p))
            return " or ".join(f"{name} = {to_unicode(r)}" for r in roots)
    return None


def _admissible_root(root: sp.Expr, p: sp.Symbol, denominator: sp.Expr, right: sp.Expr) -> bool:
    if root.is_real is False or (p.is_positive and root.is_positive is False) or root.has(sp.I):
        return False
    if denominator.xreplace({p: root}) == 0:
        return False
    return not right.xreplace({p: root}).has(sp.zoo, sp.nan)
