"""The answers of an eom question, both routes (docs/json.md, eom)."""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp


@dataclass(frozen=True)
class FrameAnswers:
    """The equations written in one moving frame: L', its equations, F with
    L − L' = dF/dt, and whether they are the scene's equations."""

    frame: str
    lagrangian: sp.Expr  # L' in the frame
    equations: tuple[sp.Expr, ...]  # its Lagrange's equations, each = 0
    total_derivative: sp.Expr  # F with L − L' = dF/dt
    equivalent: bool  # the equations agree with the scene's and L − L' − dF/dt = 0


@dataclass(frozen=True)
class EomAnswers:
    """Lagrange's equations, exact: each equation, the same in each moving frame asked,
    whether they agree and the total derivative that links them, and q̈ in general and
    at a state."""

    equations: tuple[sp.Expr, ...]  # each expression = 0, one per coordinate
    frames: tuple[FrameAnswers, ...] = ()  # the frames asked for
    equivalent: bool | None = None  # every frame agrees (None: no frames asked)
    total_derivative: sp.Expr | None = None  # F of the first frame asked
    accelerations: dict[str, sp.Expr] | None = None  # q̈ per coordinate, of q, q̇ (None: M singular)
    at: dict[str, sp.Expr] | None = None  # q̈ per coordinate at the state asked for (None: none asked)


@dataclass(frozen=True)
class NumericFrameAnswers:
    """The equations in one moving frame, with numbers, and whether they agree with the
    scene's."""

    frame: str
    equations: tuple[sp.Expr, ...]  # Lagrange's equations from L' in the frame, each = 0
    equivalent: bool  # the same as the scene's, coefficient by coefficient, within the errors


@dataclass(frozen=True)
class NumericEomAnswers:
    """Lagrange's equations with numbers: each equation, its relative error, and the
    frames' equations."""

    equations: tuple[sp.Expr, ...]  # each expression = 0, float coefficients
    relative_errors: tuple[float, ...]  # per equation, against the 50-digit derivation
    frames: tuple[NumericFrameAnswers, ...] = ()
