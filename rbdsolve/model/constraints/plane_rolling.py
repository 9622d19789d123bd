"""Rolling on a plane in 3D: the contact point of a round body, and why it stays a
constraint.

A body with a **sphere**'s rim (radius ρ, centre E) touches a plane of unit normal n
(towards the body) at C = E − ρ n. A **disk**'s or **ring**'s rim, the circle of radius ρ
about E in the plane normal to the body's axis a, touches it at its point nearest the
plane, the direction in the rim's plane closest to −n:

    C = E − ρ u,   u = (n − (n·a) a)/s,   s = |n − (n·a) a| = √(1 − (n·a)²),

(s ≠ 0: a rim lying flat on the plane does not roll). s is written without absolute
values, √(cos² θ) = cos θ: that is the rim's lowest point while s > 0, so where s is a
constant the model assumes s > 0 (a ring tilted by θ from the vertical: cos θ > 0),
and refuses values that break it.

Rolling without slipping sets the body's point at C at rest, v_G + ω × (C − G) = 0:
three relations between the rates that do not integrate to relations between the
coordinates (a coin can roll back to its place turned), so no coordinate is eliminated.
The contact is kept as a constraint: ``steady_motion`` uses C as it uses a point named
in ``rolling_at``; ``impact`` keeps v_C = 0 along the plane just after, with the plane's
impulse along it unknown (``material_velocity``, ``tangents``); eom, equilibria, modes and
reactions refuse it (problem/sections/questions.py).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Mapping

import sympy as sp

from rbdsolve.errors import InputError
from rbdsolve.form.printers import to_unicode
from rbdsolve.form.tidy import tidy
from rbdsolve.model.assumptions import Assumed
from rbdsolve.model.constraints.contacts import implied
from rbdsolve.model.constraints.edges import body_part, part_edge
from rbdsolve.model.state import t
from rbdsolve.model.symbols import Symbols
from rbdsolve.problem.scene import Contact
from rbdsolve.problem.schema import Problem
from rbdsolve.problem.surfaces import SurfaceKind
from rbdsolve.form.zero import simplifies_to_zero


@dataclass(frozen=True)
class PlaneRolling:
    """A body rolling on a plane: its contact point C(q, t) and the plane's unit normal
    n (towards the body), in scene axes."""

    name: str
    body: str
    point: sp.Matrix
    normal: sp.Matrix
    source: Contact
    requires: tuple[Assumed, ...] = ()  # s > 0 (see the module)


def plane_contacts(problem: Problem, names: Symbols, rotations: Mapping[str, sp.Matrix],
                   values: Mapping[sp.Symbol, sp.Expr]) -> tuple[PlaneRolling, ...]:
    """Each contact on a plane, with its body's rotation (body axes to scene axes)."""
    bodies = {b.name: b for b in problem.bodies}
    return tuple(_contact(c, bodies[c.body], names, rotations[c.body], values)
                 for c in problem.contacts if c.surface.kind is SurfaceKind.PLANE)


def _contact(c: Contact, body, names: Symbols, R: sp.Matrix, values) -> PlaneRolling:
    rim = part_edge(body_part(body, c.part), c.edge, names, planar=False)
    origin = names.vector(body.at)
    origin = origin if origin.rows == 3 else origin.col_join(sp.zeros(1, 1))
    centre = origin + R * rim.centre
    n = names.vector(c.surface.direction)
    n = (n / sp.sqrt(n.dot(n))).applyfunc(sp.radsimp)
    if rim.plane_normal is None:  # a sphere
        return PlaneRolling(c.name, c.body, _touching(c, centre - rim.radius * n, n, names), n, c)
    a = (R * rim.plane_normal).applyfunc(sp.trigsimp)
    across = tidy(n.dot(a))
    square = sp.factor(sp.trigsimp(1 - across**2))
    if square == 0:
        raise InputError(f"contact '{c.name}': the rim of '{c.body}' lies flat on the plane (its axis along the "
                         "plane's normal), so it does not roll on its rim", c.loc)
    s = sp.powdenest(sp.sqrt(square), force=True).replace(sp.Abs, lambda x: x)
    u = (n - across * a) / s
    point = (centre - rim.radius * u).applyfunc(tidy)
    return PlaneRolling(c.name, c.body, _touching(c, point, n, names), n, c, _lowest(c, s, names, values))


def _lowest(c: Contact, s: sp.Expr, names: Symbols, values) -> tuple[Assumed, ...]:
    """s > 0, C the rim's lowest point: refused when the values break it, assumed when
    s is a constant the parameters' signs do not decide (nothing when it moves)."""
    if s.has(t) or s.free_symbols & set(names.state.q) or s.is_positive:
        return ()
    number = s.xreplace(dict(values))
    if number.is_number and not number > 0:
        raise InputError(f"contact '{c.name}': with the values given, {to_unicode(s)} = {to_unicode(number)} is not "
                         f"positive: the rim of '{c.body}' leans past the plane's normal, so the point "
                         "found is its highest, not the one on the plane", c.loc)
    return (implied(c, s, sp.Integer(0), names, f"contact '{c.name}': {c.body} touches the plane with the lowest "
                    "point of its rim"),)


def _touching(c: Contact, point: sp.Matrix, n: sp.Matrix, names: Symbols) -> sp.Matrix:
    """With ``through: P`` given, C must be on the plane: (C − P)·n = 0 for every motion."""
    if c.surface.point is None:
        return point
    P = names.vector(c.surface.point)
    P = P if P.rows == 3 else P.col_join(sp.zeros(1, 1))
    gap = tidy((point - P).dot(n))
    if gap != 0 and not simplifies_to_zero(gap):
        raise InputError(f"contact '{c.name}': body '{c.body}' does not touch the plane: its contact point is "
                         f"{to_unicode(gap)} from it along the normal", c.surface.loc)
    return point


def tangents(n: sp.Matrix) -> tuple[sp.Matrix, sp.Matrix]:
    """Two unit vectors across the unit normal n, t₁ × t₂ = n: t₁ from the scene axis
    least along n (x for a table, n = z), with its part along n taken out."""
    axis = min((sp.eye(3)[:, k] for k in range(3)), key=lambda e: abs(float(e.dot(n))))
    t1 = axis - axis.dot(n) * n
    t1 = (t1 / sp.sqrt(t1.dot(t1))).applyfunc(sp.radsimp)
    return t1, n.cross(t1).applyfunc(sp.radsimp)


def material_velocity(contact: PlaneRolling, body, state) -> sp.Matrix:
    """The velocity of the body's material point at C, v_G + ω × (C − G) (not dC/dt:
    C moves round the rim as the body rolls)."""
    return body.velocity(state) + body.angular_velocity(state).cross(contact.point - body.position)
