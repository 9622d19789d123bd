"""Where, at the parameter values, a push or a tension first reaches zero along the
motion released from rest — the angle at which a disk leaves a drum.

The exact route gives the zeros of N(q) as equations (cos q = c, limits.py) and when
they are reached; with every parameter given a value, the reader wants the one place
the motion meets first. Released from rest at q₀ (one coordinate, energy conserved),

    q̇²(q) = 2 (V(q₀) − V(q)) / M(q),   dq̇²/dq = 2 q̈,

so the motion sets off towards the sign s of q̈(q₀) (q̈(q₀) = 0: it stays at rest) and
runs on while q̇² ≥ 0. The first zero of N on that way is found by stepping q from q₀
in the direction s — at most one whole turn for an angle — and refining the step where
N changes sign (a bracketing root finder, mpmath's Anderson–Björck); where q̇² turns
negative first, the motion turns back at that point (q̇² = 0, refined the same way) and
repeats between q₀ and it, so N never reaches zero.

A length has no turn to step over: it takes, in its place, a whole turn of a wheel as
large as the scene's largest length L (2π L in STEPS steps, ``length_step``: a hoop of
radius 0.3 m held by a spring of natural length 0.5 m steps 4.4 mm at a time over 3.1 m),
and a motion that meets neither a zero nor a turning back within it has no answer here.
Only where the push holds at the release (N(q₀) > 0: ``holds`` says when it does not). A
zero where N only touches 0 without changing sign between two steps (half a degree, or
2π L/720, apart) is not seen: it is a double root, not a generic loss of contact.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import sympy as sp

STEPS = 720  # a whole turn in steps of half a degree


@dataclass(frozen=True)
class FirstZero:
    """Along the motion at the values: where the push first reaches zero (coordinate ->
    value), or else where the motion first turns back; both None where it goes round a
    whole turn with the push positive and repeats (a periodic motion), or stays at rest."""

    lost_at: dict[str, float] | None
    turns_at: dict[str, float] | None


ANGLE_STEP = 2 * math.pi / STEPS


def first_zero(push: sp.Expr, rate_squared: sp.Expr, q: sp.Symbol, start: sp.Expr, name: str,
               values: dict, step: float = ANGLE_STEP) -> FirstZero | None:
    """``push`` N(q) and ``rate_squared`` q̇²(q) (plain symbols, the parameters' ``values``
    put in here) from rest at q = ``start``, in STEPS steps of ``step`` (half a degree for
    an angle; for a length, ``length_step``); None where there is no answer to give (the
    push does not hold at the release, a value is not a number, or a motion that is not
    periodic in q goes a whole turn without either)."""
    push, rate_squared = push.xreplace(values), rate_squared.xreplace(values)
    N, v2 = _numeric(push, q), _numeric(rate_squared, q)
    slope = sp.diff(rate_squared, q).xreplace({q: start.xreplace(values)})
    q0, direction = real_number(start.xreplace(values)), real_number(slope)
    if q0 is None or direction is None or not _positive(N(q0)):
        return None
    if direction == 0:
        return FirstZero(None, None)  # released at an equilibrium: it stays there
    step = math.copysign(step, direction)
    before = q0
    for i in range(1, STEPS + 1):
        x = q0 + i * step
        speed, force = v2(x), N(x)
        if speed is None or speed < 0:  # the motion turns back between ``before`` and x
            turn = _turning(v2, q0, before, x)
            if turn is None:
                return None
            if not _positive(N(turn)):
                return _lost(N, before, turn, name)
            return FirstZero(None, {name: turn})
        if force is None:
            return None
        if force <= 0:
            return _lost(N, before, x, name)
        before = x
    return FirstZero(None, None) if _periodic(push, q) and _periodic(rate_squared, q) else None


def _turning(v2, q0: float, a: float, b: float) -> float | None:
    """Where q̇² reaches 0 between a and b. From the release (a = q₀, where q̇² = 0
    already) the root finder would return q₀ itself: there q̇²/(q − q₀) is taken, whose
    value at q₀ is dq̇²/dq, of the motion's sign, and whose zero is the turning point (a
    stiff spring that turns a hoop back 2.7 mm down the slope, within the first step)."""
    if a != q0:
        return _root(v2, a, b)

    def divided(y: float) -> float | None:
        v = v2(y)
        return None if v is None or y == q0 else v / (y - q0)

    return _root(divided, q0 + (b - q0) * 1e-9, b)


def _near_turn(rate_squared: sp.Expr, q: sp.Symbol, q0: float) -> float | None:
    """How far from the release the motion turns back by q̇²'s quadratic about it,
    q̇² ≈ a₁ δ + ½ a₂ δ² = 0 at |δ| = 2 |a₁/a₂| (a₁ a₂ < 0), the values put in: a
    length's steps are kept well under it, so that a quick turn is met in its first
    steps. None where the quadratic does not turn back."""
    a1, a2 = (real_number(sp.diff(rate_squared, q, k).xreplace({q: q0})) for k in (1, 2))
    if a1 is None or a2 is None or a1 * a2 >= 0:
        return None
    return abs(2 * a1 / a2)


TURN_STEPS = 16  # a length's steps at least this many to the turning point q̇²'s quadratic gives


def length_step(lengths: list[float], rate_squared: sp.Expr, q: sp.Symbol, q0: float) -> float | None:
    """The step along a length coordinate from the release q₀: a whole turn of a wheel as
    large as the scene's largest length L (2π L over STEPS steps), the span a length has
    in place of an angle's turn, and at most 1/TURN_STEPS of the way to where q̇²'s
    quadratic turns back (``_near_turn``: a quick turn is met in its first steps, not
    stepped over); None without a length to scale by."""
    largest = max((abs(x) for x in lengths), default=0.0)
    if largest <= 0:
        return None
    step, turn = 2 * math.pi * largest / STEPS, _near_turn(rate_squared, q, q0)
    return min(step, turn / TURN_STEPS) if turn else step


def reaches(rate_squared: sp.Expr, q: sp.Symbol, start: sp.Expr, to: sp.Expr, values: dict) -> bool | None:
    """Does the motion released from rest at ``start`` get to q = ``to`` (the parameters'
    ``values`` put in)? It sets off towards the sign of dq̇²/dq at the start and runs on
    while q̇² ≥ 0: so only if ``to`` lies that way and q̇² ≥ 0 at every step of half a
    degree (of the way, for a length) up to it — a barrier in between (an inverted rod
    on a torsion spring cannot cross the top) turns it back before. Where q̇² repeats
    after a turn (q an angle only in sines and cosines of it), ``to`` is the same place a
    whole number of turns on, so it is met the first time the motion comes round to it
    (3π/2 reached going down from 2π/3 at −π/2). None where a value is not a number."""
    v2 = _numeric(rate_squared.xreplace(values), q)
    slope = real_number(sp.diff(rate_squared, q).xreplace(values).xreplace({q: start.xreplace(values)}))
    q0, end = real_number(start.xreplace(values)), real_number(to.xreplace(values))
    if q0 is None or end is None or slope is None:
        return None
    if end == q0:
        return True
    if slope != 0 and _periodic(rate_squared, q):
        way = math.copysign(1.0, slope)
        end = q0 + way * ((way * (end - q0)) % (2 * math.pi))  # the first time round it is met
    if slope * (end - q0) <= 0:
        return False  # it sets off the other way (or stays): it comes back to the start, never past it
    steps = max(8, min(STEPS, int(abs(end - q0) / (2 * math.pi / STEPS)) + 1))
    speeds = [v2(q0 + (end - q0) * i / steps) for i in range(1, steps + 1)]
    if any(v is None for v in speeds):
        return None
    scale = max(abs(v) for v in speeds) or 1.0
    return all(v >= -1e-12 * scale for v in speeds)


def first_loss(push: sp.Expr, q: sp.Symbol, a: float, b: float) -> float | None:
    """The first q on the way from ``a`` to ``b`` where ``push`` N(q) (the values put in)
    is no longer positive, refined between steps of half a degree (of the way, for a
    length) where N changes sign; ``a`` itself where N ≤ 0 there already; None where N
    stays positive all the way, or is not a real number on it."""
    N = _numeric(push, q)
    if not _positive(N(a)):
        return a if N(a) is not None else None
    steps = max(8, min(STEPS, int(abs(b - a) / (2 * math.pi / STEPS)) + 1))
    before = a
    for i in range(1, steps + 1):
        x = a + (b - a) * i / steps
        force = N(x)
        if force is None:
            return None
        if force <= 0:
            return _root(N, before, x)
        before = x
    return None


def _lost(N, a: float, b: float, name: str) -> FirstZero | None:
    root = _root(N, a, b)
    return None if root is None else FirstZero({name: root}, None)


def _numeric(expr: sp.Expr, q: sp.Symbol):
    """x ↦ expr at q = x as a float; None where it is not a real number there."""
    f = sp.lambdify(q, expr, modules="mpmath")

    def value(x: float) -> float | None:
        try:
            return real_number(f(x))
        except (ZeroDivisionError, ValueError, TypeError, OverflowError):
            return None

    return value


def unscaled(expr: sp.Expr, given: dict, q: sp.Symbol) -> sp.Expr | None:
    """expr at the values, without its positive factors, where that leaves q alone: the
    powers of positive parameters (``sign_part``) and the other factors free of q that
    sympy finds positive from the parameters' signs, a sum of them among them (a ball
    rolling off a drum, q̇² = 10 g (cos θ₀ − cos θ)/(7 (R + r)): 1/(R + r)). Parameters
    left open that only scale a push and q̇² so leave its zeros where they are."""
    from rbdsolve.solvers.conditions.conditions import sign_part  # the open scales' case only

    found = sign_part(sp.factor_terms(expr.xreplace(given)))
    found = sp.Mul(*(x for x in sp.Mul.make_args(found) if x.has(q) or x.is_positive is not True))
    return found if found.free_symbols <= {q} else None


def real_number(x: object) -> float | None:
    """x as a float where it is a finite real number (to rounding), else None."""
    try:
        z = complex(x)
    except (TypeError, ValueError):
        return None
    if not math.isfinite(z.real) or abs(z.imag) > 1e-12 * max(1.0, abs(z.real)):
        return None
    return z.real


def _positive(x: float | None) -> bool:
    return x is not None and x > 0


def _root(f, a: float, b: float) -> float | None:
    """The zero of f between a and b, where f changes sign there (f's value None
    counts as not a root); None where it does not or the root finder fails."""
    import mpmath

    fa, fb = f(a), f(b)
    if fa is None or fb is None or fa * fb > 0:
        return None
    if fb == 0:
        return b
    scale = max(abs(fa), abs(fb))

    def known(x) -> float:
        y = f(float(x))
        if y is None:
            raise ValueError("not a real number there")
        return y / scale

    # in double precision whatever mpmath's working precision is elsewhere; findroot then
    # checks |f(root)| ≤ 1e-10 of f's size at the bracket's ends: a pole where f changes
    # sign is no root
    try:
        with mpmath.workdps(15):
            root = float(mpmath.findroot(known, (a, b), solver="anderson", tol=1e-20))
    except (ValueError, ZeroDivisionError):
        return None
    return root if min(a, b) <= root <= max(a, b) else None


def _periodic(expr: sp.Expr, q: sp.Symbol) -> bool:
    """Does q enter only through sines and cosines of n q + b, n an integer (the same
    after a whole turn; not θ³ sin θ, nor a half-disk's sin(r θ/(R + r)))?"""
    inside = [f for f in expr.atoms(sp.sin, sp.cos) if f.has(q)]
    if expr.xreplace({f: sp.Integer(0) for f in inside}).has(q):
        return False
    return all(sp.Poly(f.args[0], q).degree() == 1 and sp.diff(f.args[0], q).is_integer for f in inside)
