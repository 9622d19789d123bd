"""The answers of a kinematics question, both routes (docs/json.md, kinematics)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Mapping

import sympy as sp

Vector = tuple[sp.Expr, sp.Expr, sp.Expr]
Floats = tuple[float | None, float | None, float | None]


@dataclass(frozen=True)
class PointMotion:
    """A point at the state: r, v = dr/dt, a = dv/dt (scene axes) and the speed |v|."""

    point: str
    position: Vector
    velocity: Vector
    acceleration: Vector
    speed: sp.Expr


@dataclass(frozen=True)
class Distance:
    """|r_B − r_A| between two points, and its rate d|r_B − r_A|/dt."""

    between: tuple[str, str]
    distance: sp.Expr
    rate: sp.Expr


@dataclass(frozen=True)
class BodyMotion:
    """A body at the state: its angular velocity ω and angular acceleration α = dω/dt
    (scene axes; a planar body's (0, 0, α̇) and (0, 0, α̈), α its angle)."""

    body: str
    angular_velocity: Vector
    angular_acceleration: Vector


@dataclass(frozen=True)
class LineTurning:
    """The line from A to B in the plane: its rate of turning φ̇ and its angular
    acceleration φ̈ (about z, counterclockwise), φ the angle of r_B − r_A."""

    through: tuple[str, str]
    rate: sp.Expr
    acceleration: sp.Expr


@dataclass(frozen=True)
class KinematicsAnswers:
    at: Mapping[str, sp.Expr]  # the state used: 'theta', 'dot(theta)', 'ddot(theta)' -> value
    points: tuple[PointMotion, ...]
    distances: tuple[Distance, ...]
    bodies: tuple[BodyMotion, ...] = ()
    lines: tuple[LineTurning, ...] = ()


@dataclass(frozen=True)
class NumericPointMotion:
    point: str
    position: Floats
    velocity: Floats
    acceleration: Floats
    speed: float | None


@dataclass(frozen=True)
class NumericDistance:
    between: tuple[str, str]
    distance: float | None
    rate: float | None


@dataclass(frozen=True)
class NumericBodyMotion:
    body: str
    angular_velocity: Floats
    angular_acceleration: Floats


@dataclass(frozen=True)
class NumericLineTurning:
    through: tuple[str, str]
    rate: float | None
    acceleration: float | None


@dataclass(frozen=True)
class NumericKinematicsAnswers:
    at: Mapping[str, float | None]
    points: tuple[NumericPointMotion, ...]
    distances: tuple[NumericDistance, ...]
    bodies: tuple[NumericBodyMotion, ...] = ()
    lines: tuple[NumericLineTurning, ...] = ()
