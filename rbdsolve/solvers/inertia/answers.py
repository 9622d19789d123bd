"""The answers of an inertia question, both routes (docs/json.md, inertia)."""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from rbdsolve.report import steps as st


@dataclass(frozen=True)
class InertiaAnswers:
    mass: sp.Expr
    centre: tuple[sp.Expr, ...]  # r_G, scene axes
    about: tuple[sp.Expr, ...] | None  # the point P, or None
    J_G: sp.ImmutableMatrix  # about G, in the requested axes
    J: sp.ImmutableMatrix  # about P (J_G when no point is given)
    principal_moments: tuple[sp.Expr, ...]  # ascending, repeated by multiplicity
    principal_axes: tuple[tuple[sp.Expr, ...], ...]  # unit vectors, one per moment
    repeated: tuple[sp.Expr, ...]  # moments of multiplicity > 1 (their axes: any in a plane)


@dataclass(frozen=True)
class Principal:
    moments: tuple[sp.Expr, ...]
    axes: tuple[tuple[sp.Expr, ...], ...]
    repeated: tuple[sp.Expr, ...]
    steps: tuple[st.Step, ...]
    warnings: tuple[str, ...]


@dataclass(frozen=True)
class NumericInertiaAnswers:
    mass: float
    J: tuple[tuple[float, ...], ...]  # about the asked point (G by default), in the asked axes
    principal_moments: tuple[float, ...]  # ascending
    principal_axes: tuple[tuple[float, ...], ...]  # unit vectors, one per moment
    absolute_error: float  # bound on each principal moment's error
