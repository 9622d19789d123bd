"""The answers of an equilibria question, both routes (docs/json.md, equilibria)."""

from __future__ import annotations

from dataclasses import dataclass, field
from enum import Enum
from typing import Mapping

import sympy as sp

from rbdsolve.solvers.conditions.conditions import CriticalValue


class Stability(Enum):
    STABLE = "stable"
    UNSTABLE = "unstable"
    NEUTRAL = "neutral"
    UNDETERMINED = "undetermined"
    DEPENDS = "depends"  # on the parameters: see stability_cases


@dataclass(frozen=True)
class StabilityCase:
    """A stability that holds when a condition on the parameters does."""

    when: sp.Basic  # a condition on the parameters (a sympy relational)
    stability: Stability




@dataclass(frozen=True)
class Equilibrium:
    """One equilibrium, exact: where it is, its stability and why (the Hessian), the
    conditions on the parameters for it to exist and for each stability, and the
    configurations it equals."""

    at: Mapping[str, sp.Expr]  # coordinate name -> value
    stability: Stability
    hessian: sp.ImmutableMatrix
    reason: str  # why this stability: the eigenvalue signs, or what is undecided
    conditions: tuple[sp.Expr, ...] = ()  # it exists only where each is ≥ 0
    equivalent: tuple[Mapping[str, sp.Expr], ...] = ()  # other coordinate values of the same configuration
    exists_when: sp.Basic = sp.true  # the conditions solved for one parameter (true: always)
    stability_cases: tuple[StabilityCase, ...] = ()  # with stability DEPENDS: one per case


@dataclass(frozen=True)
class SingularPoint:
    """A solution of ∂V/∂q = 0 where the coordinates are singular (solvers/configuration/
    placement.py): not reported as an equilibrium."""

    at: Mapping[str, sp.Expr]
    verdict: str  # "not an equilibrium" or "undecided"
    reason: str
    lost: tuple[tuple[float, ...], ...]  # directions of q that do not move the scene there


@dataclass(frozen=True)
class EquilibriaAnswers:
    """Every equilibrium found exactly, the configurations where the coordinates are
    singular, and the critical parameter values where a stability changes."""

    equilibria: tuple[Equilibrium, ...]
    singular_points: tuple[SingularPoint, ...] = ()
    critical: tuple[CriticalValue, ...] = ()  # where an existence or a stability changes


@dataclass(frozen=True)
class NumericEquilibrium:
    """One equilibrium with numbers: where it is, its stability from the Hessian's
    curvatures, its free directions, the same configuration written otherwise, an
    exact form where recognized, and its error bound."""

    at: Mapping[str, float]
    stability: Stability
    curvatures: tuple[float, ...]  # eigenvalues of the Hessian of V there, ascending
    free: tuple[tuple[float, ...], ...] = ()  # directions of a continuum it represents (unit vectors)
    equivalent: tuple[Mapping[str, float], ...] = ()  # other coordinate values of the same configuration
    recognized: Mapping[str, str] = field(default_factory=dict)  # coordinate -> '0', 'pi/2', 'pi': within its bound
    bound: float | None = None  # the absolute error bound on the coordinates (when any is recognized)


@dataclass(frozen=True)
class NumericEquilibriaAnswers:
    """Every equilibrium found numerically, the starts searched from, and the singular
    configurations."""

    equilibria: tuple[NumericEquilibrium, ...]
    starts: int  # Newton starts
    singular_points: tuple[SingularPoint, ...] = ()
