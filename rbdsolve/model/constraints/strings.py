"""A body hanging on a string from a drum, over a pulley (light, or with mass).

The string is wound on the drum's round edge (centre E, radius ρ) and leaves it at the
tangent point C along the constant unit direction d, straight to the pulley at P, over
it, and down along h to the hanging body. The drum's point at C and the string there
move together (no slip on the drum); the straight part is inextensible, so every point
of it moves along d at the same speed, and the light pulley passes that speed on:

    ℓ̇ = v_C · d,    v_C = dE/dt + φ̇ e_z × (C − E),

the rate at which the hanging part lengthens (φ the drum's angle). For a drum placed by
planar rolling v_C · d = Σ aᵢ q̇ᵢ with constant aᵢ (a cylinder rolling on the floor, the
string off its top: v_C = 2ẋ), so ℓ = Σ aᵢ qᵢ from the reference, and the body hangs at
P + (ℓ₀ + ℓ) h. C is the side of the drum from which the line along d passes through P;
the string keeps its direction only if (P − C)·n stays 0 (n = e_z × d) as the scene
moves, which is checked: a string whose straight part would turn is refused.

A pulley with mass (a body of its own on a fixed axle at its centre) is turned by the
string without slipping: its rim moves at the string's speed, so its angle is ψ = ±ℓ/R
(R its rim's radius, the sign the way the string bends over it, ``wheel_turn``), and it
adds ½ J ψ̇² to T; the string's geometry is the light pulley's (P the point where it
reaches the rim, the body hanging along h from P).

Without a pulley the body hangs straight from the drum's rim along d, from the tangent
point C on the side the file names; C moves with the drum's centre (not with its
material), so the hanging part lengthens at ℓ̇ = (v_C − Ċ)·d, and the body is at
C + (ℓ₀ + ℓ) d (an Atwood machine: two bodies on the two sides of one pulley).
"""

from __future__ import annotations

import sympy as sp

from rbdsolve.form.tidy import tidy
from rbdsolve.errors import InputError
from rbdsolve.model.constraints.edges import Curved
from rbdsolve.model.state import t, user_function
from rbdsolve.model.symbols import Symbols
from rbdsolve.problem.scene import Contact
from rbdsolve.problem.schema import Body
from rbdsolve.form.zero import settled, simplifies_to_zero, tidied_sign

_Z = sp.Matrix([0, 0, 1])


def hang(c: Contact, drum: Body, e: Curved, names: Symbols, values: dict | None = None):
    """(the hanging body's origin, the record for the report: the point C, ℓ̇ = v_C·d
    and ℓ as the drum's coordinates give it, and ℓ in the coordinates)."""
    p = c.pulley
    origin = _vector3(names.vector(drum.at)) if drum.at is not None else sp.zeros(3, 1)
    phi = names.scalar(drum.angle) if drum.angle is not None else sp.Integer(0)
    centre = origin + sp.rot_axis3(-phi) * e.centre
    d = _unit(names.vector(p.direction))
    state = names.state
    if p.over is None:  # straight from the drum: the string's top, C, moves with the drum's centre
        C = _side_point(c, centre, e.radius, d, values or {})
        top = state.d_dt(C)
    else:
        over = _vector3(names.vector(p.over))
        C, top = _tangent_point(c, centre, e.radius, d, over, names), sp.zeros(3, 1)
    v_C = state.d_dt(centre) + state.d_dt(phi) * _Z.cross(C - centre)
    rate = sp.expand(sp.trigsimp(sp.expand((v_C - top).dot(d))))
    coefficients = [settled(sp.cancel(tidy(rate.coeff(qd))), state.q) for qd in state.qd]
    if any(a.has(*state.q) for a in coefficients) or rate.has(t):
        raise InputError(f"contact '{c.name}': the string's speed off '{drum.name}' ({sp.sstr(rate)}) does not "
                         "integrate to a length; the drum must roll or turn at constant rates' ratios", p.loc)
    if all(a == 0 for a in coefficients):
        raise InputError(f"contact '{c.name}': drum '{drum.name}' does not move (its place and angle depend on no "
                         f"coordinate), so '{c.body}' would hang still: no degree of freedom is left for the "
                         "string; give the drum a coordinate or a contact", p.loc)
    paid = sum((a * q for a, q in zip(coefficients, state.q)), sp.Integer(0))
    lengthening = user_function(f"l_{c.name}")(t)
    record = (C, sp.Derivative(lengthening, t), state.to_time(rate), lengthening, state.to_time(paid))
    if p.over is None:
        start = names.scalar(p.length) if p.length is not None else sp.Integer(0)
        return C + (start + paid) * d, record, paid
    down = _down(p, names)
    start = names.scalar(p.length) if p.length is not None else _distance(over, C, names)
    return over + (start + paid) * down, record, paid


def wheel_turn(c: Contact, radius: sp.Expr, paid: sp.Expr, names: Symbols, values: dict) -> sp.Expr:
    """The angle of a pulley with mass that the string turns without slipping: its rim
    moves with the string, ℓ̇ = R ψ̇ in magnitude, turning the way the string bends
    over it, from d (off the drum) towards h (down to the body): ψ = sign((d × h)_z) ℓ/R
    (a string off a cylinder's top to the right, then down: clockwise, ψ = −ℓ/R)."""
    return wheel_bend(c, names, values) * paid / radius


def wheel_bend(c: Contact, names: Symbols, values: dict) -> sp.Expr:
    """The way the string bends over a pulley with mass, from d (off the drum) to h
    (down to the body): sign((d × h)_z), 1 counterclockwise; refused where it does not
    bend (d ∥ h) or the parameters' signs leave it open."""
    d = _unit(names.vector(c.pulley.direction))
    bend = tidy(d.cross(_down(c.pulley, names))[2])
    if simplifies_to_zero(bend):
        raise InputError(f"contact '{c.name}': the string does not bend over pulley '{c.pulley.wheel}' (it leaves the "
                         f"drum along {sp.sstr(list(d[:2]))} and runs on along the same line): give 'down' across "
                         "'direction'", c.pulley.wheel_loc)
    sign = tidied_sign(bend, values)
    if not sign.is_number or sign == 0:
        raise InputError(f"contact '{c.name}': which way pulley '{c.pulley.wheel}' turns depends on the sign of "
                         f"{sp.sstr(bend)}: give the parameters in it values", c.pulley.wheel_loc)
    return sign


def wheel_rim(wheel: Body, names: Symbols) -> sp.Expr:
    """The radius of a pulley's rim (a disk, ring or cylinder of one shape)."""
    from rbdsolve.model.constraints.edges import body_part, part_edge

    return part_edge(body_part(wheel, None), "rim", names).radius


def _down(p, names: Symbols) -> sp.Matrix:
    """h, the way the string runs after the pulley (straight down by default)."""
    return _unit(names.vector(p.down)) if p.down is not None else sp.Matrix([0, -1, 0])


_SIDES = {"below": (0, -1, 0), "above": (0, 1, 0), "left": (-1, 0, 0), "right": (1, 0, 0)}


def _side_point(c: Contact, centre: sp.Matrix, rho, d: sp.Matrix, values: dict) -> sp.Matrix:
    """C = E ± ρ n (n = e_z × d) on the drum's side the file names, as drawn: the one
    with n·e > 0 for that side's direction e (left: −e_x), a sign the values decide
    where the direction holds parameters."""
    side = c.pulley.side
    across = tidy(_Z.cross(d).dot(sp.Matrix(_SIDES[side])))
    if simplifies_to_zero(across):
        raise InputError(f"contact '{c.name}': a string running along {sp.sstr(list(d[:2]))} leaves the drum on "
                         f"its {'left or right' if side in ('above', 'below') else 'top or bottom'}, not "
                         f"{side} it: name the side across the string", c.pulley.loc)
    sign = tidied_sign(across, values)
    if not sign.is_number or sign == 0:
        raise InputError(f"contact '{c.name}': which side of the drum is '{side}' for a string along "
                         f"{sp.sstr(list(d[:2]))} depends on the sign of {sp.sstr(across)}: give the parameters in "
                         "it values", c.pulley.loc)
    return centre + sign * rho * _Z.cross(d)


def _tangent_point(c: Contact, centre, rho, d, over, names: Symbols) -> sp.Matrix:
    """C = E ± ρ n on the side from which the line along d reaches P (at the reference
    configuration, ahead of C), and stays through P as the scene moves."""
    n = _Z.cross(d)
    reference = {q: 0 for q in names.state.q}
    for sign in (1, -1):
        C = centre + sign * rho * n
        across = tidy((over - C).dot(n))
        if not simplifies_to_zero(across.xreplace(reference)):
            continue
        if tidied_sign((over - C).dot(d).xreplace(reference)) == -1:
            continue
        if not simplifies_to_zero(across):
            raise InputError(f"contact '{c.name}': the string from '{c.pulley.drum}' to the pulley does not keep its "
                             f"direction as the scene moves ((P − C)·n = {sp.sstr(across)}, not 0): a straight "
                             "part that turns is not supported", c.pulley.loc)
        return C
    raise InputError(f"contact '{c.name}': the string leaving '{c.pulley.drum}' along the direction given does not "
                     "pass through the pulley's point 'over' at the reference configuration (all coordinates 0): "
                     "it must leave the drum tangentially, straight towards that point", c.pulley.loc)


def _distance(a: sp.Matrix, b: sp.Matrix, names: Symbols) -> sp.Expr:
    reference = {q: 0 for q in names.state.q}
    gap = (a - b).xreplace(reference)
    return sp.sqrt(tidy(gap.dot(gap)))


def _unit(v: sp.Matrix) -> sp.Matrix:
    v = _vector3(v)
    return (v / sp.sqrt(v.dot(v))).applyfunc(lambda x: sp.radsimp(sp.trigsimp(x)))


def _vector3(v: sp.Matrix) -> sp.Matrix:
    return v if v.rows == 3 else v.col_join(sp.zeros(3 - v.rows, 1))
