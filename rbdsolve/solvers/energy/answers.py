"""The answers of an energy question (docs/json.md, energy)."""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from rbdsolve.solvers.conditions.conditions import CriticalValue


@dataclass(frozen=True)
class EnergyAnswers:
    integral: str  # "T + V" (energy conserved) or "T2 - T0 + V" (Jacobi's integral)
    constant: sp.Expr  # the integral h as a function of the state
    start: sp.Expr  # its value at the start state
    rate_squared: dict[str, sp.Expr] | None  # coordinate -> q̇²(q) (one coordinate), else None
    speed_squared: dict[str, sp.Expr] | None  # point -> v²(q) along the motion (one coordinate)
    to: dict[str, sp.Expr] | None  # the configuration asked ('to'): coordinate -> value, or None
    there: There | None  # the rates and speeds there, or None
    work: dict[str, sp.Expr] | None = None  # applied load -> its work from the start, V_F(q₀) − V_F(q)
    critical: tuple[CriticalValue, ...] = ()  # the critical values of ``there.reached_when``
    momenta: dict[str, sp.Expr] | None = None  # cyclic coordinate -> its constant momentum p = ∂L/∂q̇ (several coordinates)
    rates: dict[str, sp.Expr] | None = None  # cyclic coordinate -> its rate in q and the other's rate, from p


@dataclass(frozen=True)
class There:
    """At the configuration asked (``to``): q̇² and |q̇|, and each point's speed |v|;
    ``reached`` False (and the rates and speeds None) where q̇² < 0 there, None where
    the parameters decide it: ``reached_when`` says where (q̇² ≥ 0 there, solved for one
    parameter where one splits it), and the rates and speeds hold there."""

    rate_squared: dict[str, sp.Expr]
    rate: dict[str, sp.Expr | None]
    speed: dict[str, sp.Expr | None]
    reached: bool | None
    work: dict[str, sp.Expr] | None = None  # each applied load's work from the start to here
    reached_when: sp.Basic = sp.true  # where q̇² ≥ 0 there, for every value the assumptions allow


@dataclass(frozen=True)
class NumericEnergyAnswers:
    start: float | None
    rate_squared: dict[str, float | None]  # at 'to'
    rate: dict[str, float | None]
    speed: dict[str, float | None]
