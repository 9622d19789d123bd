"""Which force (and moment) a support can exert, read off the kinematics.

An ideal support does no work in any motion the scene allows (d'Alembert's principle):
its force R at P is orthogonal to every velocity the body's material point at P can
have relative to the holder,

    v_rel = v_G + ω × (P − r_G) − (the holder's point there)  =  Σ_j (∂v_rel/∂q̇_j) q̇_j,

so R lies in the orthogonal complement of the columns ∂v_rel/∂q̇_j. In the plane: no
column (a pivot, a joint) leaves R free, two components; one direction (a smooth
guide, a particle on a sphere) leaves a push N along the normal; two independent
directions leave nothing: the point is not held. A moment M about the normal to the
plane appears where the body cannot turn relative to the holder at all (a block on a
smooth plane), except for a particle at its own point.

A rolling contact holds its body's point at rest: a push N along the surface's normal
n and a friction force F along t = e_z × n. A string pulls its drum towards the fixed
point: a tension T along the string.
"""

from __future__ import annotations

import random
from dataclasses import dataclass, replace
from enum import Enum

import sympy as sp

from rbdsolve.form.tidy import tidy
from rbdsolve.form.printers import to_unicode
from rbdsolve.errors import InputError, Location, UnsolvedError
from rbdsolve.model.build import Model, RigidBody
from rbdsolve.model.state import t
from rbdsolve.model.energies.energy import memoized
from rbdsolve.problem.options import Support, SupportKind
from rbdsolve.model.values.values import parameter_sample
from rbdsolve.form.zero import simplifies_to_zero, tidied_sign

_Z = sp.Matrix([0, 0, 1])


class How(Enum):
    """How a support holds its body (one word each: the JSON's answers are names sympy reads)."""

    PIVOT = "pivot"  # the point at rest relative to its holder (a joint when the holder is a body)
    GUIDE = "guide"  # the point moves along one direction only: a push along the normal
    ROLLING = "rolling"  # a rolling contact: a push and friction
    STRING = "string"  # a string: a tension
    BALL_JOINT = "ball_joint"  # a 3D point at rest relative to its holder


@dataclass(frozen=True)
class Component:
    """One unknown of a support: R += symbol · direction (a force), or a moment about e_z."""

    symbol: sp.Symbol
    direction: sp.Matrix  # unit vector, scene axes (a moment: e_z)
    moment: bool = False
    one_sided: bool = False  # a push or a pull: it cannot change sign and hold (N, T)
    friction: bool = False
    # the same unknown on other bodies: (body, point, direction), a string's other end (its drum)
    also: tuple[tuple[str, sp.Matrix, sp.Matrix], ...] = ()


@dataclass(frozen=True)
class Held:
    """One support: at ``point`` (its position), on body ``on`` from ``by`` (None: the
    ground), its unknowns, and how it holds (pivot, guide, contact, string, joint)."""

    name: str
    point: sp.Matrix
    on: str
    by: str | None
    components: tuple[Component, ...]
    how: How
    loc: Location | None = None  # where the question asks for it (bad input points there)
    added: bool = False  # not asked: a string that pulls a body asked about, found with the others


def body(model: Model, name: str) -> RigidBody:
    return next(b for b in model.bodies if b.name == name)


def material_velocity(model: Model, b: RigidBody, P: sp.Matrix) -> sp.Matrix:
    """v of body b's material point at P: v_G + ω × (P − r_G)."""
    return b.velocity(model.state) + b.angular_velocity(model.state).cross(P - b.position)


def planar(model: Model) -> bool:
    """Every body turns about e_z only and moves in the x-y plane, gravity in it too."""
    flat = all(not b.turns_3d and b.position is not None and simplifies_to_zero(b.position[2]) for b in model.bodies)
    return flat and (model.gravity is None or model.gravity[2] == 0)


@memoized
def held(model: Model, support: Support) -> Held:
    """The support's components and directions; found once per model (the exact route
    and the check before printing both ask, and a guide's normal costs a few simplify
    calls)."""
    placed = _contact(model, support) if support.kind is SupportKind.CONTACT else _point(model, support)
    return replace(placed, loc=support.loc)


def _contact(model: Model, support: Support) -> Held:
    return contact_support(model, next(c for c in model.contacts if c.name == support.point))


def contact_support(model: Model, rolling) -> Held:
    """A contact as a support: a rolling contact's push and friction, a string's tension
    (on its drum, and for a hanging body on both: on the body up the string, on the drum
    at C along the string)."""
    name = rolling.name
    if rolling.source.pulley is not None:
        return _hanging(model, rolling)
    if rolling.source.string:
        d = model.symbols.vector(rolling.source.surface.direction)
        u = -(d / sp.sqrt(d.dot(d))).applyfunc(sp.simplify)  # from the drum back to the fixed point
        return Held(name, rolling.point, rolling.body, None,
                    (Component(sp.Symbol(f"T_{name}"), u, one_sided=True),), How.STRING)
    n = rolling.normal
    tangent = _Z.cross(n)
    # on another body's edge (a cylinder on a plank), the same push and friction act back on
    # that body: in its balance where it is held too (the plank on the floor), by Newton's third law
    under = rolling.source.surface.body
    back = (lambda d: ((under, rolling.point, -d),)) if under is not None else (lambda d: ())
    return Held(name, rolling.point, rolling.body, None,
                (Component(sp.Symbol(f"N_{name}"), n, one_sided=True, also=back(n)),
                 Component(sp.Symbol(f"F_{name}"), tangent, friction=True, also=back(tangent))), How.ROLLING)


def _hanging(model: Model, rolling) -> Held:
    """A body on a string from a drum: the tension T pulls the body up the string (along
    −h, h the way the hanging part runs) at the body's origin, where the string is tied,
    and the drum along d, the way the string leaves it, at the tangent point C."""
    p = rolling.source.pulley
    names = model.symbols
    hanging = body(model, rolling.body)
    d = _unit(names.vector(p.direction))
    h = _unit(names.vector(p.down)) if p.over is not None and p.down is not None else (
        sp.Matrix([0, -1, 0]) if p.over is not None else d)
    at = names.vector(hanging.source.at)
    if p.wheel is not None:
        return Held(rolling.name, at, hanging.name, None, _over_wheel(model, rolling, d, h), How.STRING)
    tension = Component(sp.Symbol(f"T_{rolling.name}"), -h, one_sided=True, also=((p.drum, rolling.point, d),))
    return Held(rolling.name, at, hanging.name, None, (tension,), How.STRING)


def _over_wheel(model: Model, rolling, d: sp.Matrix, h: sp.Matrix) -> tuple[Component, Component]:
    """A string over a pulley with mass W (centre c, rim radius R, turned the way the
    string bends, s = sign((d × h)_z)) has a tension on each side, different by what
    turns W: T_S1 off the drum, on the drum at C along d and on W where the string
    reaches its rim, E = c − s R e_z × d, along −d; T_S2 down to the body, on the body up
    the string (−h) and on W where the string leaves it, X = c − s R e_z × h, along h.
    (T_S1 acts on the hanging body with no direction: the body's own balance holds only T_S2.)"""
    from rbdsolve.model.constraints.strings import wheel_bend, wheel_rim  # a scene with a pulley with mass only

    p = rolling.source.pulley
    c = body(model, p.wheel).position
    R = wheel_rim(model.problem.body(p.wheel), model.symbols)
    s = wheel_bend(rolling.source, model.symbols, dict(model.values))
    entry, exit_ = c - s * R * _Z.cross(d), c - s * R * _Z.cross(h)
    off = Component(sp.Symbol(f"T_{rolling.name}1"), sp.zeros(3, 1), one_sided=True,
                    also=((p.drum, rolling.point, d), (p.wheel, entry, -d)))
    down = Component(sp.Symbol(f"T_{rolling.name}2"), -h, one_sided=True, also=((p.wheel, exit_, h),))
    return down, off


def _unit(v: sp.Matrix) -> sp.Matrix:
    return (v / sp.sqrt(tidy(v.dot(v)))).applyfunc(tidy)


def _point(model: Model, support: Support) -> Held:
    P = model.point(support.point)
    on = body(model, support.on)
    v = material_velocity(model, on, P)
    w = on.angular_velocity(model.state)
    if support.by is not None:
        by = body(model, support.by)
        v, w = v - material_velocity(model, by, P), w - by.angular_velocity(model.state)
    if support.by is None:
        _require_material(model, support, on, P, v)
    columns = [v.diff(qd) for qd in model.qd]
    if not planar(model):
        if _rank(columns, model) != 0:
            raise UnsolvedError(f"the force at '{support.point}': only pivots and ball joints (the point at rest "
                                "relative to its holder) are answered in a 3D scene yet")
        return Held(support.point, P, on.name, support.by, _free(support.point, 3), How.BALL_JOINT)
    rank = _rank(columns, model)
    turns = any(not all(simplifies_to_zero(x) for x in w.diff(qd)) for qd in model.qd)
    moment = () if turns or _particle_at(on, P) else (Component(sp.Symbol(f"M_{support.point}"), _Z, moment=True),)
    if rank == 0:
        return Held(support.point, P, on.name, support.by, _free(support.point, 2) + moment, How.PIVOT)
    if rank == 1:
        n = _normal(model, support, next(c for c in columns if c != sp.zeros(3, 1)))
        push = Component(sp.Symbol(f"N_{support.point}"), n, one_sided=support.by is None and not support.two_sided)
        return Held(support.point, P, on.name, support.by, (push,) + moment, How.GUIDE)
    what = f"body '{on.name}'" + (f" relative to body '{support.by}'" if support.by else "")
    raise InputError(f"'{support.point}' is not a support of {what}: its point there moves freely in the plane "
                     f"(v = {to_unicode(model.readable(v.T))}), so nothing holds it there", support.loc)


def _require_material(model: Model, support: Support, on: RigidBody, P: sp.Matrix, v: sp.Matrix) -> None:
    """A support at a point that moves holds the body's own point there: dP/dt must be
    v_G + ω × (P − r_G). Where it is not, the body's angle and its points disagree (a
    ladder's ends at L (sin θ, 0) and (0, L cos θ) with ``angle: -theta``: its ends would
    turn the other way), and every moment about G, so every force, would be wrong. A
    point fixed in space (a peg the body slides over) and a particle are not asked."""
    moves = model.state.d_dt(P)
    if on.inertia == sp.zeros(3, 3) or all(simplifies_to_zero(x) for x in moves):
        return
    if all(simplifies_to_zero(x) for x in moves - v):
        return
    angle = f" (its angle: {to_unicode(model.readable(on.angle))}; the other way round?)" if on.angle is not None else ""
    raise InputError(f"'{support.point}' moves, but not with body '{on.name}'{angle}: dP/dt = "
                     f"{to_unicode(model.readable(model.to_time(moves.T)))}, while the body's point there moves at v_G + ω × (P − r_G) "
                     f"= {to_unicode(model.readable(model.to_time(v.T)))}; the body's angle and its points disagree, so its moments, and "
                     "the forces, would be wrong ('rbdsolve draw' shows the body against its points)", support.loc)


def _free(name: str, dims: int) -> tuple[Component, ...]:
    return tuple(Component(sp.Symbol(f"R_{name}{axis}"), sp.eye(3)[:, k]) for k, axis in enumerate("xyz"[:dims]))


def _particle_at(b: RigidBody, P: sp.Matrix) -> bool:
    return b.inertia == sp.zeros(3, 3) and all(simplifies_to_zero(x) for x in P - b.position)


def generic_point(model: Model, seed: int) -> dict[sp.Symbol, sp.Expr]:
    """The parameters (at their values, else pseudo-random), the coordinates, rates and
    time at pseudo-random rationals: a generic state to test an identity or a rank at."""
    rng = random.Random(seed)
    point = parameter_sample(model, rng)
    point.update({q: sp.Rational(rng.randint(1, 97), 37) for q in (*model.q, *model.qd, t)})
    return point


def _rank(columns: list[sp.Matrix], model: Model) -> int:
    """The rank of the velocity columns at a generic state (two random samples agree)."""
    if not columns:
        return 0
    ranks = []
    for seed in (7, 11):
        matrix = sp.Matrix.hstack(*columns).xreplace(generic_point(model, seed)).evalf(30)
        ranks.append(sp.Matrix(matrix).rank(iszerofunc=lambda x: abs(x) < 1e-20))
    return max(ranks)


def _normal(model: Model, support: Support, column: sp.Matrix) -> sp.Matrix:
    """The unit normal e_z × c/|c|, turned to the given ``normal`` or against gravity at
    the reference configuration (q = 0).

    Where e_z × c is parallel to that direction everywhere (a floor, a wall, an incline
    given its normal), the normal is that direction itself: e_z × c/|c| would hold the
    sign of c (a foot at L (cos φ, 0) slides along −sin φ e_x), which flips where the
    guide's velocity vanishes — at q = 0 for an angle measured from the floor, where no
    sign can be read off."""
    toward = (model.symbols.vector(support.normal) if support.normal is not None
              else -model.gravity if model.gravity is not None else None)
    across = _Z.cross(column)
    if toward is not None and simplifies_to_zero(across.cross(toward).dot(_Z)):
        return _unit(toward)
    c = column.applyfunc(tidy)
    n = (_Z.cross(c) / sp.sqrt(tidy(c.dot(c)))).applyfunc(lambda x: tidy(sp.factor_terms(x)))
    if toward is None:
        return n
    at_zero = {q: 0 for q in model.q}
    sign = tidied_sign(n.dot(toward).xreplace(at_zero), model.decided_by)
    return -n if sign == -1 else n
