"""Rotations in 3D: about an axis, by a sequence of body-fixed turns, and the angular
velocity of a turning frame.

A turn by α about the unit axis n (Rodrigues):

    R = cos α 1 + sin α [n]× + (1 − cos α) n nᵀ.

A sequence of body-fixed (intrinsic) turns, first about a scene axis, then about an
axis of the turned frame, and so on (z-x-z Euler angles: [[z, ψ], [x, θ], [z, φ]]),
composes by right multiplication, R = R₁(α₁) R₂(α₂) R₃(α₃); the columns of R are the
turned frame's unit vectors in scene axes. Its angular velocity ω follows from
Ṙ Rᵀ = [ω]× (e.g. Goldstein, ch. 4.8).
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


def vee(W: sp.Matrix) -> sp.Matrix:
    """w from a skew matrix W = [w]× (the inverse of ``cross_matrix``)."""
    return sp.Matrix([W[2, 1], W[0, 2], W[1, 0]])


def angular_velocity(R: sp.Matrix, state: State) -> sp.Matrix:
    """ω in the axes R is written in, from Ṙ Rᵀ = [ω]×."""
    return vee((state.d_dt(R) * R.T).applyfunc(tidy))
