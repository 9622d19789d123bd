"""A spring's length as an exam writes it: d + x, not |d + x|.

A linear spring's length is √(d·d), d = r_A − r_B; where d lies along one axis sympy
writes √(u²) as |u|, and V = ½ k (|u| − l₀)² then gives sign(u) in ∂V/∂q and
DiracDelta(u) in K. An exam takes the spring as it is drawn: u keeps the sign it has at
the reference configuration (every coordinate 0) as long as the spring does not pass
through zero length, so |u| = u there when u > 0 (−u when u < 0), decided by the
parameters' signs and the assumptions (R = r + δ: ``model/assumptions.py``). Where that
sign is not decided (u = h − l at q = 0, with nothing said of h and l), |u| stays and the
model section states the two cases in words (``model/summary/summary.py``).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Mapping

import sympy as sp
from rbdsolve.form.zero import simplifies_to_zero


@dataclass(frozen=True)
class Length:
    """One |u| in a spring's length: u, and its sign at the reference configuration
    (1 or −1, by which |u| was written ±u), or None where it is not decided (|u| kept)."""

    inside: sp.Expr
    sign: int | None


def signed_length(length: sp.Expr, reference: Mapping[sp.Symbol, sp.Expr],
                  assumed: Mapping[sp.Symbol, sp.Expr],
                  ranges: Mapping[sp.Symbol, tuple[sp.Expr, sp.Expr]] | None = None,
                  values: Mapping[sp.Symbol, sp.Expr] | None = None) -> tuple[sp.Expr, tuple[Length, ...]]:
    """``length`` with each |u| written ±u where u's sign at ``reference`` (the
    coordinates at 0) is decided by the parameters' signs or ``assumed`` (the
    assumptions' substitutions), or else over the declared range of the one coordinate
    u holds (``_sign_over``), and what was done to each |u|."""
    found = sorted(length.atoms(sp.Abs), key=sp.default_sort_key)
    lengths = tuple(Length(a.args[0], _sign(a.args[0], reference, assumed, ranges or {}, values or {}))
                    for a in found)
    signed = {a: x.sign * x.inside for a, x in zip(found, lengths) if x.sign is not None}
    return length.xreplace(signed), lengths


def as_square_root(length: sp.Expr) -> sp.Expr:
    """√(d·d) written √(u²) = |u| where d·d is a square once its sin² + cos² are
    joined: a spring along a slope, d = (D − x)(cos α, sin α), has d·d = (D − x)²
    (cos² α + sin² α), which sympy leaves as √(D² − 2 D x + x²); |D − x| is then the
    form ``signed_length`` writes D − x. Small radicands of sines and cosines only
    (trigsimp is slow: a radicand of 60 operations with tan, sec and sinh took it a
    minute), and the length unchanged unless it became an |u|."""
    if not (length.is_Pow and length.exp == sp.S.Half) or sp.count_ops(length.base) > _SMALL:
        return length
    if any(f.func not in (sp.sin, sp.cos) for f in length.base.atoms(sp.Function)):
        return length
    joined = sp.sqrt(sp.factor(sp.trigsimp(length.base)))
    return joined if joined.has(sp.Abs) else length


_SMALL = 80  # operations in a radicand worth joining (two springs on a slope have ~30)


def _sign(u: sp.Expr, reference: Mapping, assumed: Mapping, ranges: Mapping, values: Mapping) -> int | None:
    """u's sign over the declared range of its coordinate first (``_sign_over``), else at
    the reference configuration where that lies inside the range (or none is declared):
    a rod sliding in a turning tube, x in [l/2, 10], tied to the axis at its inner end x −
    l/2, has that length positive over the range, though −l/2 at x = 0, outside it; a
    block hung by its top face at a/2 above its centre, depth y in [0, 5], has a/2 − y
    at the range's end y = 0, the spring drawn upside down there: neither decides, and
    |u| stays. The range's ends are read at the parameters' values too (x in [l/2, 10]
    with l = 10 cm: x − l/2 from 0 to 9.95, whatever the rate left open)."""
    over = _sign_over(u, ranges, assumed, values)
    if over is not None:
        return over
    if reference_outside(u, reference, ranges):
        return None
    return _sign_at(u, reference, assumed)


def reference_outside(u: sp.Expr, reference: Mapping, ranges: Mapping) -> bool:
    """Does the reference configuration lie at an end of, or outside, the declared range
    of a coordinate u holds (decided by the parameters' signs)?"""
    for q in u.free_symbols & set(ranges):
        at = reference.get(q)
        if at is None:
            continue
        lo, hi = ranges[q]
        inside = sp.And(sp.StrictLessThan(lo, at), sp.StrictLessThan(at, hi))
        if inside is sp.false:
            return True
    return False


def _sign_at(u: sp.Expr, reference: Mapping, assumed: Mapping) -> int | None:
    """u's sign at the reference configuration, where the parameters' signs (or the
    assumptions) decide it, and it is not 0; else None."""
    value = u.xreplace(dict(reference))
    for form in (value, value.xreplace(dict(assumed))):
        for written in (form, sp.factor(form)):
            if written.is_positive:
                return 1
            if written.is_negative:
                return -1
    return None


def _sign_over(u: sp.Expr, ranges: Mapping, assumed: Mapping, values: Mapping | None = None) -> int | None:
    """u's sign over the declared range [lo, hi] of the one coordinate q it holds, where u
    is linear in q: a linear u keeps one sign between its values at the ends, so u ≥ 0 at
    both and > 0 at one makes it positive inside the range (zero at most at an end: a
    collar on a turning rod with r in [0, 10 L] and a spring from the axis, |r| = r).
    None where that is not decided."""
    coordinates = u.free_symbols & set(ranges)
    if len(coordinates) != 1:
        return None
    (q,) = coordinates
    if sp.diff(u, q, 2) != 0:
        return None
    ends = [u.xreplace({q: end}) for end in ranges[q]]
    forms = [ends, [e.xreplace(dict(assumed)) for e in ends]]  # as _sign_at: as written, then assumed
    if values:
        forms.append([e.xreplace(dict(values)) for e in ends])  # then at the values given (a box's ends)
    for form in forms:
        if all(e.is_extended_nonnegative for e in form) and any(e.is_extended_positive for e in form):
            return 1  # (extended: an end may be ∞, a polar distance's)
        if all(e.is_extended_nonpositive for e in form) and any(e.is_extended_negative for e in form):
            return -1
    return None


def without_deltas(matrix: sp.Matrix) -> sp.Matrix:
    """A Hessian at a configuration with each DiracDelta(u) whose u is not zero there
    written 0: ∂²|u|/∂q² = 2 δ(u) (∂u/∂q)² vanishes wherever the spring's length is not
    zero, and a spring of zero length at an equilibrium is no spring an exam draws. A
    DiracDelta(0) (the length zero there whatever the parameters) is kept: V is not twice
    differentiable there, and the solvers say so."""
    deltas = {d: sp.Integer(0) for d in matrix.atoms(sp.DiracDelta) if not simplifies_to_zero(d.args[0])}
    return matrix.xreplace(deltas) if deltas else matrix


def held_sides(springs, at: Mapping[sp.Symbol, sp.Expr]) -> tuple[sp.Expr, ...]:
    """s·u at the configuration ``at`` for each |u| of the springs' lengths written s·u
    (``signed_length``): the stretch is the spring's own only where s·u ≥ 0, the spring
    on the side it is drawn on. A bead on a turning rod held by a spring from the axis
    (length |a + x|, written a + x) has the equilibrium x = m Ω² a/(k − m Ω²), where
    a + x = a k/(k − m Ω²): one only where k > m Ω²; past it, the bead would sit
    beyond the axis, the spring through zero length, where its V is not ½ k x²."""
    sides = []
    for spring in springs:
        for x in spring.lengths:
            if x.sign is not None:
                side = sp.factor(x.sign * x.inside.xreplace(dict(at)))
                if side not in sides:
                    sides.append(side)
    return tuple(sides)


def crushed_sides(springs, at: Mapping[sp.Symbol, sp.Expr]) -> tuple[sp.Expr, ...]:
    """The sides of ``held_sides`` whose zero puts a spring with a natural length l₀ ≠ 0
    at zero length (its stretch s·u − l₀ has a part other than its one |u|): there it
    pushes with k l₀ along no defined direction, no equilibrium
    (solvers/equilibria/zero_length.py), so such a side must be > 0, not ≥ 0. The
    elastic pendulum's r = L − m g/k at θ = π exists where k > m g/L, not at k = m g/L."""
    return held_sides([s for s in springs if _pushes_at_zero_length(s)], at)


def _pushes_at_zero_length(spring) -> bool:
    """One |u| in the length, written s·u, and a stretch other than s·u (an l₀ ≠ 0)."""
    if len(spring.lengths) != 1 or spring.lengths[0].sign is None:
        return False
    (x,) = spring.lengths
    return sp.expand(spring.stretch - x.sign * x.inside) != 0


def polar_distances(d: sp.Matrix, q: tuple[sp.Symbol, ...]) -> dict[sp.Symbol, tuple[sp.Expr, sp.Expr]]:
    """{r: (0, ∞)} where a spring's end-to-end vector is d = r e(θ), e a unit vector of
    the other coordinates with e(θ + π) = −e(θ) for one of them: r is a polar distance
    (the elastic pendulum, P = r (sin θ, −cos θ) on a spring from O). r < 0 then repeats a
    configuration, (r, θ) the same point as (−r, θ + π), so the exam's r ≥ 0 loses none,
    as a declared range [0, …] would say (``_sign_over``: |r| = r)."""
    found = {}
    for r in q:
        e = (d / r).applyfunc(sp.cancel)
        if not d.has(r) or e.has(r) or sp.trigsimp(sp.expand(e.dot(e))) != 1:
            continue
        turns = [t for t in q if t != r and e.has(t)]
        if any(_opposite(e, t) for t in turns):
            found[r] = (sp.Integer(0), sp.oo)
    return found


def _opposite(e: sp.Matrix, t: sp.Symbol) -> bool:
    """Whether e(t + π) = −e(t)."""
    return all(sp.expand_trig(x.xreplace({t: t + sp.pi}) + x) == 0 for x in e)
