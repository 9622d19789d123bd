"""Where a contact holds: a rocking body's contact point must stay on its edge.

A contact on an edge of limited extent (a half disk's arc, a slab's underside) is valid
only while its coordinate q lies in the span the model derived (``Rolling.span``, the
two ends a and b in either order): (q − a)(q − b) ≤ 0. A solution of ∂V/∂q = 0 outside
it (a half disk upside down, θ = π) is the formula's, not the body's: the contact point
would be off the edge, the body resting on a corner or its flat side, and the scene's
energies no longer describe it. Both routes drop such solutions with the reason
(``outside``); where the parameters leave the sign open, the equilibrium is kept with
a warning saying what must hold (``undecided``).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Mapping

import sympy as sp

from rbdsolve.errors import UnsolvedError
from rbdsolve.form.printers import to_unicode
from rbdsolve.form.tidy import tidy
from rbdsolve.model.build import Model
from rbdsolve.solvers.conditions.signs import Undecided, sign_of


@dataclass(frozen=True)
class OffEdge:
    """A solution of ∂V/∂q = 0 where a contact point would leave its edge: the first
    contact it fails, and why (the edge and its span)."""

    at: dict
    coordinate: str  # what the span bounds: the contact's coordinate, or it less the turn of the body rolled on
    value: sp.Expr  # its value there
    reason: str
    named: str  # the contact's coordinate


def outside(model: Model, at: Mapping[sp.Symbol, sp.Expr]) -> OffEdge | None:
    """Where ``at`` is outside some contact's span (None: inside, or undecided)."""
    for c, value, sign in _measures(model, at):
        if sign == 1:
            reason = (f"the contact point {c.name} would be off {c.body}'s {c.source.edge} edge, which it stays "
                      f"on for {span_text(model, c)}")
            return OffEdge(dict(at), to_unicode(model.readable(c.measured)), value, reason, c.coordinate.name)
    return None


def undecided(model: Model, solutions) -> list[str]:
    """For solutions kept where the parameters leave a contact's span open (the
    equilibrium's place depends on them), what must hold for the contact to exist there."""
    lines = []
    for sol in solutions:
        for c, value, sign in _measures(model, sol):
            if isinstance(sign, Undecided):
                name = to_unicode(model.readable(c.measured))
                lines.append(f"{name} = {to_unicode(value)} is an equilibrium only while "
                             f"the contact point {c.name} is on {c.body}'s {c.source.edge} edge, "
                             f"{span_text(model, c)}: the parameters leave that open")
    return lines


def split(model: Model, solutions) -> tuple[list, list[OffEdge]]:
    """Solutions (each {q: value}) kept, and those off an edge with their reason."""
    kept, dropped = [], []
    for sol in solutions:
        off = outside(model, sol)
        (kept.append(sol) if off is None else dropped.append(off))
    return kept, dropped


def warnings(dropped: list[OffEdge]) -> list[str]:
    """One line per reason: the values it drops (six digits when they are floats)."""
    by_reason: dict[str, list[str]] = {}
    for d in dropped:
        shown = f"{float(d.value):.6g}" if isinstance(d.value, sp.Float) else to_unicode(d.value)
        by_reason.setdefault(d.reason, []).append(shown)  # one contact per reason: its coordinate
    lines = []
    for reason, values in by_reason.items():
        listed = ", ".join(values[:6]) + (f", … ({len(values)} in all)" if len(values) > 6 else "")
        name = next(d.coordinate for d in dropped if d.reason == reason)
        what = ("is a solution of ∂V/∂q = 0 but not an equilibrium of the scene" if len(values) == 1 else
                "are solutions of ∂V/∂q = 0 but not equilibria of the scene")
        lines.append(f"{name} = {listed} {what}, not listed: {reason}")
    return lines


def held_for(model: Model, q: sp.Symbol) -> str:
    """Where the contacts measured by q hold ("" for none with a span)."""
    return " and ".join(span_text(model, c) for c in model.contacts if c.span is not None and c.measured.has(q))


def span_text(model: Model, c) -> str:
    """a ≤ q ≤ b when the parameters order the ends, else "q between a and b"."""
    a, b = c.span
    name = to_unicode(model.readable(c.measured))
    order = sign_of(tidy(b - a), model.decided_by)
    if isinstance(order, Undecided):
        return f"{name} between {to_unicode(a)} and {to_unicode(b)}"
    low, high = (a, b) if order >= 0 else (b, a)
    return f"{to_unicode(low)} ≤ {name} ≤ {to_unicode(high)}"


def _measures(model: Model, at: Mapping[sp.Symbol, sp.Expr]):
    """(contact, w₀, the sign of (w₀ − a)(w₀ − b)) for each contact with a span whose
    measure w (q, or q − β on a turning body's edge) has a value at ``at``."""
    for c in model.contacts:
        if c.span is None or not c.measured.free_symbols <= set(at):
            continue
        value = sp.sympify(c.measured.xreplace(dict(at)))
        a, b = c.span
        sign = sign_of(tidy(sp.expand((value - a) * (value - b))), model.decided_by)
        if isinstance(sign, Undecided):  # each side alone, by the ranges of the inverse functions in w₀
            sides = [_bounded_sign(tidy(value - end)) for end in (a, b)]
            sign = sign if None in sides else sides[0] * sides[1]
        if isinstance(sign, Undecided):  # on the span or at an end (asin u against ±π/2): it holds
            sides = [_bounded_sign(tidy(value - end), weak=True) for end in (a, b)]
            sign = sign if None in sides or sides[0] * sides[1] != -1 else 0
        if isinstance(sign, Undecided) and _left_of_the_axis(value, a, b):
            sign = 1
        yield c, value, sign


def _left_of_the_axis(value: sp.Expr, a: sp.Expr, b: sp.Expr) -> bool:
    """w₀ = atan2(y, x) with x ≤ 0 wherever it is real (a negative number times positive
    parameters and square roots), against the span −π/2 ≤ w ≤ π/2: cos w₀ ≤ 0, so w₀ is
    off the span but at its ends, where x = 0 — a place another root, asin(±1), gives
    already (a half disk on the floor turned by a couple: its second root, the formula's
    with the flat side down, never on the curved edge)."""
    if not isinstance(value, sp.atan2) or {tidy(a), tidy(b)} != {-sp.pi / 2, sp.pi / 2}:
        return False
    coefficient, rest = value.args[1].as_coeff_Mul()
    return coefficient.is_negative and all(
        f.is_positive or (f.is_Pow and (f.base.is_positive or f.exp == sp.Rational(1, 2)) and f.exp.is_real)
        for f in sp.Mul.make_args(rest))


# the ranges of the inverse functions an exact equilibrium is written with, and whether
# their ends are reached (atan's are not)
_RANGES = {sp.atan: (-sp.pi / 2, sp.pi / 2, False), sp.asin: (-sp.pi / 2, sp.pi / 2, True),
           sp.acos: (sp.Integer(0), sp.pi, True)}


def _bounded_sign(x: sp.Expr, weak: bool = False) -> int | None:
    """The sign of c + Σ kᵢ fᵢ(uᵢ), c and kᵢ numbers and fᵢ atan, asin or acos, from
    the ranges of the fᵢ, halved where the sign of uᵢ is known (atan u ∈ (0, π/2) for
    u > 0, the middle not reached): π − atan(π m/(2M)) > π/2 for every m, M. None
    where the range meets 0; ``weak``: where it crosses 0 (asin u + π/2 ≥ 0 is 1)."""
    low, high = (sp.Integer(0), True), (sp.Integer(0), True)  # (bound, reached)
    for term in sp.Add.make_args(sp.expand(x)):
        k, f = (term, sp.Integer(1)) if term.is_number else term.as_coeff_Mul()
        if f == 1:
            low, high = (low[0] + k, low[1]), (high[0] + k, high[1])
            continue
        if type(f) not in _RANGES:
            return None
        a, b, reached = _RANGES[type(f)]
        ends = [(a, reached), (b, reached)]
        middle = (sp.pi / 2 if f.func is sp.acos else sp.Integer(0), False)  # f(0), not reached for u ≠ 0
        rising = f.func is not sp.acos
        if f.args[0].is_positive:
            ends[0 if rising else 1] = middle
        elif f.args[0].is_negative:
            ends[1 if rising else 0] = middle
        (lo, lo_reached), (hi, hi_reached) = ends if k > 0 else ends[::-1]
        low = (low[0] + k * lo, low[1] and lo_reached)
        high = (high[0] + k * hi, high[1] and hi_reached)
    if low[0].is_positive or (low[0] == 0 and (weak or not low[1])):
        return 1
    if high[0].is_negative or (high[0] == 0 and (weak or not high[1])):
        return -1
    return None


def require_on_edges(question, model: Model) -> None:
    """Small oscillations about a configuration given with ``about:`` are refused where a
    contact point would be off its edge there (both modes routes)."""
    about = question.options.about
    at = {q: model.symbols.scalar(e) for q, (_, e) in zip(model.q, about)}
    off = outside(model, at)
    if off is not None:
        expr = next(e for name, e in about if name == off.named)
        raise UnsolvedError(f"{expr.loc}: no small oscillations about {off.named} = {expr.text}: {off.reason}")
