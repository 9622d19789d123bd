"""Units that an answer's meaning fixes, where its dimension alone would print wrong.

A radian is a pure number, so a dimension (kg, m, s) cannot tell a torque from an
energy: both are kg·m²/s². What the answer is tells them apart, and which of the
coordinates are angles (``units.known_dimensions``). With q_i an angle in radians:

- K_ij = ∂²V/∂q_i∂q_j (and a Hessian of V, its eigenvalues): J/rad² is a torsional
  stiffness, N·m/rad; J/(m·rad) is N/rad; over two lengths, N/m;
- M_ij = ∂²T/∂q̇_i∂q̇_j: kg·m² over two angles (J·s²/rad²), kg·m over an angle and a
  length, kg over two lengths; G_ij (the gyroscopic matrix, of q̇_j in ∂L/∂q̇_i) is J·s
  over the same;
- a generalized impulse I_θ = Δ(∂T/∂θ̇) is an angular impulse, N·m·s (I_x: N·s), and a
  cyclic coordinate's momentum p = ∂L/∂q̇ in a steady motion kg·m²/s (p_x: kg·m/s);
- q̇ and q̈ of an angle are rad/s and rad/s², q̇² rad²/s² (of a length m/s, m/s², m²/s²);
- a moment (of gravity, of a support: M_C, M_O) is a torque, N·m; a support's force and
  its other components (N_C, F_C, R_Ox) are forces, N (the numeric route's numbers at a
  state too, which have no expression to read a dimension from);
- a growth rate γ = √(−λ) is in 1/s (e^(γt) grows; nothing turns), an eigenvalue λ = ω²
  of small oscillations in 1/s² (λ = 0 too, which has no dimension to read), and its
  frequency ω in rad/s (read from ω's expression, it has none where a parameter given
  as a bare number, a frame's rate Ω = 8.9, carries no dimension);
- the function F a frame's Lagrangian differs by, L' = L + dF/dt, is an action, J·s
  (F = 0 too); the point an inertia is taken about is a place, in m (the origin too);
- a parameter that is a torsional spring's stiffness is in N·m/rad, and so is each
  critical value of it.
"""

from __future__ import annotations

import re
from fractions import Fraction
from typing import Mapping

from rbdsolve.problem import expr as ex
from rbdsolve.problem.quantities.quantity import LENGTH, NUMBER, Dimension

TIME = Dimension(time=Fraction(1))
MASS = Dimension(mass=Fraction(1))
INERTIA = MASS * LENGTH ** 2
ENERGY = INERTIA / TIME ** 2
TORSIONAL = "N·m/rad"

# (dimension, radians it is per) -> its unit; any other keeps its dimension's unit
PER_RADIAN = {(ENERGY, 1): "N·m", (ENERGY, 2): TORSIONAL, (ENERGY / LENGTH, 1): "N/rad",
              (INERTIA / TIME, 1): "N·m·s"}  # fmt: skip
_PER_COORDINATE_PAIR = {"M": ENERGY * TIME ** 2, "G": ENERGY * TIME, "K": ENERGY, "hessian": ENERGY, "curvatures": ENERGY}
_RATE_OF = re.compile(r"(d?dot)\((\w+)\)")


def per_radians(dimension: Dimension, radians: int) -> str:
    """The unit of a quantity of ``dimension`` per ``radians`` radians: N·m for J/rad,
    N·m/rad for J/rad²; a pure number per radian is still a pure number."""
    return PER_RADIAN.get((dimension, radians), dimension.unit)


def pair_unit(key: str, first: Dimension | None, second: Dimension | None) -> str | None:
    """The unit of M_ij, K_ij or a Hessian's entry, q_i and q_j of these dimensions
    (NUMBER: an angle)."""
    if first is None or second is None:
        return None
    radians = (first == NUMBER) + (second == NUMBER)
    return per_radians(_PER_COORDINATE_PAIR[key] / (first * second), radians)


def rate_unit(dimension: Dimension | None, order: int, power: int = 1) -> str | None:
    """q̇ (order 1) or q̈ (order 2) of a coordinate of ``dimension``, to ``power``:
    rad/s, rad/s², rad²/s² for an angle."""
    if dimension is None:
        return None
    if dimension == NUMBER:
        return {(1, 1): "rad/s", (2, 1): "rad/s²", (1, 2): "rad²/s²"}.get((order, power), (TIME ** (-order * power)).unit)
    return ((dimension / TIME ** order) ** power).unit


def fixed_unit(kind: str, path: tuple, coordinates: Mapping[str, Dimension | None]) -> str | None:
    """The unit the answer at ``path`` (of a ``kind`` question) has by what it is (the
    module's list), or None where its expression is to be read."""
    named = [p for p in path if isinstance(p, str)]
    indices = [p for p in path if isinstance(p, int)]
    if not named:
        return None
    key = named[-1]
    if key in _PER_COORDINATE_PAIR:
        return _pair(key, indices, list(coordinates.values()))
    if key in ("growth_rates", "growth_rate"):  # γ = √(−λ): a rate of growth, e^(γt), not of turning
        return "1/s"
    if kind == "kinematics" and named[:1] == ["bodies"] and key in ("angular_velocity", "angular_acceleration"):
        return "rad/s" if key == "angular_velocity" else "rad/s²"
    if kind == "kinematics" and named[:1] == ["lines"] and key in ("rate", "acceleration"):
        return "rad/s" if key == "rate" else "rad/s²"
    if kind == "modes" and key == "eigenvalues":
        return "1/s²"
    if kind == "modes" and key == "frequencies":  # ω = √λ, whatever units the parameters were given in
        return "rad/s"
    if kind == "modes" and named[-2:-1] == ["momenta"] and key in coordinates:
        return _momentum(coordinates[key])  # the values put in first: a number, no dimension to read
    if kind == "eom" and key == "total_derivative":
        return "J·s"
    if kind == "inertia" and named == ["about"]:
        return "m"
    if kind in ("steady_motion", "reactions") and (key == "moment" or named[-2:-1] == ["components"]
                                                   and key.startswith("M_")):
        return "N·m"  # (steady_spin's 'moment' is a principal moment of inertia)
    if kind in ("steady_motion", "reactions") and (key == "force" or named[-2:-1] == ["components"]):
        return "N"  # at a given state too, whose rates put in as bare numbers (θ̇ = 8) carry no 1/s to read
    if kind == "reactions" and len(named) == 3 and named[0] in ("at", "along"):
        return "N·m" if key.startswith("M_") else "N"  # {support: {component: a number}}: the numeric route's
    if kind in ("eom", "reactions") and len(named) == 2 and named[0] in ("at", "accelerations"):
        return rate_unit(coordinates.get(key), 2) if key in coordinates else None
    if kind == "impact" and len(named) == 2 and key in coordinates:
        if named[0] == "impulses":
            return _impulse(coordinates[key])
        if named[0] == "velocities":
            return rate_unit(coordinates[key], 1)
    if kind == "energy" and len(named) >= 2 and named[-2] in ("speed", "speed_squared"):
        return "m/s" if named[-2] == "speed" else "m²/s²"  # a point's speed, whatever q's unit was given in
    if kind == "energy" and len(named) >= 2 and key in coordinates and named[-2] in ("rate", "rate_squared"):
        return rate_unit(coordinates[key], 1, 2 if named[-2] == "rate_squared" else 1)
    if kind == "reactions" and named[:1] in (["rate_squared"], ["there_rate_squared"]) and key in coordinates:
        return rate_unit(coordinates[key], 1, 2)
    if kind == "steady_motion" and (named[0] in ("rates", "angular_velocity")
                                    or named[0] == "at_solutions" and "values" not in named):
        return "rad/s"
    if kind == "steady_spin" and named[-2:-1] == ["precession"] and key in ("alpha", "nu", "gamma"):
        return "rad"  # the angles between ω, the axis and L
    return None


def _momentum(dimension: Dimension | None) -> str | None:
    """p = ∂L/∂q̇ of a coordinate of ``dimension``: kg·m²/s for an angle, kg·m/s for a length."""
    if dimension is None:
        return None
    return (INERTIA / TIME).unit if dimension == NUMBER else (MASS * dimension / TIME).unit


def _pair(key: str, indices: list[int], dims: list[Dimension | None]) -> str | None:
    if key == "curvatures":  # eigenvalues of the Hessian: one unit only if every q shares it
        shared = set(dims)
        return pair_unit("K", dims[0], dims[0]) if len(shared) == 1 and dims else None
    pair = indices[-2:]
    if len(pair) < 2 or any(i >= len(dims) for i in pair):
        return None
    return pair_unit(key, dims[pair[0]], dims[pair[1]])


def _impulse(dimension: Dimension | None) -> str | None:
    """I_q = Δ(∂T/∂q̇): J·s per the unit of q."""
    if dimension is None:
        return None
    return per_radians(ENERGY * TIME / dimension, 1 if dimension == NUMBER else 0)


def torsional_stiffnesses(problem) -> frozenset[str]:
    """The parameters that stand alone as a torsional spring's stiffness (``stiffness: c``
    of a spring with an ``angle``), in N·m/rad."""
    return frozenset(spring.stiffness.tree.id for spring in problem.springs
                     if spring.ends is None and isinstance(spring.stiffness.tree, ex.Name))


def couple_moments(problem) -> frozenset[str]:
    """The parameters a couple's moment is written in (``moment: C0``, ``C0*[0, 0, 1]``):
    M L² T⁻², a torque, in N·m, not J (an energy has the same dimension)."""
    return frozenset(name for couple in problem.couples for name in couple.moment.names())
