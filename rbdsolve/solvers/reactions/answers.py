"""The answers of a reactions question (docs/json.md, reactions). A reaction is named
by its point (or contact) as steady_motion's and impact's are: ``reactions`` maps that
name to the force on the body (``force``, scene axes) and its components by name."""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from rbdsolve.solvers.conditions.conditions import CriticalValue
from rbdsolve.solvers.reactions.first_zero import FirstZero
from rbdsolve.solvers.reactions.largest import LargestFriction


@dataclass(frozen=True)
class Reaction:
    on: str  # the body the force acts on
    by: str | None  # the body it comes from (None: the ground, the surface, the string)
    how: object  # supports.How: pivot, guide, rolling, string, ball_joint (JSON: its value)
    components: dict[str, sp.Expr]  # R_Ox, R_Oy / N_C, F_C / T_S / M_O -> value
    force: tuple[sp.Expr, sp.Expr, sp.Expr]  # R on ``on``, scene axes
    moment: sp.Expr | None = None  # about e_z, where the support keeps the body from turning


@dataclass(frozen=True)
class ReactionsAnswers:
    reactions: dict[str, Reaction]  # functions of the state (q, q̇), the accelerations put in
    accelerations: dict[str, sp.Expr]  # q̈ per coordinate, from Lagrange's equations
    at: dict[str, Reaction] | None = None  # at the state asked for (at:, from_rest:)
    rate_squared: dict[str, sp.Expr] | None = None  # q̇² by T + V constant (from rest, one coordinate)
    along: dict[str, dict[str, sp.Expr]] | None = None  # name -> component -> value, a function of q
    contact_lost: dict[str, tuple[sp.Basic, ...]] | None = None  # N or T -> where it is zero (Eq's)
    least_friction: dict[str, sp.Expr] | None = None  # rolling contact -> least μ = |F|/N
    least_friction_at: dict[str, sp.Expr] | None = None  # at the state asked: rolling contact -> least μ there
    # at the state: support -> when it holds (N ≥ 0, T ≥ 0, μ_C ≥ |F|/N), solved for one parameter
    holds_when: dict[str, sp.Basic] | None = None
    # N or T -> where each of its zeros along the motion exists (|c| ≤ 1), as ``contact_lost``
    lost_exists_when: dict[str, tuple[sp.Basic, ...]] | None = None
    critical: tuple[CriticalValue, ...] = ()  # the critical values these conditions use
    # with every parameter given a value: N or T -> where it first reaches 0 along the motion
    first_zero: dict[str, FirstZero] | None = None
    # with every parameter given a value: rolling contact -> its least μ at its largest over the motion, and where
    least_friction_over: dict[str, LargestFriction] | None = None
    to: dict[str, sp.Expr] | None = None  # the configuration asked ('to'), where the motion gets to
    there: dict[str, Reaction] | None = None  # the forces there (None where the motion does not get there)
    there_rate_squared: dict[str, sp.Expr] | None = None  # q̇² there, from the energy integral ('to')
    there_reached: bool | None = None  # q̇² ≥ 0 there: decided (True, False), or None where the parameters decide


@dataclass(frozen=True)
class NumericReactionsAnswers:
    at: dict[str, dict[str, float]]  # name -> component -> value at the state
    accelerations: dict[str, float]
    residual: float  # the largest balance left, relative to its terms
