"""The friction a motion released from rest needs: with every parameter given a value,
the least coefficient at each place, μ(q) = |F(q)|/N(q) along the motion, at its
largest over the places the motion reaches — what an exam means by "the least
coefficient of friction for the hoop to roll without slipping".

The places reached run from the release q₀ the way the motion sets off (first_zero.py)

    to where it turns back (q̇² = 0, ``turns_at``), or
    to where another push or tension is lost first (the motion as modelled ends there), or
    over a whole turn, where it goes round and repeats,

and μ is sampled at SAMPLES + 1 evenly spaced places of that span, its largest sample
refined by a golden-section search between the sample's neighbours. Where the
contact's own N reaches zero on the way, μ grows without bound towards that place: no
number is given (the first zero says where). A peak narrower than a sample's spacing
(1/240 of the span) can be missed, as first_zero's zeros can (docs/failure-edges.md).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import sympy as sp

from rbdsolve.solvers.reactions.first_zero import FirstZero

SAMPLES = 240


@dataclass(frozen=True)
class LargestFriction:
    """The largest least μ over the motion, ``mu``, the place ``at`` where it is needed
    (coordinate -> value), and where the span ends: ``until`` (coordinate -> value; None
    over a whole turn) and ``lost``, the push or tension whose zero ends it (None where
    the motion turns back there)."""

    mu: float
    at: dict[str, float]
    until: dict[str, float] | None
    lost: str | None


def largest_friction(push: sp.Expr, friction: sp.Expr, own: str, found: dict[str, FirstZero],
                     rate_squared: sp.Expr, q: sp.Symbol, start: float, name: str) -> LargestFriction | None:
    """μ = |``friction``|/``push`` (functions of q alone, every value put in) at its
    largest over the motion from rest at ``start``; ``found``: each push's first zero
    (first_zero.py, past the first loss left out), ``own`` the name of this contact's
    push. None where the span is not known, the motion stays at rest, or ``own`` is lost
    on the way (μ unbounded there)."""
    span = _span(found, rate_squared, q, start, name)
    if span is None:
        return None
    end, until, lost = span
    if lost == own or end == start:  # lost on the way (μ unbounded), or no span to take it over
        return None
    import numpy as np  # with values only: the exact routes load no numpy (tests/test_architecture.py)

    mu = _mu(push, friction, q)
    places = np.linspace(start, end, SAMPLES + 1)
    with np.errstate(all="ignore"):
        values = mu(places)
    if not np.all(np.isfinite(values)):
        return None
    i = int(np.argmax(values))
    best, at = float(values[i]), float(places[i])
    low, high = sorted((places[max(i - 1, 0)], places[min(i + 1, SAMPLES)]))
    refined = _refined(mu, float(low), float(high))
    if refined is not None and refined[0] > best:
        best, at = refined
    return LargestFriction(best, {name: at}, until, lost)


def _span(found: dict[str, FirstZero], rate_squared: sp.Expr, q: sp.Symbol, start: float,
          name: str) -> tuple[float, dict[str, float] | None, str | None] | None:
    """Where the motion reached ends, that place as an answer (None over a whole turn),
    and the push whose zero ends it (None: it turns back there, or goes round)."""
    if not found:
        return None
    losses = [(abs(z.lost_at[name] - start), z.lost_at[name], k) for k, z in found.items() if z.lost_at]
    if losses:
        _, end, lost = min(losses)
        return end, {name: end}, lost
    turns = [z.turns_at[name] for z in found.values() if z.turns_at]
    if turns:
        end = min(turns, key=lambda x: abs(x - start))
        return end, {name: end}, None
    slope = sp.diff(rate_squared, q).xreplace({q: start})
    try:
        direction = float(slope)
    except (TypeError, ValueError):
        return None
    if direction == 0:
        return None  # released at an equilibrium: it stays there, and the state asked gives μ
    return start + math.copysign(2 * math.pi, direction), None, None  # round and round: one turn is all of it


def _mu(push: sp.Expr, friction: sp.Expr, q: sp.Symbol):
    """q ↦ |F|/N as floats (numpy, element by element: an array of places at once)."""
    import numpy as np

    f = sp.lambdify(q, sp.Abs(friction) / push, modules="numpy")

    def mu(x):
        found = np.asarray(f(x))
        if np.iscomplexobj(found):  # a root of a negative number: no place the motion reaches
            found = np.where(np.abs(found.imag) <= 1e-12 * np.abs(found), found.real, np.nan)
        return np.broadcast_to(found.astype(float), np.shape(x))

    return mu


GOLDEN = (math.sqrt(5) - 1) / 2  # the golden section's bracket shrinks by this each step


def _refined(mu, low: float, high: float) -> tuple[float, float] | None:
    """μ's largest between ``low`` and ``high``, and where, by golden-section search
    (μ has one peak between a dense sample's neighbours): two inner points a fraction
    GOLDEN of the bracket from its ends; the bracket keeps the side of the larger one and
    shrinks by GOLDEN, reusing the other point, until it is 1e-12 of its scale (about 60
    steps). scipy's bounded Brent search did the same, but importing scipy.optimize
    took about 0.25 s (quiet) of a 2.5 s file."""
    import numpy as np

    if high <= low:
        return None

    def at(x: float) -> float:
        return float(mu(np.float64(x)))

    tolerance = 1e-12 * max(1.0, abs(low), abs(high))
    a, b = low, high
    c, d = b - GOLDEN * (b - a), a + GOLDEN * (b - a)
    fc, fd = at(c), at(d)
    with np.errstate(all="ignore"):
        while b - a > tolerance:
            if fc >= fd:
                b, d, fd = d, c, fc
                c = b - GOLDEN * (b - a)
                fc = at(c)
            else:
                a, c, fc = c, d, fd
                d = a + GOLDEN * (b - a)
                fd = at(d)
    x = (a + b) / 2
    value = at(x)
    return (value, x) if math.isfinite(value) else None
