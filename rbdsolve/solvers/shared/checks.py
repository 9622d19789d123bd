"""Every answer checked before it is printed (issue 38): the equations an answer must
satisfy, evaluated at sampled admissible parameter values.

Each family says what its answers must satisfy (its ``check.py``, registered beside
its routes in ``solvers/__init__.py``): an equilibrium ∂V/∂q = 0, a steady motion its
balances, an eigenvalue det(K − λM) = 0, the velocities after an impact the impulse
equations, the reactions each body's balances. A residual is

- ``Vanishes``: an expression that must be 0, or
- ``Pencil``: K − λM at an eigenvalue λ, whose determinant must be 0, and which
  must annihilate the mode shape a,

each with ``where``, the condition under which the answer exists (its existence
condition: a radicand ≥ 0, s ≥ s_c). It is evaluated in 30-digit arithmetic (mpmath)
at one point — the problem's values, the other parameters drawn inside the
assumptions — and at a second where some parameter has no value; at points where
``where`` fails more are drawn, and a residual no admissible point reaches is not
checked. Coordinates and rates left in an answer (a reaction as a function of the
state) are drawn too.

It passes when |r| ≤ TOLERANCE · s, with s the size of its terms: the sum of the sizes
of a sum's terms, the product of a product's factors, |value| elsewhere (so a sum that
cancels to 0 is measured against what cancelled); for a pencil, |det(K − λM)| against
(max row sum of |K| + |λ| |M|)ⁿ. A failure is rbdsolve's bug: ``CheckFailed`` says so and the
question is left unanswered (exit code 1), never printed.
"""

from __future__ import annotations

import random
from dataclasses import dataclass, replace
from typing import Callable, Iterable, Sequence

import mpmath
import sympy as sp
from sympy.core.relational import Relational

from rbdsolve.errors import UnsolvedError
from rbdsolve.form.printers import to_unicode
from rbdsolve.solvers.shared.condition_roots import admissible, angle_parameters

TOLERANCE = 1e-9  # relative to the size of the terms; a wrong answer is off by O(1)
DIGITS = 30
EXTRA_DRAWS = 6  # more points tried for a residual whose answer does not exist at the first


@dataclass(frozen=True)
class Vanishes:
    """``value`` = 0 wherever ``where`` holds."""

    what: str  # "∂V/∂θ at equilibrium 1"
    value: sp.Expr
    where: sp.Basic = sp.true


@dataclass(frozen=True)
class Pencil:
    """K − λM at λ is singular, det(K − λM) = 0, and annihilates ``shape`` where one is
    given, (K − λM) a = 0, wherever ``where`` holds. K, M and λ are kept apart, so that
    the size of each entry K − λM is |K| + |λ| |M| even where λ is a decimal that
    sympy would cancel against K at once (a certified eigenvalue)."""

    what: str  # "λ₁"
    K: sp.ImmutableMatrix
    M: sp.ImmutableMatrix
    lam: sp.Expr
    shape: tuple[sp.Expr, ...] | None = None
    where: sp.Basic = sp.true


Residual = Vanishes | Pencil
Residuals = Callable[..., Sequence[Residual]]  # (question, model, answers) -> the residuals


class CheckFailed(UnsolvedError):
    """An answer failed rbdsolve's own check: a bug in rbdsolve, not in the file.
    ``route``: the route whose answer it was, once known."""

    def __init__(self, message: str, route: object = None):
        super().__init__(message)
        self.route = route


def verify(residuals: Sequence[Residual], model, states: Iterable[sp.Symbol] = ()) -> None:
    """Raise CheckFailed at the first residual that is not 0 within TOLERANCE at a
    sampled admissible point where its answer exists. ``states``: the symbols other
    than parameters an answer may hold (coordinates, rates), drawn at random."""
    if not residuals:
        return
    angles = {p: span for r in residuals for p, span in angle_parameters(_expression(r)).items()}
    states = tuple(states)
    points = _points(model, angles, states)
    for residual in residuals:
        for point in _inside(residual, points, model, angles, states):
            failure = _failure(residual, point)
            if failure:
                held = _expression(residual).free_symbols
                raise CheckFailed(f"rbdsolve's own check of this answer failed: {failure} at "
                                  f"{_point_text({s: v for s, v in point.exact.items() if s in held}, model)}. "
                                  "This is a bug in rbdsolve, not in the problem file (please report it with the "
                                  "file); the answer is not printed")


def _expression(residual: Residual) -> sp.Basic:
    if isinstance(residual, Vanishes):
        return residual.value
    return sp.Tuple(residual.K, residual.M, residual.lam, *(residual.shape or ()))


@dataclass(frozen=True)
class Point:
    """A sample: exact values (for messages), and the same in mpmath numbers."""

    exact: dict
    numbers: dict

    @staticmethod
    def of(exact: dict) -> Point:
        with mpmath.workdps(DIGITS):
            return Point(exact, {s: _mp(v) for s, v in exact.items()})


def _points(model, angles: dict, states: tuple) -> list[Point]:
    """The problem's values with the other parameters drawn admissibly; a second point
    where some parameter has no value."""
    free = [s for s in model.symbols.parameters.values() if s not in model.values]
    out = []
    for k in range(2 if free else 1):
        point = admissible(model, random.Random(3800 + k), (), angles)
        if point is not None:
            out.append(_with_states(point, states, random.Random(k)))
    return out


def _with_states(point: dict, states: tuple, rng: random.Random) -> Point:
    return Point.of({**point, **{s: sp.Rational(rng.randint(300, 1500), 1000) for s in states}})


def _inside(residual: Residual, points: list[Point], model, angles: dict, states: tuple) -> list[Point]:
    """The points where the residual's answer exists; where none does (a top below its
    least spin at the given values), up to EXTRA_DRAWS more, every parameter drawn
    (the exact answer is a formula for all of them), until one does."""
    if residual.where is sp.true:
        return points
    inside = [p for p in points if _holds(residual.where, p.numbers)]
    anywhere = replace(model, values={}) if model.values and not inside else model
    for k in range(1, EXTRA_DRAWS + 1):
        if inside:
            break
        point = admissible(anywhere, random.Random(3900 + k), (), angles)
        if point is not None:
            candidate = _with_states(point, states, random.Random(k))
            if _holds(residual.where, candidate.numbers):
                inside.append(candidate)
    return inside


def _failure(residual: Residual, point: Point) -> str | None:
    """What fails at the point ('∂V/∂θ at equilibrium 1 = 0.25, its terms of size 3.1'),
    or None where it holds or cannot be evaluated there."""
    with mpmath.workdps(DIGITS):
        try:
            found = ([(residual.what, *_evaluate(residual.value, point.numbers))] if isinstance(residual, Vanishes)
                     else _pencil(residual, point.numbers))
        except (_NotEvaluated, ZeroDivisionError, ValueError, TypeError, OverflowError):
            return None
        for what, value, size in found:
            if mpmath.isfinite(value) and mpmath.isfinite(size) and abs(value) > TOLERANCE * size:
                return (f"{what} = {mpmath.nstr(value, 6)}, not 0 (its terms are of size "
                        f"{mpmath.nstr(size, 6)}, tolerance {TOLERANCE:g} of that)")
        return None


def _pencil(residual: Pencil, numbers: dict) -> list[tuple]:
    """[(what, value, size)]: det(K − λM) against (max row sum of entry sizes)ⁿ, then
    each row of (K − λM) a against the sum of its terms' sizes."""
    lam, lam_size = _evaluate(residual.lam, numbers)
    K = [[_evaluate(x, numbers) for x in row] for row in residual.K.tolist()]
    M = [[_evaluate(x, numbers) for x in row] for row in residual.M.tolist()]
    n = len(K)
    P = [[k - lam * m for (k, _), (m, _) in zip(Kr, Mr)] for Kr, Mr in zip(K, M)]
    S = [[ks + lam_size * ms for (_, ks), (_, ms) in zip(Kr, Mr)] for Kr, Mr in zip(K, M)]
    scale = max(sum(row) for row in S) ** n if n else mpmath.mpf(0)
    out = [(f"det(K − {residual.what} M)", mpmath.det(mpmath.matrix(P)) if n else mpmath.mpf(0), scale)]
    if residual.shape is not None:
        a = [_evaluate(x, numbers) for x in residual.shape]
        out += [(f"row {i + 1} of (K − {residual.what} M) a", mpmath.fsum(p * v for p, (v, _) in zip(P[i], a)),
                 mpmath.fsum(sz * size for sz, (_, size) in zip(S[i], a))) for i in range(n)]
    return out


class _NotEvaluated(Exception):
    """A node the evaluator does not know, or a symbol without a value."""


FUNCTIONS = {sp.sin: mpmath.sin, sp.cos: mpmath.cos, sp.tan: mpmath.tan, sp.cot: mpmath.cot, sp.sec: mpmath.sec,
             sp.csc: mpmath.csc, sp.exp: mpmath.exp, sp.log: mpmath.log, sp.asin: mpmath.asin,
             sp.acos: mpmath.acos, sp.atan: mpmath.atan, sp.sinh: mpmath.sinh, sp.cosh: mpmath.cosh,
             sp.tanh: mpmath.tanh}


def _evaluate(expr: sp.Basic, numbers: dict) -> tuple:
    """(value, size of its terms) at the point, in mpmath numbers."""
    if expr in numbers:
        value = numbers[expr]
        return value, abs(value)
    if expr.is_Rational:
        value = mpmath.mpf(expr.p) / expr.q
        return value, abs(value)
    if expr.is_Number or expr.is_NumberSymbol or expr is sp.I:
        value = _mp(expr)
        return value, abs(value)
    if expr.is_Symbol:
        raise _NotEvaluated(expr)
    if expr.is_Add:
        parts = [_evaluate(a, numbers) for a in expr.args]
        return mpmath.fsum(v for v, _ in parts), mpmath.fsum(s for _, s in parts)
    if expr.is_Mul:
        value, size = mpmath.mpf(1), mpmath.mpf(1)
        for a in expr.args:
            v, s = _evaluate(a, numbers)
            value, size = value * v, size * s
        return value, size
    if expr.is_Pow:
        base, size = _evaluate(expr.base, numbers)
        exponent, _ = _evaluate(expr.exp, numbers)
        value = mpmath.power(base, exponent)
        positive = mpmath.im(exponent) == 0 and mpmath.re(exponent) > 0
        return value, (mpmath.power(size, mpmath.re(exponent)) if positive else abs(value))
    if type(expr) in FUNCTIONS:
        value = FUNCTIONS[type(expr)](_evaluate(expr.args[0], numbers)[0])
        return value, abs(value)
    if isinstance(expr, sp.atan2):
        y, x = (mpmath.re(_evaluate(a, numbers)[0]) for a in expr.args)
        value = mpmath.atan2(y, x)
        return value, abs(value)
    if isinstance(expr, sp.Abs):
        value = abs(_evaluate(expr.args[0], numbers)[0])
        return value, value
    if expr.free_symbols:
        raise _NotEvaluated(expr)
    value = _mp(expr)  # a number sympy must evaluate itself (a CRootOf)
    return value, abs(value)


def _mp(value: sp.Expr):
    """A number as an mpmath number at the working precision."""
    if value.is_Rational:
        return mpmath.mpf(value.p) / value.q
    z = sp.N(value, DIGITS + 5)
    real, imaginary = z.as_real_imag()
    if not (real.is_number and imaginary.is_number):
        raise _NotEvaluated(value)
    return mpmath.mpc(mpmath.mpf(str(real)), mpmath.mpf(str(imaginary))) if imaginary else mpmath.mpf(str(real))


def _holds(condition: sp.Basic, numbers: dict) -> bool:
    """Whether a condition (relations joined by And, Or, Not) holds at the point (in
    mpmath numbers); False where a side is not real there."""
    if condition is sp.true or condition is sp.false:
        return bool(condition)
    if isinstance(condition, sp.And):
        return all(_holds(c, numbers) for c in condition.args)
    if isinstance(condition, sp.Or):
        return any(_holds(c, numbers) for c in condition.args)
    if isinstance(condition, sp.Not):
        return not _holds(condition.args[0], numbers)
    if not isinstance(condition, Relational):
        return False
    with mpmath.workdps(DIGITS):
        try:
            difference = _evaluate(condition.lhs, numbers)[0] - _evaluate(condition.rhs, numbers)[0]
        except (_NotEvaluated, ZeroDivisionError, ValueError, TypeError, OverflowError):
            return False
        if abs(mpmath.im(difference)) > 1e-20 * max(1, abs(difference)):
            return False
        x = mpmath.re(difference)
        return {">": x > 0, ">=": x >= 0, "<": x < 0, "<=": x <= 0, "==": x == 0, "!=": x != 0}[condition.rel_op]


def _point_text(point: dict, model) -> str:
    """'m = 1.3, g = 2.7' for the parameters; the state's values after them."""
    names = {s: n for n, s in model.symbols.parameters.items()}
    names |= {q: n for q, n in zip(model.q, model.coordinate_names())}
    names |= {qd: f"d{n}/dt" for qd, n in zip(model.qd, model.coordinate_names())}
    shown = [f"{names.get(s, to_unicode(s))} = {float(sp.N(v, 15)):.6g}" for s, v in point.items()]
    return ", ".join(shown) or "every parameter value"
