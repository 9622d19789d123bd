"""The answers of an impact question (docs/json.md, impact); the numeric route gives
the same fields as floats."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Mapping

import sympy as sp


@dataclass(frozen=True)
class ImpactAnswers:
    impulses: Mapping[str, sp.Expr]  # the generalized impulse I_a, per coordinate
    velocities: Mapping[str, sp.Expr]  # q̇_a just after, per coordinate
    points: Mapping[str, tuple[sp.Expr, sp.Expr, sp.Expr]]  # velocities just after
    particles: Mapping[str, tuple[sp.Expr, sp.Expr, sp.Expr]]  # striking particles' velocities after
    contact_impulses: Mapping[str, sp.Expr]  # size of each collision's impulse, λ |n|
    sticking_impulses: Mapping[str, tuple[sp.Expr, sp.Expr, sp.Expr]]  # a sticking particle's impulse on the system
    restitution: Mapping[str, sp.Expr]  # e implied by a particle's given velocity after
    energy_before: sp.Expr  # kinetic energy of the system and the striking particles
    energy_after: sp.Expr
    energy_lost: sp.Expr
    support_impulse: tuple[sp.Expr, sp.Expr, sp.Expr]  # Δp − Σ P: what the supports gave
    centre_of_percussion: sp.Expr | None  # the asked parameter's value for no support impulse
    energy_fraction: sp.Expr | None = None  # (Tᵢ − T_f)/Tᵢ, the fraction lost; None where Tᵢ = 0
