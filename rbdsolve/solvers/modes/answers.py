"""The answers of a modes question, both routes (docs/json.md, modes)."""

from __future__ import annotations

from dataclasses import dataclass
from enum import Enum
from typing import Mapping

import sympy as sp

from rbdsolve.solvers.equilibria.answers import Stability
from rbdsolve.solvers.conditions.conditions import CriticalValue


class Motion(Enum):
    OSCILLATION = "oscillation"
    GROWTH = "growth"
    NEUTRAL = "neutral"
    DEPENDS = "depends"  # on the parameters: see cases


class Form(Enum):
    """How an exact route's eigenvalue is given: a formula, or a decimal each of whose
    digits is proven (a root of a factor of degree ≥ 5: solvers/modes/certified.py)."""

    EXACT = "exact"
    CERTIFIED = "certified"


CERTIFIED_DEGREE = 5  # an irreducible factor this long has its roots as certified decimals


@dataclass(frozen=True)
class MotionCase:
    """The kind of small motion (oscillation, growth) that holds when a condition on the
    parameters does."""

    when: sp.Basic  # a condition on the parameters
    kind: Motion


@dataclass(frozen=True)
class ModesAnswers:
    """Small motions about an equilibrium, exact: M and K, det(K − λM), the eigenvalues
    and what each gives (a frequency, a growth rate), the mode shapes, and the
    conditions and critical values where the motion changes kind."""

    about: Mapping[str, sp.Expr]
    M: sp.ImmutableMatrix
    K: sp.ImmutableMatrix
    characteristic: sp.Expr  # det(K − λM), a polynomial in λ
    eigenvalues: tuple[sp.Expr, ...]  # λ, ascending, repeated by multiplicity
    frequencies: tuple[sp.Expr | None, ...]  # ω = √λ where λ > 0
    motions: tuple[Motion, ...]
    shapes: tuple[tuple[sp.Expr, ...], ...]  # one amplitude vector per eigenvalue
    growth_rates: tuple[sp.Expr | None, ...] = ()  # γ = √(−λ) where λ < 0
    multiplicities: tuple[int, ...] = ()  # of each λ as a root of det(K − λM)
    amplitude_check: object = None  # solvers/modes/amplitude.py, with 'check_amplitudes'
    cases: tuple[tuple[MotionCase, ...], ...] = ()  # per λ: its kind case by case (empty: decided)
    critical: tuple[CriticalValue, ...] = ()  # where a λ changes sign
    forms: tuple[Form, ...] = ()  # per λ: a formula, or certified decimals (its ω, γ and shape alike)
    certified_digits: int | None = None  # the significant digits of every certified decimal
    exists_when: sp.Basic = sp.true  # where the equilibrium it is about exists (as for equilibria; true: always)


@dataclass(frozen=True)
class NumericModesAnswers:
    """Small motions about an equilibrium with numbers: M and K, the eigenvalues,
    frequencies and shapes with their error bounds, and the conditioning they come
    from."""

    about: Mapping[str, float]
    M: tuple[tuple[float, ...], ...]
    K: tuple[tuple[float, ...], ...]
    eigenvalues: tuple[float, ...]  # λ, ascending
    frequencies: tuple[float | None, ...]  # ω = √λ where λ > 0
    motions: tuple[Motion, ...]
    shapes: tuple[tuple[float, ...], ...]  # first nonzero entry 1, as on the exact route
    absolute_errors: tuple[float, ...]  # the bound on |λ̂ − λ| for each λ
    relative_errors: tuple[float | None, ...]  # that over |λ|; None where λ is neutral (zero within it)
    growth_rates: tuple[float | None, ...] = ()  # γ = √(−λ) where λ < 0
    orthonormal_shapes: tuple[tuple[float, ...], ...] = ()  # the shapes scaled so aᵢᵀ M aⱼ = δᵢⱼ
    clusters: tuple[tuple[int, ...], ...] = ()  # modes (1-based) equal within their bounds: one mode space each
    shape_errors: tuple[float, ...] = ()  # sin Θ bound between each mode's computed space and the exact one
    condition_M: float | None = None  # κ₂(M)
    conditions: tuple[float | None, ...] = ()  # relative condition number κ(λ) of each λ; None where neutral
    spread: float | None = None  # max |λ|/min |λ| over the modes that are not neutral
    amplitude_check: object = None  # solvers/modes/amplitude.py, with 'check_amplitudes'


@dataclass(frozen=True)
class Skipped:
    """An equilibrium whose small oscillations were not answered, and why."""

    about: Mapping[str, object]
    reason: str


def none_answered(skipped: tuple[Skipped, ...] | list[Skipped], found_by: str) -> str:
    """Why 'about: each' answered nothing: each equilibrium's reason, or, where there was
    none to answer about, that no equilibrium was found (``found_by``: how they were
    sought), never an empty reason."""
    if not skipped:
        return f"no equilibrium was found {found_by}, so there are no small oscillations about one"
    return "no equilibrium's small oscillations could be answered: " + "; ".join(
        s.reason or "(no reason given)" for s in skipped)


@dataclass(frozen=True)
class EachModesAnswers:
    """'about: each': the modes at every equilibrium ``equilibria`` lists (both routes)."""

    modes: tuple  # a ModesAnswers (or NumericModesAnswers) per equilibrium answered
    skipped: tuple[Skipped, ...] = ()  # the others (a singular mass matrix, an undecidable sign)


def with_amplitude_check(question, model, solution):
    """The modes solution with ``amplitude_check`` filled in when the question asks for
    it (solvers/modes/amplitude.py's ``with_check``; both routes call this); unchanged
    otherwise, without importing the simulation's module (~2 ms of start-up)."""
    if not getattr(question.options, "check_amplitudes", ()):
        return solution
    from rbdsolve.solvers.modes.amplitude import with_check

    return with_check(question, model, solution)


@dataclass(frozen=True)
class GyroscopicCase:
    """A stability of M ü + G u̇ + K u = 0 that holds when a condition on the parameters
    does, with the growth rate of the motion where it is unstable and one is known."""

    when: sp.Basic
    stability: Stability
    growth_rate: sp.Expr | None = None


@dataclass(frozen=True)
class GyroscopicModesAnswers:
    """Small motions with gyroscopic terms (a spinning top, a rotor in gimbals, a body in a
    turning frame), exact: the steady state (the coordinates kept and the cyclic ones'
    steady rates and momenta), M, G and K, det(K − ω²M + iωG), the frequencies ω, and
    where the motion is stable: the conditions, case by case, and the critical values."""

    about: Mapping[str, sp.Expr]  # coordinates kept -> value
    steady: Mapping[str, sp.Expr]  # cyclic coordinate -> its steady rate (Routh's reduction)
    momenta: Mapping[str, sp.Expr]  # cyclic coordinate -> its constant momentum ∂L/∂q̇
    M: sp.ImmutableMatrix
    G: sp.ImmutableMatrix  # skew: Gᵢⱼ = ∂cᵢ/∂qⱼ − ∂cⱼ/∂qᵢ
    K: sp.ImmutableMatrix
    characteristic: sp.Expr  # det(K − ω²M + iωG), even in ω
    frequencies: tuple[sp.Expr, ...]  # ω > 0, ascending; real where the motion is stable
    stability: Stability  # stable, unstable, depends (see cases), undetermined, neutral
    stable_if: tuple[sp.Expr, ...]  # each > 0 where stable (the signs the parameters decide left out)
    stability_cases: tuple[GyroscopicCase, ...] = ()  # with stability DEPENDS, or where the values decide it
    critical: tuple[CriticalValue, ...] = ()
    neutral: int = 0  # directions with ω = 0


@dataclass(frozen=True)
class NumericGyroscopicModesAnswers:
    """Small motions with gyroscopic terms in numbers: the steady state, M, G and K, the
    frequencies ω of the roots s = iω on the imaginary axis, the growth rates Re s > 0
    of the others, every root s with its error bound, and the stability."""

    about: Mapping[str, float]
    steady: Mapping[str, float]
    M: tuple[tuple[float, ...], ...]
    G: tuple[tuple[float, ...], ...]
    K: tuple[tuple[float, ...], ...]
    frequencies: tuple[float, ...]  # ω > 0 of the roots on the axis, ascending
    stability: Stability  # stable (every root on the axis within its bound) or unstable
    growth_rates: tuple[float, ...]  # Re s > 0 of the roots off the axis, ascending
    roots: tuple[tuple[float, float], ...]  # every s of (s² M + s G + K) X = 0, as (re, im)
    root_errors: tuple[float, ...]  # the bound on |ŝ − s| of each root
    neutral: int = 0  # directions with s = 0
