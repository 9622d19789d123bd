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
class FreePrecession:
    """Torque-free precession of an axisymmetric body (precession.py)."""

    axis: str  # the symmetry axis: e1, e2 or e3 (principal axes of 'moments')
    spin: sp.Expr  # ω₃, along the axis
    transverse: sp.Expr  # ω⊥, across it
    omega: sp.Expr  # |ω|
    angular_momentum: sp.Expr  # |L|
    body_rate: sp.Expr  # Ω_b: ω about the axis, relative to the body
    space_rate: sp.Expr  # φ̇: the axis about L, in space
    alpha: sp.Expr  # angle between ω and the axis
    nu: sp.Expr  # angle between the axis and L
    gamma: sp.Expr  # angle between ω and L


@dataclass(frozen=True)
class SteadySpinAnswers:
    body: str
    moments: tuple[sp.Expr, sp.Expr, sp.Expr]  # J₁, J₂, J₃ about the principal axes e1, e2, e3
    cases: tuple[SpinCase, ...]
    precession: FreePrecession | None = None  # when 'precession' is asked


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
    precession: FreePrecession | None = None  # in floats, when 'precession' is asked
