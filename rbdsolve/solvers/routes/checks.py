"""Every answer checked before it is printed (issue 38): the equations an answer must
satisfy, evaluated at sampled admissible parameter values.

Each family says what its answers must satisfy (its ``check.py``, registered beside
its routes in ``solvers/__init__.py``): an equilibrium ∂V/∂q = 0, a steady motion its
balances, an eigenvalue det(K − λM) = 0, the velocities after an impact the impulse
equations, the reactions each body's balances. A residual is

- ``Vanishes``: an expression that must be 0, or
- ``Pencil``: K − λM at each eigenvalue λ, which must annihilate its mode shape a
  (or, without one, have determinant 0),

each with ``where``, the condition under which the answer exists (its existence
condition: a radicand ≥ 0, s ≥ s_c). It is evaluated in 30-digit arithmetic (mpmath)
at one point — the problem's values, the other parameters drawn inside the
assumptions; where ``where`` fails there, more are drawn (every parameter: the exact
answer is a formula for all of them), and a residual no admissible point reaches is
not checked. Coordinates and rates left in an answer (a reaction as a function of the
state) are drawn too.

It passes when |r| ≤ TOLERANCE · s, with s the size of its terms: the sum of the sizes
of a sum's terms, the product of a product's factors, |value| elsewhere (so a sum that
cancels to 0 is measured against what cancelled); for a pencil, each row of
(K − λM) a against the sum of |K| + |λ| |M| times |a| over it (|det(K − λM)| against
(max row sum of |K| + |λ| |M|)ⁿ without a shape). A failure is rbdsolve's bug: ``CheckFailed`` says so and the
question is left unanswered (exit code 1), never printed.
"""

from __future__ import annotations

import math
import random
from dataclasses import dataclass, replace
from typing import Callable, Iterable, Sequence

import mpmath
import sympy as sp
from sympy.core.relational import Relational

from rbdsolve.errors import UnsolvedError
from rbdsolve.form.arrange import subscript
from rbdsolve.form.printers import to_unicode
from rbdsolve.solvers.conditions.condition_roots import admissible, angle_parameters

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
    """K − λM at each eigenvalue λₖ annihilates its shape aₖ, (K − λₖM) aₖ = 0 (so is
    singular: aₖ ≠ 0), or where no shape is given is singular, det(K − λₖM) = 0;
    wherever ``where`` holds. K, M and λ are kept apart, so that the size of each entry
    of K − λM is |K| + |λ| |M| even where λ is a decimal that sympy would cancel against
    K at once (a certified eigenvalue); K and M are evaluated once for all λₖ."""

    about: str  # "" or " about equilibrium 2", after "λ₁" in messages
    K: sp.ImmutableMatrix
    M: sp.ImmutableMatrix
    eigenvalues: tuple[sp.Expr, ...]
    shapes: tuple[tuple[sp.Expr, ...] | None, ...]  # one per eigenvalue (None: none given)
    where: sp.Basic = sp.true

    @property
    def what(self) -> str:
        return f"the eigenvalues{self.about}"


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
    return sp.Tuple(residual.K, residual.M, *residual.eigenvalues, *(x for a in residual.shapes if a for x in a))


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
    """One point: the problem's values, the other parameters drawn inside the
    assumptions (a generic point: a wrong formula vanishes there by accident only)."""
    point = admissible(model, random.Random(3800), (), angles)
    return [] if point is None else [_with_states(point, states, random.Random(0))]


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


NOISE = mpmath.mpf(10) ** (6 - DIGITS)  # terms this small in DIGITS digits are roundings of zero


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
            if size <= NOISE:  # every term a rounding of zero (sin π in 30 digits): 0 = 0, nothing to weigh
                continue
            if mpmath.isfinite(value) and mpmath.isfinite(size) and abs(value) > TOLERANCE * size:
                return (f"{what} = {mpmath.nstr(value, 6)}, not 0 (its terms are of size "
                        f"{mpmath.nstr(size, 6)}, tolerance {TOLERANCE:g} of that)")
        return None


def _pencil(residual: Pencil, numbers: dict) -> list[tuple]:
    """[(what, value, size)] for each λₖ: each row of (K − λₖM) aₖ against the sum of its
    terms' sizes, or det(K − λₖM) against (max row sum of entry sizes)ⁿ. The entries
    are evaluated in 30 digits, the pencil's arithmetic then in floats: each is measured
    against the sizes of its terms, which rounding at 10⁻¹⁶ leaves far inside TOLERANCE
    (n³ operations in mpmath took a third of a 16-link chain's modes)."""
    K = [[_floats(_evaluate(x, numbers)) for x in row] for row in residual.K.tolist()]
    M = [[_floats(_evaluate(x, numbers)) for x in row] for row in residual.M.tolist()]
    n = len(K)
    out = []
    for k, (lam, shape) in enumerate(zip(residual.eigenvalues, residual.shapes), 1):
        name, about = f"λ{subscript(k)}", residual.about
        value, lam_size = _floats(_evaluate(lam, numbers))
        P = [[kv - value * mv for (kv, _), (mv, _) in zip(Kr, Mr)] for Kr, Mr in zip(K, M)]
        S = [[ks + lam_size * ms for (_, ks), (_, ms) in zip(Kr, Mr)] for Kr, Mr in zip(K, M)]
        if shape is None:
            scale = max(sum(row) for row in S) ** n if n else 0.0
            out.append((f"det(K − {name} M){about}", _determinant(P), scale))
            continue
        a = [_floats(_evaluate(x, numbers)) for x in shape]
        out += [(f"row {i + 1} of (K − {name} M) a{subscript(k)}{about}", sum(p * v for p, (v, _) in zip(P[i], a)),
                 math.fsum(sz * size for sz, (_, size) in zip(S[i], a))) for i in range(n)]
    return [(what, mpmath.mpmathify(v), mpmath.mpf(size)) for what, v, size in out]


def _floats(pair: tuple) -> tuple[complex, float]:
    value, size = pair
    return complex(value), float(size)


def _determinant(rows: list[list[complex]]) -> complex:
    """det by Gaussian elimination with partial pivoting (an empty matrix: 1)."""
    a = [list(r) for r in rows]
    det = 1 + 0j
    for j in range(len(a)):
        pivot = max(range(j, len(a)), key=lambda i: abs(a[i][j]))
        if a[pivot][j] == 0:
            return 0j
        if pivot != j:
            a[j], a[pivot], det = a[pivot], a[j], -det
        det *= a[j][j]
        for i in range(j + 1, len(a)):
            factor = a[i][j] / a[j][j]
            a[i] = [x - factor * y for x, y in zip(a[i], a[j])]
    return det


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
