"""The boundary a contact needs: each shape's named edges, in body axes.

A **curved** edge is an arc of a circle: its centre and radius, and the directions d
(unit, from the centre) that lie on the arc: those within the arc's half angle β of its
middle direction u (None: the whole circle). A half disk's arc is y ≥ 0 in its own axes
(u = y, β = π/2), a quarter disk's x, y ≥ 0 (u the diagonal, β = π/4), a hemisphere's
z ≥ 0 (its section by any plane through its axis), a cylinder segment's the directions
within its ``half_angle`` α of y (the segment y ≥ r cos α of the disk).
A **flat** edge is a straight side: its midpoint, its outward unit normal and its half
length; a plate's ``bottom`` is y = −h/2 with normal −y and half length w/2, a rod's its
own line (no thickness, half length l/2), a half disk's or hemisphere's flat face the
diameter (half length r). An arc's limits and a side's half length are the edge's
extent: a contact is valid only while its point stays on it (model/constraints/contacts.py).
The part's ``axis:`` turns them with the shape (Q, :func:`~rbdsolve.model.inertia.rotation_to`).
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import sympy as sp

from rbdsolve.model.inertia import OWN_AXIS, rotation_to
from rbdsolve.model.symbols import Symbols
from rbdsolve.problem.schema import Body, Part, Shape
from rbdsolve.form.zero import simplifies_to_zero

_X, _Y, _Z = sp.Matrix([1, 0, 0]), sp.Matrix([0, 1, 0]), sp.Matrix([0, 0, 1])
_ROUND_IN_PLANE = (Shape.RING, Shape.DISK, Shape.CYLINDRICAL_SHELL, Shape.CYLINDER, Shape.TUBE,
                   Shape.HALF_DISK, Shape.HALF_RING, Shape.QUARTER_DISK, Shape.CYLINDER_SEGMENT)  # fmt: skip
_DOMES = (Shape.HEMISPHERE, Shape.HEMISPHERICAL_SHELL)
_ARCS = {Shape.HALF_DISK: (_Y, sp.pi / 2), Shape.HALF_RING: (_Y, sp.pi / 2), Shape.CYLINDER_SEGMENT: (_Y, None),
         Shape.QUARTER_DISK: ((_X + _Y) / sp.sqrt(2), sp.pi / 4)}  # (middle, half angle); domes: (z, π/2)


@dataclass(frozen=True)
class Curved:
    centre: sp.Matrix  # from the body's origin, body axes
    radius: sp.Expr
    arc: tuple[sp.Matrix, sp.Expr] | None  # (u, β): d on the arc iff the angle from u to d is at most β
    plane_normal: sp.Matrix | None  # the circle's plane (None: a sphere's, any plane through its centre)


@dataclass(frozen=True)
class Flat:
    point: sp.Matrix  # the edge's midpoint, body axes
    outward: sp.Matrix  # unit normal out of the body
    half_length: sp.Expr  # the edge spans point ± half_length along e_z × outward


class NotInPlane(ValueError):
    """The edge's circle is not in the scene's xy-plane (the message says how to turn it)."""


def edge(shape: Shape, name: str, dims: dict[str, sp.Expr], axis: sp.Matrix | None,
         radius: sp.Expr | None = None, planar: bool = True) -> Curved | Flat:
    """Edge ``name`` of the shape, turned by its ``axis`` (None: no turn). ``radius``:
    a string wound at its own radius about the shape's centre (edge ``axle``).
    ``planar``: the edge must lie in the scene's xy-plane (False: a rim rolling on a
    plane in 3D, any way round)."""
    Q = rotation_to(axis, OWN_AXIS.get(shape, _Z)) if axis is not None else sp.eye(3)
    if name == "axle":
        return _in_plane(shape, Curved(sp.zeros(3, 1), radius, None, Q * _Z if shape in _ROUND_IN_PLANE else None))
    r = dims.get("outer_radius", dims.get("radius"))
    if name == "rim":
        rim = Curved(sp.zeros(3, 1), radius or r, None, None if shape in (Shape.SPHERE, Shape.SPHERICAL_SHELL)
                     else Q * _Z)
        return _in_plane(shape, rim) if planar else rim
    if name == "curved":
        middle, half = _ARCS.get(shape, (_Z, sp.pi / 2))
        half = dims["half_angle"] if shape is Shape.CYLINDER_SEGMENT else half
        plane = None if shape in _DOMES else Q * _Z
        return _in_plane(shape, Curved(sp.zeros(3, 1), r, (Q * middle, half), plane), Q)
    if name == "flat" and shape is Shape.CYLINDER_SEGMENT:  # the chord y = r cos α, 2 r sin α long
        alpha = dims["half_angle"]
        return _in_plane(shape, Flat(Q * (r * sp.cos(alpha) * _Y), Q * -_Y, r * sp.sin(alpha)), Q)
    if name == "flat":  # the straight edge through the centre: a half disk's diameter, a hemisphere's face
        outward = -_Y if shape is Shape.HALF_DISK else -_Z
        return _in_plane(shape, Flat(sp.zeros(3, 1), Q * outward, r), Q)
    sign = -1 if name == "bottom" else 1  # bottom / top of a plate or a rod
    half = dims["height"] / 2 if shape is Shape.PLATE else sp.Integer(0)
    extent = dims["width"] / 2 if shape is Shape.PLATE else dims["length"] / 2
    return Flat(Q * (sign * half * _Y), Q * (sign * _Y), extent)


def body_part(body: Body, name: str | None) -> Part:
    """The body's part named ``name`` (None: its only part)."""
    return body.parts[0] if name is None else next(p for p in body.parts if p.name == name)


def part_edge(part: Part, name: str, names: Symbols, radius: sp.Expr | None = None,
              planar: bool = True) -> Curved | Flat:
    """Edge ``name`` of a body's ``part``, in body axes from the body's origin: the
    shape's edge (:func:`edge`) moved by the part's ``at``; a part given by its inertia
    has only the circle of ``radius`` about its centre of mass (its ``at``), in the
    scene's plane. In a planar contact only the offset's component in the plane counts:
    the surface (a floor, a drum) runs through every depth, so a spool's rim at
    z = −w/2 touches the floor as one at z = 0 would."""
    if part.shape is None:
        found: Curved | Flat = Curved(sp.zeros(3, 1), radius, None, _Z)
    else:
        dims = {k: names.scalar(v) for k, v in part.dimensions}
        found = edge(part.shape, name, dims, names.axis(part.axis) if part.axis is not None else None, radius,
                     planar)
    if part.at is None:
        return found
    offset = names.vector(part.at)
    offset = offset if offset.rows == 3 else offset.col_join(sp.zeros(3 - offset.rows, 1))
    if planar:
        offset[2] = 0
    if isinstance(found, Curved):
        return replace(found, centre=found.centre + offset)
    return replace(found, point=found.point + offset)


def _in_plane(shape: Shape, e: Curved | Flat, Q: sp.Matrix | None = None) -> Curved | Flat:
    """A planar contact needs the edge's section in the scene's xy-plane."""
    if shape in _DOMES and Q is not None and not simplifies_to_zero((Q * _Z)[2]):
        raise NotInPlane(f"a {shape.value}'s axis must lie in the plane of the scene to rock in it "
                         "(for instance 'axis: -y', the dome down)")
    if isinstance(e, Curved) and e.plane_normal is not None:
        n = e.plane_normal.applyfunc(sp.simplify)
        if n[0] != 0 or n[1] != 0:
            raise NotInPlane(f"the {shape.value}'s circle is not in the plane of the scene: its own axis must "
                             "be along z (leave 'axis' out)" if shape in _ROUND_IN_PLANE[:5] else
                             f"the {shape.value} must lie in the plane of the scene (its axis in the xy-plane)")
    if isinstance(e, Flat) and not simplifies_to_zero(e.outward[2]):
        raise NotInPlane(f"the {shape.value}'s flat edge is not across the plane of the scene")
    return e
