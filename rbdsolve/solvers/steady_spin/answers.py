"""The answers of a steady spin question, both routes (docs/json.md, steady_spin)."""

from __future__ import annotations

from dataclasses import dataclass
from enum import Enum

import sympy as sp


class Stability(Enum):
    STABLE = "stable"
    UNSTABLE = "unstable"
    NEUTRAL = "neutral"
    CONDITIONAL = "conditional"  # decided by the order of symbolic moments


@dataclass(frozen=True)
class SpinStability:
    spin: tuple[sp.Expr, sp.Expr, sp.Expr]  # ω in principal axes
    stability: Stability
    rate: sp.Expr | None  # growth rate (unstable), oscillation or precession rate (stable)
    condition: sp.Expr | None  # for CONDITIONAL: stable exactly when this is > 0


@dataclass(frozen=True)
class Condition:
    """When a case applies: these pairs of moments equal, those different (pairs the
    scene already decides are left out; both empty: always)."""

    equal: tuple[tuple[sp.Expr, sp.Expr], ...]
    different: tuple[tuple[sp.Expr, sp.Expr], ...]


@dataclass(frozen=True)
class SpinCase:
    condition: Condition
    steady_spins: tuple[tuple[sp.Expr, sp.Expr, sp.Expr], ...]  # ω, with free sizes
    stability: tuple[SpinStability, ...]


@dataclass(frozen=True)
class SteadySpinAnswers:
    body: str
    moments: tuple[sp.Expr, sp.Expr, sp.Expr]  # J₁, J₂, J₃ about the principal axes e1, e2, e3
    cases: tuple[SpinCase, ...]


@dataclass(frozen=True)
class NumericSpin:
    axis: tuple[float, float, float]  # unit principal axis in body axes
    moment: float
    stability: Stability
    rate: float | None  # per unit spin: turning (stable), growth (unstable), precession (symmetric)


@dataclass(frozen=True)
class NumericSteadySpinAnswers:
    body: str
    moments: tuple[float, float, float]  # ascending
    spins: tuple[NumericSpin, ...]
