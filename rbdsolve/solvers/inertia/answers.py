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
    at: dict[str, sp.Expr] | None = None  # the configuration asked about (coordinate -> value)
    axis: tuple[sp.Expr, ...] | None = None  # the unit vector e of 'axis', scene axes
    J_axis: sp.Expr | None = None  # eᵀ J_P e: the moment about that axis through P (G by default)


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
    J_axis: float | None = None  # eᵀ J_P e about the asked axis (scene axes), if one is asked
