"""Rotations in 3D: about an axis, by a sequence of body-fixed turns, and the angular
velocity of a turning frame.

A turn by α about the unit axis n (Rodrigues):

    R = cos α 1 + sin α [n]× + (1 − cos α) n nᵀ.

A sequence of body-fixed (intrinsic) turns, first about a scene axis, then about an
axis of the turned frame, and so on (z-x-z Euler angles: [[z, ψ], [x, θ], [z, φ]]),
composes by right multiplication, R = R₁(α₁) R₂(α₂) R₃(α₃); the columns of R are the
turned frame's unit vectors in scene axes. Its angular velocity ω follows from
Ṙ Rᵀ = [ω]× (e.g. Goldstein, ch. 4.8), or, turn by turn, as the sum of each turn's rate
about its axis as the turns before it have placed it,

    ω = Σ_k α̇_k R₁ … R_(k−1) a_k                              (scene axes),

and a body's inertia in scene axes, J_scene = R J Rᵀ, is taken the same way from the
innermost turn out, J ← R_k J R_kᵀ for k = n … 1. A last turn about an axis of symmetry
of J (a top's spin, a wheel's roll) leaves J unchanged at its step, and appears in ω
only through its rate α̇_n: neither holds its angle, so T = ½ ωᵀ J_scene ω holds no t
for a body spun at a constant rate s about its axis (α_n = s t).
"""

from __future__ import annotations

import sympy as sp

from rbdsolve.model.state import State
from rbdsolve.form.tidy import tidy


def cross_matrix(n: sp.Matrix) -> sp.Matrix:
    """[n]×, with [n]× v = n × v."""
    return sp.Matrix([[0, -n[2], n[1]], [n[2], 0, -n[0]], [-n[1], n[0], 0]])


def axis_rotation(n: sp.Matrix, angle: sp.Expr) -> sp.Matrix:
    """Rodrigues' formula for a unit axis n."""
    return sp.cos(angle) * sp.eye(3) + sp.sin(angle) * cross_matrix(n) + (1 - sp.cos(angle)) * n * n.T


def sequence_rotation(turns: list[tuple[sp.Matrix, sp.Expr]]) -> sp.Matrix:
    """R = R₁(α₁) R₂(α₂) …, each turn about an axis of the frame turned so far."""
    R = sp.eye(3)
    for axis, angle in turns:
        R = R * axis_rotation(axis / sp.sqrt(axis.dot(axis)), angle)
    return R.applyfunc(tidy)


Turns = tuple[tuple[sp.Matrix, sp.Expr], ...]  # (unit axis in the frame turned so far, angle), outermost first


def unit_turns(turns: list[tuple[sp.Matrix, sp.Expr]]) -> Turns:
    """Each turn's axis as a unit vector (the angle unchanged)."""
    return tuple(((axis / sp.sqrt(axis.dot(axis))).applyfunc(tidy), angle) for axis, angle in turns)


def turns_angular_velocity(turns: Turns, state: State) -> sp.Matrix:
    """ω = Σ_k α̇_k R₁ … R_(k−1) a_k, in scene axes, each component tidied."""
    omega, placed = sp.zeros(3, 1), sp.eye(3)
    for axis, angle in turns:
        rate = state.d_dt(angle)
        if rate != 0:
            omega += rate * (placed * axis)
        placed = placed * axis_rotation(axis, angle)
    return omega.applyfunc(tidy)


def turns_conjugate(turns: Turns, J: sp.Matrix) -> sp.Matrix:
    """R J Rᵀ for R = R₁ … R_n, innermost turn first, each step tidied: a turn about an
    axis of symmetry of what it turns leaves it as it is, so its angle never shows."""
    out = sp.Matrix(J)
    for axis, angle in reversed(turns):
        R = axis_rotation(axis, angle)
        out = (R * out * R.T).applyfunc(tidy)
    return out


def vee(W: sp.Matrix) -> sp.Matrix:
    """w from a skew matrix W = [w]× (the inverse of ``cross_matrix``)."""
    return sp.Matrix([W[2, 1], W[0, 2], W[1, 0]])


def angular_velocity(R: sp.Matrix, state: State) -> sp.Matrix:
    """ω in the axes R is written in, from Ṙ Rᵀ = [ω]×."""
    return vee((state.d_dt(R) * R.T).applyfunc(tidy))
