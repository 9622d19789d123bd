"""The shape library: inertia tensors about the centre of mass, in the shape's own axes.

Table formulas (any dynamics text, e.g. Meriam & Kraige, Appendix B). Each shape has a
symmetry axis ("its axis"): a rod lies along its axis; a ring and a disk have their axis
normal to their plane; a plate of ``width`` (along x) and ``height`` (along y) has its
normal along z. ``axis:`` in a problem file says which body axis the shape's axis
points along; the tensor is permuted accordingly.

Products of inertia follow the convention J_xy = -∫ x y dm (the tensor's off-diagonal
entries), as in the SG2150 course.
"""

from __future__ import annotations

import sympy as sp

from rbdsolve.problem.schema import Shape

# The shape's own axis is its local z for a ring, disk or plate, and its local x for a
# rod. Rotating that axis to a body axis is a cyclic permutation of the coordinates.
_OWN_AXIS = {Shape.ROD: "x"}
_ORDER = "xyz"


def shape_inertia(shape: Shape, mass: sp.Expr, dims: dict[str, sp.Expr], axis: str) -> sp.Matrix:
    """J_G of ``shape`` in body axes, with the shape's axis along body ``axis``."""
    own = _moments(shape, mass, dims)
    shift = (_ORDER.index(axis) - _ORDER.index(_OWN_AXIS.get(shape, "z"))) % 3
    # Local axis i ends up on body axis (i + shift) mod 3.
    moments = [sp.Integer(0)] * 3
    for i, value in enumerate(own):
        moments[(i + shift) % 3] = value
    return sp.diag(*moments)


def _moments(shape: Shape, m: sp.Expr, dims: dict[str, sp.Expr]) -> tuple[sp.Expr, sp.Expr, sp.Expr]:
    """Principal moments (J_x, J_y, J_z) about the centre of mass, in the shape's axes."""
    if shape is Shape.PARTICLE:
        return (sp.Integer(0),) * 3
    if shape is Shape.ROD:  # slender rod along x: J = m L²/12 about any normal axis
        L = dims["length"]
        return sp.Integer(0), m * L**2 / 12, m * L**2 / 12
    if shape is Shape.RING:  # thin ring in the xy-plane: J_z = m r², J_x = J_y = m r²/2
        r = dims["radius"]
        return m * r**2 / 2, m * r**2 / 2, m * r**2
    if shape is Shape.DISK:  # uniform disk in the xy-plane: J_z = m r²/2, J_x = J_y = m r²/4
        r = dims["radius"]
        return m * r**2 / 4, m * r**2 / 4, m * r**2 / 2
    if shape is Shape.PLATE:  # rectangle a (x) by b (y): J_x = m b²/12, J_y = m a²/12
        a, b = dims["width"], dims["height"]
        return m * b**2 / 12, m * a**2 / 12, m * (a**2 + b**2) / 12
    raise ValueError(f"no inertia formula for {shape}")  # pragma: no cover


def explicit_inertia(entries: list[sp.Expr]) -> sp.Matrix:
    """J_G from a problem file: J (planar, about z), [J1, J2, J3], or 3x3 rows."""
    if len(entries) == 1:
        return sp.diag(0, 0, entries[0])
    if len(entries) == 3:
        return sp.diag(*entries)
    return sp.Matrix(3, 3, entries)
