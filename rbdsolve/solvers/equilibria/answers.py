"""The answers of an equilibria question, both routes (docs/json.md, equilibria)."""

from __future__ import annotations

from dataclasses import dataclass
from enum import Enum
from typing import Mapping

import sympy as sp


class Stability(Enum):
    STABLE = "stable"
    UNSTABLE = "unstable"
    NEUTRAL = "neutral"
    UNDETERMINED = "undetermined"


@dataclass(frozen=True)
class Equilibrium:
    at: Mapping[str, sp.Expr]  # coordinate name -> value
    stability: Stability
    hessian: sp.ImmutableMatrix
    reason: str  # why this stability: the eigenvalue signs, or what is undecided
    conditions: tuple[sp.Expr, ...] = ()  # it exists only where each is ≥ 0


@dataclass(frozen=True)
class EquilibriaAnswers:
    equilibria: tuple[Equilibrium, ...]


@dataclass(frozen=True)
class NumericEquilibrium:
    at: Mapping[str, float]
    stability: Stability
    curvatures: tuple[float, ...]  # eigenvalues of the Hessian of V there, ascending
    free: tuple[tuple[float, ...], ...] = ()  # directions of a continuum it represents (unit vectors)


@dataclass(frozen=True)
class NumericEquilibriaAnswers:
    equilibria: tuple[NumericEquilibrium, ...]
    starts: int  # Newton starts
