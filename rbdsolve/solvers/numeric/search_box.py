"""The box the numeric equilibria search covers, one interval per coordinate, each
with the reason it is what it is (the report prints them):

* a declared ``range`` (``coordinates: {x: {kind: length, range: [0, 2*l]}}``), at the
  parameter values;
* the coordinate of a contact on an edge of limited extent: the span where the contact
  holds (a slab on a drum, |θ| ≤ b/(2R)): elsewhere no solution is an equilibrium of
  the scene (``contact_span``);
* a spring's polar distance r (the elastic pendulum's, P = r e(θ) from the spring's
  other end: model/energies/spring_length.py ``polar_distances``), without a range: r ≥ 0,
  to SEARCH_SCALE times the scene's largest length ((−r, θ) is the point (r, θ + π), so
  r < 0 would list each equilibrium twice, as the exact route does not);
* a periodic angle: one turn, (−π, π] (the scan adds a cell each side); a contact's
  travel round a circle is one where ∂V/∂q repeats after a turn (numeric_model.periodic_angles);
* an angle that is not periodic (declared ``periodic: false``, in the angle of a
  torsional spring, or a contact's travel round a circle, ``along`` it), without a
  range: ±SEARCH_SCALE π (five turns each way), or wider where a torsional spring holds
  the one coordinate and the bound of its equilibria is beyond (``_held_by_torsion``);
* anything else (a length, or a coordinate whose kind is not known): ±SEARCH_SCALE
  times the scene's largest length (the largest value of a parameter whose dimension
  is a length), ±SEARCH_SCALE when no length has a value. A mass of 1000 kg does not
  widen a box of metres.

Equilibria outside the box are not searched; a range is how to say where to look.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import sympy as sp

from rbdsolve.errors import UnsolvedError
from rbdsolve.form.printers import unicode_name
from rbdsolve.model.build import Model
from rbdsolve.model.energies.energy import potential_energy
from rbdsolve.problem.quantities.quantity import LENGTH
from rbdsolve.problem.schema import CoordinateKind
from rbdsolve.problem.surfaces import Measure, SurfaceKind

SEARCH_SCALE = 10.0


@dataclass(frozen=True)
class Interval:
    low: float
    high: float
    why: str  # "declared", "one turn", …


def search_box(model: Model, angles: frozenset) -> tuple[Interval, ...]:
    """One interval per coordinate; ``angles``: the periodic ones (numeric_model.periodic_angles)."""
    return tuple(_interval(c, q, q in angles, model) for c, q in zip(model.problem.coordinates, model.q))


def _interval(c, q: sp.Symbol, periodic: bool, model: Model) -> Interval:
    if c.range is not None:
        low, high = (_number(model.symbols.scalar(end).xreplace(dict(model.values)), c.name) for end in c.range)
        if low >= high:
            raise UnsolvedError(f"{c.range[0].loc}: the range of '{c.name}' is empty at the parameter values "
                                f"({low:g} to {high:g})")
        return Interval(low, high, "declared")
    span = _contact_span(model, q)
    if span is not None:
        return span
    polar = _polar_spring(model, q)
    if polar is not None:
        name, length = _largest_length(model)
        reach, scale = (SEARCH_SCALE * length, f"{SEARCH_SCALE:g} × {name} = {SEARCH_SCALE * length:g}") if name \
            else (SEARCH_SCALE, f"{SEARCH_SCALE:g}")
        return Interval(0.0, reach, f"≥ 0, a polar distance (spring '{polar}'), to {scale}")
    if periodic:
        return Interval(-math.pi, math.pi, "one turn")
    if c.kind is CoordinateKind.ANGLE or q in _torsion_angles(model) or c.name in _round_a_circle(model):
        reach = SEARCH_SCALE * math.pi
        held = _held_by_torsion(model, q)
        if held is not None and (held[0] < -reach or held[1] > reach):
            low, high = held
            return Interval(low, high, "wide enough for every equilibrium: only there can the torsional springs' "
                                       "moment balance the other loads at their largest")
        return Interval(-reach, reach, f"±{SEARCH_SCALE:g}π: an angle that winds up, with no declared range")
    name, length = _largest_length(model)
    if name is None:
        return Interval(-SEARCH_SCALE, SEARCH_SCALE, f"±{SEARCH_SCALE:g}: no length of the scene has a value")
    reach = SEARCH_SCALE * length
    return Interval(-reach, reach, f"±{SEARCH_SCALE:g} {name}; {name} = {length:g}, the scene's largest length")


def _held_by_torsion(model: Model, q: sp.Symbol) -> tuple[float, float] | None:
    """Where every equilibrium of a one-coordinate scene without frames lies, when
    ∂V/∂q = c q + b + Σ aᵢ Tᵢ(q) with c > 0 (torsional springs) and each Tᵢ a product of
    sines and cosines (|Tᵢ| ≤ 1): there c q + b = −Σ aᵢ Tᵢ, so |q + b/c| ≤ Σ |aᵢ|/c.
    A weak spring on a heavy pendulum (c = 0.5 N m/rad, m g d = 39 N m) has equilibria
    out to 78 rad, past the ±10π a winding angle is searched over; None where ∂V/∂q is
    not of that form."""
    if len(model.q) != 1 or model.problem.frames:
        return None
    gradient = sp.expand(sp.diff(potential_energy(model).total.xreplace(dict(model.values)), q))
    c = b = bound = 0.0
    for term in sp.Add.make_args(gradient):
        factor, rest = term.as_independent(q, as_Add=False)
        if factor.free_symbols:
            return None
        if rest == 1:
            b += float(factor)
        elif rest == q:
            c += float(factor)
        elif all(isinstance(p, (sp.sin, sp.cos)) or (p.is_Pow and isinstance(p.base, (sp.sin, sp.cos))
                                                        and p.exp.is_positive and p.exp.is_integer)
                 for p in sp.Mul.make_args(rest)):
            bound += abs(float(factor))
        else:
            return None
    if c <= 0:
        return None
    centre, half = -b / c, bound / c
    return centre - 1.01 * half - 1.0, centre + 1.01 * half + 1.0  # a margin past the bound, for the scan's cells


def _contact_span(model: Model, q: sp.Symbol) -> Interval | None:
    """The span of the contact measured by q itself, at the parameter values (None: no
    such contact, or its ends need values the model lacks)."""
    for c in model.contacts:
        if c.span is None or c.measured != q:
            continue
        ends = [end.xreplace(dict(model.values)) for end in c.span]
        if any(end.free_symbols for end in ends):
            return None
        low, high = sorted(float(end) for end in ends)
        if low < high:
            return Interval(low, high, f"the span where contact '{c.name}' holds")
    return None


def search_rule(model: Model, angles: frozenset) -> str:
    """Where the numeric search looks, in words, before any value is known: 'over θ in
    (−π, π]', 'over θ in the span where contact 'C' holds'…"""
    parts = []
    for c, q, name in zip(model.problem.coordinates, model.q, model.coordinate_names()):
        shown = unicode_name(name)
        spans = [k for k in model.contacts if k.span is not None and k.measured == q]
        if c.range is not None:
            parts.append(f"{shown} in its declared range")
        elif spans:
            parts.append(f"{shown} in the span where contact '{spans[0].name}' holds")
        elif _polar_spring(model, q) is not None:
            parts.append(f"{shown} ≥ 0 (a polar distance)")
        elif q in angles:
            parts.append(f"{shown} in (−π, π]")
        elif c.kind is CoordinateKind.ANGLE or q in _torsion_angles(model) or c.name in _round_a_circle(model):
            parts.append(f"{shown} in ±{SEARCH_SCALE:g}π")
        else:
            parts.append(f"{shown} in ±{SEARCH_SCALE:g} × the scene's largest length")
    return "over " + ", ".join(parts) + " (a coordinate's 'range' sets it)"


def _polar_spring(model: Model, q: sp.Symbol) -> str | None:
    """The name of a spring whose length |q| is written q because q is a polar distance
    (a Length of q itself with sign +1: at the reference q = 0 nothing else decides it;
    a declared range is read before this), or None."""
    for s in model.springs:
        if any(x.inside == q and x.sign == 1 for x in s.lengths):
            return s.name
    return None


def _torsion_angles(model: Model) -> set:
    """Coordinates in the angle of a torsional spring: angles, whatever their kind says."""
    return {q for s in model.springs if s.source.angle is not None for q in s.stretch.free_symbols & set(model.q)}


def _round_a_circle(model: Model) -> set[str]:
    """Coordinates that are a contact's travel round a fixed circle (``along`` it): an
    angle, whatever their kind says (a wheel inside a cylinder at θ = π is no length)."""
    return {c.coordinate for c in model.problem.contacts
            if c.measure is Measure.ALONG and c.surface.kind is SurfaceKind.CIRCLE and c.coordinate}


def round_a_circle(model: Model) -> frozenset:
    """``_round_a_circle``'s coordinates, as the model's symbols."""
    names = _round_a_circle(model)
    return frozenset(q for c, q in zip(model.problem.coordinates, model.q) if c.name in names)


def _largest_length(model: Model) -> tuple[str | None, float]:
    lengths = [(abs(float(model.values[model.symbols.parameters[n]])), n) for n, d in model.problem.dimensions
               if d == LENGTH and n in model.symbols.parameters and model.symbols.parameters[n] in model.values]
    if not lengths:
        return None, 0.0
    length, name = max(lengths)
    return name, length


def _number(value: sp.Expr, name: str) -> float:
    if value.free_symbols:
        raise UnsolvedError(f"the range of '{name}' needs values for {', '.join(sorted(map(str, value.free_symbols)))}")
    return float(value)


def box_text(model: Model, angles: frozenset) -> str:
    """'θ in [−25.1327, 25.1327] (declared)', one per coordinate."""
    return "; ".join(f"{unicode_name(name)} in [{i.low:.6g}, {i.high:.6g}] ({i.why})"
                     for name, i in zip(model.coordinate_names(), search_box(model, angles)))
