"""Equilibria whose existence or stability depends on the parameters, as exams state
them: "exists when Ω ≥ Ω_c", "stable when Ω < Ω_c, unstable when Ω > Ω_c", with
Ω_c = √(g/R) (``solvers/conditions/conditions.py`` cuts a parameter's range into pieces
at its critical values and finds the sign on each).

Existence: each condition c ≥ 0 (a radicand, 1 − x² under acos, a spring's signed
length: ``existing_where``) that the parameters' signs do not decide holds on the
pieces where c > 0, a boundary included where c is finite. Stability can change only where an eigenvalue of the Hessian K crosses zero,
where det K = 0: det K is cut into pieces, and on each where the equilibrium exists K
is classified again with the parameter put in at a point of the piece (δ > 0 moving
it across); neighbours of one stability are one case (a double pendulum on a turntable
is stable below Ω_c1 and unstable above, whatever det K does past Ω_c2). What cannot
be split stays as before: undetermined, with the conditions as they were.
"""

from __future__ import annotations

from dataclasses import replace
from functools import lru_cache
from typing import Mapping

import sympy as sp

from rbdsolve.model.build import Model
from rbdsolve.model.derivative import derivative
from rbdsolve.model.energies.energy import hessian, memoized, potential_energy
from rbdsolve.model.energies.spring_length import crushed_sides, held_sides, without_deltas
from rbdsolve.solvers.equilibria.answers import Equilibrium, Stability, StabilityCase
from rbdsolve.solvers.conditions.condition_roots import angle_parameters
from rbdsolve.solvers.conditions.angle_signs import angle_sign
from rbdsolve.solvers.conditions.conditions import (Critical, Existence, Piece, at_samples, changes,
                                                 existing, existing_within_bounds, exists_when, partition,
                                                 real_where)
from rbdsolve.form.printers import to_unicode
from rbdsolve.form.roots import roots_as_absolute
from rbdsolve.form.tidy import square_root, tidy
from rbdsolve.solvers.conditions.signs import Undecided, matrix_inertia, over_sines, sign_of


@memoized
def gradient(model: Model) -> tuple[sp.Expr, ...]:
    """∂V/∂q, each component tidied."""
    V = potential_energy(model).total
    return tuple(tidy(derivative(V, q)) for q in model.q)


def existing_where(at: Mapping, model: Model) -> list[sp.Expr]:
    """What must be ≥ 0 for the solution ``at`` of ∂V/∂q = 0 to be an equilibrium of the
    scene: its radicands, 1 − c² under acos (its values real), and each spring's signed
    length s·u there (the spring on the side it is drawn on: model/energies/spring_length.py)."""
    return [*real_where(at.values()), *held_sides(model.springs, at), *unsquared_where(at, model)]


def unsquared_where(at: Mapping, model: Model) -> list[sp.Expr]:
    """``_unsquared_where``, once per model and root (the existence and the stiffness
    there each ask: seconds at θ₀ = acos(c) of six parameters)."""
    return list(_unsquared_where(model, tuple(at.items())))


@memoized
def _unsquared_where(model: Model, root: tuple) -> tuple[sp.Expr, ...]:
    """What must be ≥ 0 for a root found through a squared form of ∂V/∂q = 0 to solve
    the equations themselves. Solving clears the roots of the coordinates by squaring:
    a bead on a turning rod held to the axis by a spring, k (1 − L/√(d² + s²)) = m Ω²,
    gives s² = k² L²/(k − m Ω²)² − d², real for Ω past √(k/m) too, where √(d² + s²) =
    k L/|k − m Ω²| is not k L/(k − m Ω²). Each root whose radicand is a square there is
    |F|; where ∂V/∂q vanishes with |F| = F only (or −F only), F ≥ 0 (−F ≥ 0) is the
    condition."""
    grad = gradient(model)
    if not any(square_root(p) and p.base.has(*model.q) for g in grad for p in g.atoms(sp.Pow)):
        return ()
    residual = [roots_as_absolute(g.xreplace(dict(root))) for g in grad]
    out = []
    for a in sorted({a for r in residual for a in r.atoms(sp.Abs)}, key=sp.default_sort_key):
        holds = [sign for sign in (1, -1) if all(_vanishes(r.xreplace({a: sign * a.args[0]})) for r in residual)]
        if len(holds) == 1:
            out.append(holds[0] * a.args[0])
    return tuple(out)


def stiffness_at(model: Model, at: Mapping) -> sp.ImmutableMatrix:
    """K = ∂²V/∂q∂q at the root ``at``, as ``unsquared`` writes it: once per model and
    root (the equilibria classify it and the modes about them take it again; at
    θ₀ = acos(…) of six parameters its factoring takes seconds)."""
    return _stiffness_at(model, tuple(at.items()))


@memoized
def _stiffness_at(model: Model, at: tuple) -> sp.ImmutableMatrix:
    V = potential_energy(model).total
    root = dict(at)
    return sp.ImmutableMatrix(unsquared(without_deltas(hessian(V, model.q).xreplace(root)), root, model))


def unsquared(H: sp.Matrix, at: Mapping, model: Model) -> sp.Matrix:
    """H (a Hessian, a stiffness matrix) at the root ``at``, its square roots of squares
    written as the unsquared equations have them (``unsquared_where``) and each entry
    tidied: √(d² + s²) = k L/(k − m Ω²) at the bead's off-centre equilibrium, not a nest
    of radicals."""
    signs = unsquared_where(at, model)
    if not signs:  # √((h + l)²) at θ = 0 is h + l, |d − L| where the signs do not decide it
        return H.applyfunc(lambda e: _compact(tidy(roots_as_absolute(e)) if _radical(e, model) else tidy(e)))
    known = {a: f for f in signs for a in (sp.Abs(f), sp.Abs(-f))}
    return H.applyfunc(lambda e: _compact(tidy(roots_as_absolute(e).xreplace(known))))


COMPACT_OPS = 120  # an entry longer than this is put over one denominator and factored, where that is shorter


@lru_cache(maxsize=256)  # θ₀ = ±acos(c) give one K entry: factored once (0.7 s each for a rod on a spring of natural length)
def _compact(entry: sp.Expr) -> sp.Expr:
    """A long entry as one factored fraction where that is shorter: a rod on a wall spring
    at sin(θ₀/2) = a k/(4 a k − g m) has K = a (3 a k − g m)(5 a k − g m)/(4 a k − g m),
    which cos(θ₀) and sin(θ₀) put in wrote as 800 operations of nested fractions."""
    if sp.count_ops(entry) <= COMPACT_OPS:
        return entry
    short = sp.factor(sp.together(entry))  # (cancel first is 3 times slower for the same form)
    return short if sp.count_ops(short) < sp.count_ops(entry) else entry


def _radical(expr: sp.Expr, model: Model) -> bool:
    """Does expr hold a square root of parameters alone (a radicand the root put in)?"""
    return any(square_root(p) and p.base.free_symbols and not p.base.has(*model.q) for p in expr.atoms(sp.Pow))


def _vanishes(expr: sp.Expr) -> bool:
    return sp.cancel(sp.together(expr)) == 0


def existence_where(at: Mapping, model: Model, first: sp.Symbol | None = None) -> Existence | None:
    """Where the solution ``at`` of ∂V/∂q = 0 is an equilibrium (``existing_where`` ≥ 0,
    and > 0 where zero would put a spring with a natural length at zero length:
    ``crushed_sides``), solved for ``first`` where it can; None where it cannot be split.
    Once per model, root and ``first``: the equilibria, their stability cases and the
    modes about each root ask for it again."""
    return _existence_where(model, tuple(at.items()), first)


@memoized
def _existence_where(model: Model, at: tuple, first: sp.Symbol | None) -> Existence | None:
    nonnegative, positive = _conditions(dict(at), model)
    return exists_when((), model, nonnegative, first=first, positive=positive)


def _conditions(at: Mapping, model: Model) -> tuple[list[sp.Expr], list[sp.Expr]]:
    """What must be ≥ 0 and what must be > 0 for ``at`` to be an equilibrium."""
    # F = 0 in an unsquared condition is no root (√(d² + s²) = k L/F): strict, as a crushed spring is
    return existing_where(at, model), [*crushed_sides(model.springs, at), *unsquared_where(at, model)]


def necessary_where(at: Mapping, model: Model, first: sp.Symbol | None = None) -> sp.Basic:
    """Where the equilibrium ``at`` can exist: ``existence_where``'s condition, or where
    that cannot be split, the conjunction of those of its conditions that can, each
    alone (each is needed, so a case outside one lies where there is no equilibrium;
    a spring's length 2 h k L₀/(2 h k − g m) > 0 splits where −1 ≤ cos θ₀ ≤ 1 of six
    parameters does not); true where none can."""
    found = existence_where(at, model, first)
    if found is not None:
        return found.condition
    nonnegative, positive = _conditions(at, model)
    alone = [exists_when((), model, [c], first=first) for c in nonnegative]
    alone += [exists_when((), model, (), first=first, positive=[c]) for c in positive]
    return sp.And(*[a.condition for a in alone if a is not None])


def with_cases(found: Equilibrium, model: Model, at: Mapping,
               first: sp.Symbol | None = None) -> tuple[Equilibrium, tuple[Critical, ...]]:
    """The equilibrium with ``exists_when`` and ``stability_cases`` where they depend on
    the parameters (``at``: its coordinates, one only where ``existing_where`` holds),
    and the critical values used, in ``first`` where it can (a question's ``for:``).
    Found from the symbols, whatever values are given: with values the stability itself
    is decided by them, and the cases say where that holds."""
    existence = existence_where(at, model, first)
    if existence is None:
        return _unsplit(_by_existence(_where_needed(found, model, at, first), model)), ()
    found = replace(found, exists_when=existence.condition)
    criticals = existence.criticals
    inertia = matrix_inertia(found.hessian, model.assumed)
    if not isinstance(inertia, Undecided):
        return found, criticals
    pieces = _stability_pieces(found.hessian, existence.condition, model, first)
    if pieces is None:
        return _kept_sign(found, model, existence.condition is sp.true), criticals
    cases = tuple(StabilityCase(piece.when(), stability) for piece, stability in pieces)
    changed = changes([piece for piece, _ in pieces])
    # with values for what decides it, the values decide (at the boundary itself: undetermined);
    # so do values that leave a parameter open but decide the sign for each of its values
    # (k given below k_c = m (Ω² + g/R) for every Ω: unstable, not "depends on k")
    decided = bool(model.values) and (not inertia.expr.xreplace(dict(model.values)).free_symbols
                                      or found.stability in _DECIDED)
    if len(cases) == 1:
        reason = found.reason if decided else _one_verdict(cases[0].stability, existence.condition is sp.true)
        return replace(found, stability=found.stability if decided else cases[0].stability,
                       reason=reason), (*criticals, *changed)
    if decided:  # the values decide; the cases say where that holds
        return replace(found, stability_cases=cases), (*criticals, *changed)
    what = ("the Hessian of V changes sign" if found.hessian.rows == 1
            else "an eigenvalue of the Hessian of V changes sign (det K = 0)")
    p = to_unicode(pieces[0][0].parameter)
    at = "its critical value" if len(changed) == 1 else "its critical values"
    return (replace(found, stability=Stability.DEPENDS, stability_cases=cases,
                    reason=f"{what} as {p} passes {at}"), (*criticals, *changed))


_DECIDED = (Stability.STABLE, Stability.UNSTABLE, Stability.NEUTRAL)  # found with the values (``classify``)


def _kept_sign(found: Equilibrium, model: Model, everywhere: bool) -> Equilibrium:
    """An undetermined equilibrium whose K keeps one sign over every value the
    parameters' ranges allow, proved with each angle parameter in (0, π) (``angle_sign``:
    sin α > 0 there), decided by it: a diagonal entry negative
    throughout, unstable; every leading minor positive throughout, stable (Sylvester). A
    disk on a spring, on an incline of angle α: K = −r (g m sin α + 18 k r/5) < 0 at its
    top, though sin α alone has no sign."""
    if found.stability is not Stability.UNDETERMINED:
        return found
    H = found.hessian
    if any(angle_sign(H[i, i], model) == -1 for i in range(H.rows)):
        stability = Stability.UNSTABLE
    elif all(angle_sign(tidy(H[:k, :k].det()), model) == 1 for k in range(1, H.rows + 1)):
        stability = Stability.STABLE
    else:
        return found
    return replace(found, stability=stability, reason=_one_verdict(stability, everywhere))


def _where_needed(found: Equilibrium, model: Model, at: Mapping, first: sp.Symbol | None) -> Equilibrium:
    """An undetermined equilibrium of one coordinate whose existence does not split
    whole (−1 ≤ cos θ₀ ≤ 1 of six parameters), decided where K/sin²θ₀ (``over_sines``)
    has one sign inside the bounds the equilibrium needs (``necessary_where``): a rod on
    a spring of natural length, K = k l² h² L₀ sin²θ₀/s³ with s = 2 h k L₀/(2 h k − g m),
    stable wherever it exists. Otherwise as found."""
    if found.stability is not Stability.UNDETERMINED or found.hessian.rows != 1:
        return found
    judged = over_sines(found.hessian[0, 0], at.values())
    if judged == found.hessian[0, 0]:
        return found
    part = partition(judged, model, first)
    kept = existing_within_bounds(part.pieces, necessary_where(at, model, first), model) if part else None
    verdicts = {_stability_on(sp.Matrix([[judged]]), piece, model) for piece in kept or ()}
    if len(verdicts) != 1 or verdicts & {Stability.UNDETERMINED, Stability.NEUTRAL}:
        return found
    (stability,) = verdicts
    return replace(found, stability=stability, reason=_one_verdict(stability, False))


def _by_existence(found: Equilibrium, model: Model) -> Equilibrium:
    """An undetermined equilibrium of one coordinate whose K is a condition of its own
    existence (≥ 0 where it exists) times a factor of one sign: stable (or unstable)
    wherever it exists, off its boundary. A bead on a hoop tilted at α and turned at Ω:
    K = m (Ω⁴ R² cos²α − g²)/Ω², and it exists only where Ω⁴ R² cos²α − g² ≥ 0."""
    if found.stability is not Stability.UNDETERMINED or found.hessian.rows != 1:
        return found
    K = found.hessian[0, 0]
    for condition in found.conditions:
        ratio = sp.cancel(sp.together(K / condition))
        sign = sign_of(ratio, model.assumed)
        if not isinstance(sign, int):
            sign = angle_sign(ratio, model)
        if sign in (1, -1):
            stability = Stability.STABLE if sign == 1 else Stability.UNSTABLE
            return replace(found, stability=stability, reason=_one_verdict(stability, False))
    return found


def _unsplit(found: Equilibrium) -> Equilibrium:
    """An equilibrium whose existence no parameter splits keeps its conditions as they
    are, each ≥ 0, for ``exists_when``: not "True", which says it always exists (a bead
    on a hoop tilted at α and turned at Ω exists only where Ω⁴ R² cos²α ≥ g², which
    splits in neither)."""
    if not found.conditions or found.exists_when is not sp.true:
        return found
    return replace(found, exists_when=sp.And(*(sp.GreaterThan(c, 0) for c in found.conditions)))


def _one_verdict(stability: Stability, everywhere: bool) -> str:
    """Why one stability holds on every piece of the parameters' range (a double
    pendulum's (π, π) with a hinge spring c: a maximum for small c, a saddle past
    det K = 0, unstable either way)."""
    where = ("for every value of the parameters" if everywhere
             else "wherever the equilibrium exists, off its boundary")  # K = 0 at a closed boundary
    what = {Stability.STABLE: "the Hessian of V is positive definite",
            Stability.UNSTABLE: "the Hessian of V has a negative eigenvalue"}.get(
        stability, "the same verdict holds")
    return f"{what} {where}"


def _stability_pieces(H: sp.Matrix, exists: sp.Basic, model: Model,
                      first: sp.Symbol | None) -> list[tuple[Piece, Stability]] | None:
    """The stability on each piece of the range where det K keeps its sign, those where
    the equilibrium does not exist left out, neighbours of one stability joined; None
    where det K cannot be split, or a piece lies partly where it exists."""
    found = partition(_boundary(H), model, first)
    kept = existing(found.pieces, exists, model) if found else None
    if kept is None:
        return None
    out: list[tuple[Piece, Stability]] = []
    for piece in kept:
        stability = _stability_on(H, piece, model)
        if out and out[-1][1] is stability and out[-1][0].high == piece.low:
            out[-1] = (out[-1][0].joined(piece), stability)
        else:
            out.append((piece, stability))
    return out or None


def _boundary(H: sp.Matrix) -> sp.Expr:
    """What vanishes where the stability can change: det K, zero exactly where an
    eigenvalue of K crosses zero (the trace or an entry changing sign decides nothing
    alone: a double pendulum's K₁₁ changes sign above where it stops being stable)."""
    return sp.factor(tidy(sp.Matrix(H).det()))


def _stability_on(H: sp.Matrix, piece: Piece, model: Model) -> Stability:
    """K classified at a point of the piece: exactly (δ > 0), else at SAMPLES random
    points of it (the parameters as rationals, so each K is exact numbers), which
    must all agree.

    The samples are classified first: a class found exactly at the δ-point holds at
    every point of the piece, so samples that all agree on a class give that class,
    and the δ-point's assumption queries (tenths of a second over nested radicals) are
    not made. Where the samples do not all agree on one, it is as above."""
    H = sp.Matrix(H)
    samples = at_samples(piece, H, model, 24, angle_parameters(H))
    seen = {_classified(K) for K in samples} if samples else set()
    if len(seen) == 1 and Stability.UNDETERMINED not in seen:
        return seen.pop()
    value, _ = piece.inside(H)
    found = _classified(value.applyfunc(sp.factor))
    if found is not Stability.UNDETERMINED:
        return found
    return seen.pop() if len(seen) == 1 else Stability.UNDETERMINED


def _classified(H: sp.Matrix) -> Stability:
    inertia = matrix_inertia(H, {})
    if isinstance(inertia, Undecided):
        return Stability.UNDETERMINED
    if inertia.negative:
        return Stability.UNSTABLE
    if inertia.zero:
        return Stability.UNDETERMINED
    return Stability.STABLE
