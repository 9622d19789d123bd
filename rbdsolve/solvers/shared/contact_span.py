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
from rbdsolve.form.tidy import tidy
from rbdsolve.model.build import Model
from rbdsolve.solvers.shared.signs import Undecided, sign_of


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
    for c, value, measure in _measures(model, at):
        if sign_of(measure, model.decided_by) == 1:
            reason = (f"the contact point {c.name} would be off {c.body}'s {c.source.edge} edge, which it stays "
                      f"on for {span_text(model, c)}")
            return OffEdge(dict(at), sp.sstr(model.readable(c.measured)), value, reason, c.coordinate.name)
    return None


def undecided(model: Model, solutions) -> list[str]:
    """For solutions kept where the parameters leave a contact's span open (the
    equilibrium's place depends on them), what must hold for the contact to exist there."""
    lines = []
    for sol in solutions:
        for c, value, measure in _measures(model, sol):
            if isinstance(sign_of(measure, model.decided_by), Undecided):
                lines.append(f"{sp.sstr(model.readable(c.measured))} = {sp.sstr(value)} is an equilibrium only while "
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
        shown = f"{float(d.value):.6g}" if isinstance(d.value, sp.Float) else sp.sstr(d.value)
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
    name = sp.sstr(model.readable(c.measured))
    order = sign_of(tidy(b - a), model.decided_by)
    if isinstance(order, Undecided):
        return f"{name} between {sp.sstr(a)} and {sp.sstr(b)}"
    low, high = (a, b) if order >= 0 else (b, a)
    return f"{sp.sstr(low)} <= {name} <= {sp.sstr(high)}"


def _measures(model: Model, at: Mapping[sp.Symbol, sp.Expr]):
    """(contact, w₀, (w₀ − a)(w₀ − b)) for each contact with a span whose measure w (q, or
    q − β on a turning body's edge) has a value at ``at``."""
    for c in model.contacts:
        if c.span is None or not c.measured.free_symbols <= set(at):
            continue
        value = sp.sympify(c.measured.xreplace(dict(at)))
        a, b = c.span
        yield c, value, tidy(sp.expand((value - a) * (value - b)))


def require_on_edges(question, model: Model) -> None:
    """Small oscillations about a configuration given with ``about:`` are refused where a
    contact point would be off its edge there (both modes routes)."""
    about = question.options.about
    at = {q: model.symbols.scalar(e) for q, (_, e) in zip(model.q, about)}
    off = outside(model, at)
    if off is not None:
        expr = next(e for name, e in about if name == off.named)
        raise UnsolvedError(f"{expr.loc}: no small oscillations about {off.named} = {expr.text}: {off.reason}")
