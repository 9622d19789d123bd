"""Rolling contacts: the contact point, the rolling condition v_C = 0, and the body's
place and angle that follow from it.

A body with a **curved edge** (centre E, radius ρ) touching a surface at C, with n the
surface's unit normal towards the body, has its edge's centre at C + ρ n: the body's
origin is O = C + ρ n − R(φ) E for the body's angle φ. Its material point at C moves at

    v_C = dO/dt + φ̇ e_z × (C − O),

normal to the surface by construction; rolling without slipping sets its component along
the surface's unit tangent to zero (relative to the surface, when the surface translates
with a moving point). That is linear in the two rates, a σ̇ + b φ̇ = 0, with σ the
contact's travel (a distance along a line, the angle round a circle). For a line and a
circle a/b is a constant (ρ φ̇ = −σ̇ on a line, ρ φ̇ = −(R − ρ) σ̇ inside a circle of
radius R, ρ φ̇ = (R + ρ) σ̇ outside), so the relation integrates to φ = −(a/b) σ from
the reference configuration (σ = 0, φ = 0), and only one of the two is a coordinate.

A body with a **flat edge** on a circle (a slab on a drum) stays tangent to it, so its
angle is the contact's angle round the circle, φ = σ; its origin is
O = C − R(φ)(F + λ k), with λ the contact's place along the edge (k its direction), and
rolling gives λ̇ = −(a/c) φ̇, constant again (λ = −R φ on a drum of radius R).

A string wound on a drum and held at a fixed point is a straight line the drum rolls on
(its point at C is at rest), at the winding radius.

What is derived here is written back into the Problem as each body's ``at`` and
``angle`` (expression trees), so every route — symbolic, numeric, the drawings — sees
the rolling body as an ordinary placed one.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import sympy as sp

from rbdsolve.form.printers import to_unicode
from rbdsolve.errors import InputError
from rbdsolve.model.assumptions import Assumed
from rbdsolve.model.constraints.edges import Curved, Flat, NotInPlane, body_part, part_edge
from rbdsolve.model.constraints.lengths import contact_lengths
from rbdsolve.model.state import t, user_function
from rbdsolve.model.constraints.strings import hang, wheel_rim, wheel_turn
from rbdsolve.model.symbols import Symbols, exact_number
from rbdsolve.model.trees import as_expr, reverse_names
from rbdsolve.problem.sections.contacts import NOT_PLANAR
from rbdsolve.problem.scene import Assumption, Contact
from rbdsolve.problem.schema import Body, Problem
from rbdsolve.problem.surfaces import Measure, SurfaceKind
from rbdsolve.form.tidy import tidy
from rbdsolve.form.zero import settled, simplifies_to_zero

_Z = sp.Matrix([0, 0, 1])


@dataclass(frozen=True)
class Rolling:
    """One contact's kinematics: the contact point C(q) and the rolling condition
    ``lhs = rhs`` between the rates (functions of time, for the solution's step), and
    what it integrates to, ``dependent = integrated``."""

    name: str
    body: str
    point: sp.Matrix
    lhs: sp.Expr
    rhs: sp.Expr
    dependent: sp.Expr
    integrated: sp.Expr
    moving_surface: bool
    source: Contact
    span: tuple[sp.Expr, sp.Expr] | None = None  # C stays on the body's edge while `measured` is between these
    coordinate: sp.Symbol | None = None  # the contact's coordinate q
    measured: sp.Expr | None = None  # what the span bounds: q, or q − β on a turning body's edge
    normal: sp.Matrix | None = None  # the surface's unit normal at C, towards the body (for its push N)
    requires: tuple[Assumed, ...] = ()  # what the geometry needs of the parameters (R > r inside a circle)


@dataclass(frozen=True)
class _Surface:
    point: sp.Matrix  # C(σ)
    normal: sp.Matrix  # n(σ), towards the body
    tangent: sp.Matrix  # unit dC/dσ direction
    radius: sp.Expr | None  # a circle's
    inside: bool
    moving: bool


@dataclass(frozen=True)
class _Placing:
    """How a contact's coordinate enters: the placement is derived in a stand-in ``w``
    (the coordinate relative to the surface), then w = ``relative`` (q, or q − β on a
    turning body's edge) and the ``frame`` carries it into the scene."""

    w: sp.Symbol
    relative: sp.Expr
    frame: "_Frame | None"
    q: sp.Symbol


@dataclass(frozen=True)
class _Frame:
    """The body a contact rolls on: its origin O_B(q) and angle β(q). Relative to it the
    surface is fixed, so the rolling body is placed in its axes as on a fixed surface and
    carried along: O = O_B + R(β) O_rel, φ = β + φ_rel."""

    origin: sp.Matrix
    angle: sp.Expr

    def carry(self, v: sp.Matrix) -> sp.Matrix:
        return self.origin + sp.rot_axis3(-self.angle) * v


def place_contacts(problem: Problem, names: Symbols) -> tuple[Problem, tuple[Rolling, ...]]:
    """The problem with each rolling body placed (``at``, ``angle``), and the contacts."""
    if not problem.contacts:
        return problem, ()
    bodies = {b.name: b for b in problem.bodies}
    values = {names.parameters[k]: exact_number(v) for k, v in problem.values}
    placed, rollings = {}, []
    reverse = reverse_names(names)
    for contact in problem.contacts:
        if contact.surface.kind is SurfaceKind.PLANE:  # in 3D, placed by the body's own turns: model/constraints/plane_rolling.py
            continue
        lengths = tuple(implied(contact, v, sp.Integer(0), names, why) for v, why in contact_lengths(contact, problem, names))
        body = bodies[contact.body]
        if contact.pulley is not None:  # the drum is placed already (problem/sections/contacts.py checks the order)
            origin, rolling, paid = _hanging(contact, placed.get(contact.pulley.drum, bodies[contact.pulley.drum]),
                                             names, values)
            placed[body.name] = replace(body, at=as_expr(origin, reverse, names, contact))
            rollings.append(replace(rolling, requires=lengths + rolling.requires))
            if contact.pulley.wheel is not None:
                wheel = placed.get(contact.pulley.wheel, bodies[contact.pulley.wheel])
                turn = _wheel_angle(contact, wheel, paid, names, values)
                placed[wheel.name] = replace(wheel, angle=as_expr(turn, reverse, names, contact))
            continue
        under = placed.get(contact.surface.body, bodies.get(contact.surface.body))  # the body rolled on, if any
        frame = _frame(contact, under, names)
        origin, angle, rolling = _contact(contact, body, names, values, frame, under)
        placed[body.name] = replace(body, at=as_expr(origin, reverse, names, contact),
                                    angle=as_expr(angle, reverse, names, contact))
        rollings.append(replace(rolling, requires=lengths + rolling.requires))
    return replace(problem, bodies=tuple(placed.get(b.name, b) for b in problem.bodies)), tuple(rollings)


def _frame(c: Contact, surface_body: Body | None, names: Symbols) -> _Frame | None:
    """The placement of the body contact ``c`` rolls on (None: a fixed or translating
    line or circle), placed already by 'at'/'angle' or an earlier contact (the reader
    checks the order)."""
    if c.surface.kind is not SurfaceKind.BODY:
        return None
    if surface_body.orientation:
        raise InputError(f"contact '{c.name}': body '{surface_body.name}' turns in 3D ('orientation'); a contact "
                         "rolls on a body that moves in the plane of the scene", c.surface.loc)
    origin = names.vector(surface_body.at) if surface_body.at is not None else sp.zeros(3, 1)
    angle = names.scalar(surface_body.angle) if surface_body.angle is not None else sp.Integer(0)
    return _Frame(origin if origin.rows == 3 else origin.col_join(sp.zeros(1, 1)), angle)


def _own_coordinate(c: Contact, q: sp.Symbol, s: _Surface, sigma, frame: _Frame | None) -> None:
    """The contact's coordinate measures the body's motion relative to the surface; if
    the surface itself moves with it, that relative motion is tied to the surface's (a
    relation no contact imposes) and the body has no degree of freedom of its own."""
    moves = s.point.xreplace({sigma: 0}).has(q) or (frame is not None and (frame.origin.has(q) or frame.angle.has(q)))
    if moves:
        what = f"'{c.surface.body}'" if c.surface.body else "the surface"
        raise InputError(f"contact '{c.name}' is measured by '{c.coordinate}', which also moves {what} it rolls on: "
                         f"that over-constrains the scene (the body would have no motion of its own on {what}); "
                         "give the contact a coordinate of its own", c.loc)


def _hanging(c: Contact, drum: Body, names: Symbols, values: dict) -> tuple[sp.Matrix, Rolling, sp.Expr]:
    """A body on a string from a drum over a pulley, or straight from it
    (model/constraints/strings.py), and ℓ, the string's travel, in the coordinates."""
    e = _geometry(c, drum, c.pulley.part, names, c.edge, names.scalar(c.radius) if c.radius is not None else None)
    origin, (point, lhs, rhs, dependent, integrated), paid = hang(c, drum, e, names, values)
    return origin, Rolling(c.name, c.body, point.applyfunc(tidy), lhs, rhs, dependent, integrated, False, c,
                           requires=_wound(c, drum, names)), paid


def _wheel_angle(c: Contact, wheel: Body, paid: sp.Expr, names: Symbols, values: dict) -> sp.Expr:
    """The angle of the pulley with mass the string turns (``wheel_turn``), from its rim;
    its centre does not move (its axle is fixed)."""
    if any(names.vector(wheel.at).has(q) for q in names.state.q):
        raise InputError(f"contact '{c.name}': pulley '{wheel.name}' turns on a fixed axle, but its centre 'at' "
                         "moves with the coordinates", c.pulley.wheel_loc)
    return wheel_turn(c, wheel_rim(wheel, names), paid, names, values)


def _geometry(c: Contact, body: Body, part: str | None, names: Symbols, edge_name: str, radius=None):
    """The edge of ``body``'s ``part`` that touches, in body axes from its origin."""
    try:
        return part_edge(body_part(body, part), edge_name, names, radius)
    except NotInPlane as exc:
        raise InputError(f"contact '{c.name}': {exc}; a planar contact rolls in the xy-plane of the scene (rolling "
                         "in 3D is not integrable: roll on a plane, 'rolls_on: {plane: {normal: z}}', with the body "
                         "placed by its 'at' and 'orientation'; steady_motion keeps it as a constraint, eom, "
                         "equilibria and modes cannot take it)", c.loc) from None


def _contact(c: Contact, body: Body, names: Symbols, values: dict, frame: _Frame | None, under: Body | None):
    """(origin, angle, Rolling) of the body placed by contact ``c``."""
    geometry = _geometry(c, body, c.part, names, c.edge, names.scalar(c.radius) if c.radius is not None else None)
    sigma = sp.Dummy("sigma", real=True)
    surface = _surface(c, names, sigma, under)
    q = names.coordinates[c.coordinate]
    _own_coordinate(c, q, surface, sigma, frame)
    # the coordinate relative to the body rolled on: a turn, or an angle round its rim, less β
    relative = q - frame.angle if frame is not None and not (
        isinstance(geometry, Curved) and c.measure is Measure.ALONG and surface.radius is None) else q
    how = _Placing(sp.Dummy("w", real=True), relative, frame, q)
    if isinstance(geometry, Flat):
        return _flat(c, geometry, surface, sigma, how, names)
    placed, angle, rolling = _curved(c, geometry, surface, sigma, how, names, values)
    return placed, angle, replace(rolling, requires=rolling.requires + _wound(c, body, names))


def _surface(c: Contact, names: Symbols, sigma: sp.Symbol, under: Body | None) -> _Surface:
    """The surface as C(σ), its normal and tangent; a body's edge in that body's axes."""
    s = c.surface
    if s.kind is SurfaceKind.BODY:
        return _body_edge(c, under, names, sigma)
    base = names.vector(s.point)
    moving = bool(base.free_symbols & set(names.state.q)) or base.has(t)
    if s.kind is SurfaceKind.LINE:
        d = names.vector(s.direction)
        if d.rows == 3 and not simplifies_to_zero(d[2]):
            raise InputError(f"contact '{c.name}': " + NOT_PLANAR.format(what="a line out of the xy-plane"), s.loc)
        return _line(base, d / sp.sqrt(d.dot(d)), s.inside, sigma, moving)
    return _circle(base, names.scalar(s.radius), s.inside, sigma, moving)


def _line(base, tangent, right: bool, sigma, moving: bool) -> _Surface:
    tangent = tangent.applyfunc(lambda x: sp.radsimp(sp.trigsimp(x)))
    normal = _turn(tangent) * (-1 if right else 1)
    return _Surface(base + sigma * tangent, normal, tangent, None, False, moving)


def _circle(base, R, inside: bool, sigma, moving: bool) -> _Surface:
    """σ counterclockwise from the lowest point inside, the top outside."""
    u0 = sp.Matrix([0, -1, 0]) if inside else sp.Matrix([0, 1, 0])
    u = sp.rot_axis3(-sigma) * u0
    return _Surface(base + R * u, -u if inside else u, _turn(u), R, inside, moving)


def _body_edge(c: Contact, body: Body, names: Symbols, sigma) -> _Surface:
    """Another body's edge in its own axes: a rim is a circle, a flat edge a line along
    −e_z × n (so that the body rolling on it is on its outer side)."""
    s = c.surface
    e = _geometry(c, body, s.part, names, s.edge, names.scalar(s.radius) if s.radius is not None else None)
    if isinstance(e, Flat):
        return _line(e.point, -_turn(e.outward), False, sigma, True)
    if e.arc is not None:
        raise InputError(f"contact '{c.name}': rolling on a curved edge of limited extent ('{s.edge}' of "
                         f"'{s.body}') is not supported; roll on a whole rim or a flat edge", s.loc)
    return _circle(e.centre, e.radius, s.inside, sigma, True)


def _turn(v: sp.Matrix) -> sp.Matrix:
    """e_z × v: v turned a quarter turn counterclockwise."""
    return _Z.cross(v)


def _curved(c: Contact, e: Curved, s: _Surface, sigma, how: _Placing, names: Symbols, values: dict):
    """Placement and rolling of a curved edge (see the module docstring)."""
    rho = e.radius
    _check_fits(c, rho, s, values)
    requires = _fits(c, rho, s, names)
    _check_touches(c, e, s, sigma)
    phi = sp.Dummy("phi", real=True)
    R = sp.rot_axis3(-phi)
    origin = s.point + rho * s.normal - R * e.centre
    a, b = _rates(origin, s.point, s.tangent, phi, {sigma: 1, phi: 0}, {sigma: 0, phi: 1})
    ratio = _constant(c, _ratio(a, b), (sigma, phi))  # φ̇ = ratio σ̇
    w = how.w
    if c.measure is Measure.ALONG:
        at = {sigma: w, phi: ratio * w}
        dependent, coefficient = _angle_name(c), (b, a)
    else:
        at = {phi: w, sigma: w / ratio}
        dependent, coefficient = _travel_name(c, s), (a, b)
    span = _arc_span(e, s, at[phi], {sigma: at[sigma]}, w)
    placed, angle, rolling = _result(c, origin, at, phi, s.point.subs(sigma, at[sigma]), dependent, coefficient,
                                     names, s.moving, how, span, s.normal.subs(sigma, at[sigma]))
    return placed, angle, replace(rolling, requires=requires)


def _flat(c: Contact, e: Flat, s: _Surface, sigma, how: _Placing, names: Symbols):
    """A flat edge on a circle: φ = σ, and the contact's place λ along the edge."""
    if s.radius is None:
        raise InputError(f"contact '{c.name}': a flat edge on a straight line does not roll (it slides or "
                         "rests); give the body a curved edge, or roll it on a circle", c.loc)
    if s.inside:
        raise InputError(f"contact '{c.name}': a flat edge cannot roll on the inside of a circle", c.loc)
    if not all(simplifies_to_zero(x) for x in e.outward + s.normal.subs(sigma, 0)):
        raise InputError(f"contact '{c.name}': body '{c.body}' does not touch the circle at the reference "
                         f"configuration ({c.coordinate} = 0): its '{c.edge}' edge does not face the top of the "
                         "circle there", c.loc)
    lam, phi = sp.Dummy("lambda", real=True), sp.Dummy("phi", real=True)
    k = _turn(e.outward)
    origin = (s.point - sp.rot_axis3(-phi) * (e.point + lam * k)).subs(sigma, phi)
    point = s.point.subs(sigma, phi)
    tangent = s.tangent.subs(sigma, phi)
    a, b = _rates(origin, point, tangent, phi, {phi: 1, lam: 0}, {phi: 0, lam: 1})
    ratio = _constant(c, _ratio(a, b), (phi, lam))  # λ̇ = ratio φ̇
    at = {phi: how.w, lam: ratio * how.w}
    dependent = user_function(f"s_{c.name}")(t)
    span = (-e.half_length / ratio, e.half_length / ratio)  # |λ| ≤ half length, λ = ratio·w
    return _result(c, origin, at, phi, point.subs(phi, how.w), dependent, (b, a), names, s.moving, how, span,
                   s.normal.subs(sigma, how.w))


def _rates(origin, point, tangent, phi, first: dict, second: dict) -> tuple[sp.Expr, sp.Expr]:
    """The coefficients (a, b) of v_C · t = a ẋ₁ + b ẋ₂, v_C = dO/dt + φ̇ e_z × (C − O),
    with the two rates given as weights on the placement's unknowns."""
    rates = [sp.Dummy("r1"), sp.Dummy("r2")]
    velocity = sp.zeros(3, 1)
    for rate, weights in zip(rates, (first, second)):
        velocity += rate * sum((origin.diff(x) * w for x, w in weights.items()), sp.zeros(3, 1))
        velocity += rate * weights.get(phi, 0) * _Z.cross(point - origin)
    along = sp.expand(sp.trigsimp(sp.expand(velocity.dot(tangent))))
    return along.coeff(rates[0]), along.coeff(rates[1])


def _ratio(a: sp.Expr, b: sp.Expr) -> sp.Expr:
    """−a/b of the rolling relation a ẋ₁ + b ẋ₂ = 0, a ratio of the radii for a line or a
    circle ((R − r)/r inside a circle): tidied (sin² + cos² = 1) and factored, not run
    through ``simplify``, whose first call in a process costs ~0.1 s of imports (sympy
    loads its physical units to see whether the expression holds one)."""
    return sp.factor(tidy(-a / b))


def _constant(c: Contact, ratio: sp.Expr, unknowns) -> sp.Expr:
    ratio = settled(ratio, unknowns)
    if ratio.has(*unknowns) or ratio.has(sp.nan, sp.zoo):
        raise InputError(f"contact '{c.name}': this edge and surface give a rolling relation that does not "
                         "integrate (not a line or circle on a line or circle)", c.loc)
    return ratio


def _result(c, origin, at, phi, point, dependent, coefficient, names, moving, how: _Placing, span=None,
            normal=None):
    """The body's origin and angle in the coordinate, and the Rolling record: the
    relation coefficient[0]·ḋ = −coefficient[1]·ẇ between the rates relative to the
    surface, integrated from the reference, the span of w where C stays on the edge, and
    the surface's unit normal at C (towards the body: the direction of its push N)."""
    w, frame = how.w, how.frame
    placed = origin.subs(at).xreplace({w: how.relative})
    angle = sp.sympify(at[phi]).xreplace({w: how.relative})
    point = point.xreplace({w: how.relative})
    normal = normal.xreplace({w: how.relative}) if normal is not None else None
    if frame is not None:
        placed, point, angle = frame.carry(placed), frame.carry(point), frame.angle + angle
        normal = sp.rot_axis3(-frame.angle) * normal if normal is not None else None
    turning = frame is not None and dependent.func.__name__.startswith("phi_")  # φ relative to the frame
    offset = names.state.to_time(frame.angle) if turning else sp.Integer(0)
    w_t = _difference(names.state.to_time(how.relative))
    first, second = sp.factor(coefficient[0]), sp.factor(coefficient[1])
    if first.could_extract_minus_sign():  # r φ̇ = …, not −r φ̇ = …
        first, second = -first, -second
    lhs = first * _rate(dependent - offset)
    rhs = _negated(second, _rate(w_t))
    num, den = sp.fraction(sp.factor(-second / first))
    sign = -1 if num.could_extract_minus_sign() else 1  # −(R − r) θ/r, (R + r)(θ − ψ)/r
    num = sign * num
    integrated = (sign * sp.Mul(num, w_t, sp.Pow(den, -1), evaluate=False) if isinstance(num, sp.Add)
                  or isinstance(w_t, sp.Add) else sign * num * w_t / den)
    integrated = sp.Add(offset, integrated, evaluate=False) if offset != 0 else integrated
    # tidy (sin² + cos² = 1 and the angle-sum folds), not simplify: the same forms here, at
    # a tenth of simplify's 40-120 ms an entry
    return (placed.applyfunc(tidy), angle, Rolling(
        c.name, c.body, point.applyfunc(tidy), lhs, rhs, dependent, integrated, moving or frame is not None,
        c, span, how.q, how.relative, normal.applyfunc(tidy) if normal is not None else None))


def _difference(x: sp.Expr) -> sp.Expr:
    """θ − ψ written in that order (the coordinate first, the turn of the body rolled on after)."""
    if not isinstance(x, sp.Add):
        return x
    plus = [a for a in x.args if not a.could_extract_minus_sign()]
    minus = [a for a in x.args if a.could_extract_minus_sign()]
    return sp.Add(*plus, *minus, evaluate=False)


def _rate(x: sp.Expr) -> sp.Expr:
    """ẋ: a coordinate's Derivative, or the sum of them (φ̇ − ψ̇)."""
    if not isinstance(x, sp.Add):
        return sp.Derivative(x, t)
    return _difference(sp.Add(*(sp.diff(a, t) for a in x.args)))


def _arc_span(e: Curved, s: _Surface, angle: sp.Expr, travel: dict, q) -> tuple[sp.Expr, sp.Expr] | None:
    """Where C stays on an arc (middle direction u, half angle β): the edge's point facing
    the surface, in body axes, is d(q) = R(φ)ᵀ(−n(σ)); it turns at a constant rate κ
    relative to the body (φ and σ are linear in q), d(q) = R(κ q) d₀. With δ the angle
    from u to d₀ (|δ| ≤ β, C on the arc at the reference), d is on the arc while
    −β ≤ κ q + δ ≤ β: the span is q between (−β − δ)/κ and (β − δ)/κ, the piece
    through q = 0 (the way the body rocks there). None: a whole circle."""
    if e.arc is None:
        return None
    middle, half = e.arc
    facing = (sp.rot_axis3(angle) * -s.normal.subs(travel)).applyfunc(tidy)
    d0 = facing.subs(q, 0).applyfunc(tidy)
    kappa = sp.cancel(tidy(_turn(d0).dot(facing.diff(q).subs(q, 0))))
    if simplifies_to_zero(kappa):
        return None
    delta = sp.atan2(tidy(middle.cross(d0)[2]), tidy(middle.dot(d0)))
    return (sp.cancel((-half - delta) / kappa), sp.cancel((half - delta) / kappa))


def _negated(coefficient: sp.Expr, rate: sp.Expr) -> sp.Expr:
    """−c·rate as an exam writes it: −(R − r) θ̇, not (−R + r) θ̇."""
    if coefficient.could_extract_minus_sign():
        return sp.Mul(-coefficient, rate, evaluate=False) if isinstance(rate, sp.Add) else -coefficient * rate
    if not isinstance(coefficient, sp.Add) and not isinstance(rate, sp.Add):
        return -coefficient * rate
    return sp.Mul(-1, coefficient, rate, evaluate=False)


def _angle_name(c: Contact) -> sp.Expr:
    return user_function(f"phi_{c.body}")(t)


def _travel_name(c: Contact, s: _Surface) -> sp.Expr:
    return user_function(f"{'psi' if s.radius is not None else 's'}_{c.name}")(t)


def _check_fits(c: Contact, rho: sp.Expr, s: _Surface, values: dict) -> None:
    """Inside a circle the body's edge must be smaller than the circle (as far as the
    parameters' signs and the file's values tell)."""
    if s.radius is None or not s.inside:
        return
    room = s.radius - rho
    at_values = room.xreplace(values)
    if room.is_nonpositive or (at_values.is_number and at_values <= 0):
        raise InputError(f"contact '{c.name}': body '{c.body}' (radius {to_unicode(rho)}) cannot roll inside a "
                         f"circle of radius {to_unicode(s.radius)}: the circle must be the larger", c.loc)


def _fits(c: Contact, rho: sp.Expr, s: _Surface, names: Symbols) -> tuple[Assumed, ...]:
    """Rolling inside a circle of radius R needs R > ρ (the body fits, and its centre
    moves on the circle of radius R − ρ about the centre): the model assumes it, so that
    signs decided later (stability, a mode's kind) never list the impossible ρ > R. Nothing
    when the parameters' signs already decide it, or when both are numbers (checked above)."""
    if s.radius is None or not s.inside:
        return ()
    room = sp.expand(s.radius - rho)
    if not room.free_symbols or room.is_positive:
        return ()
    return (implied(c, s.radius, rho, names, f"contact '{c.name}': {c.body} rolls inside the circle"),)


def _wound(c: Contact, drum: Body, names: Symbols) -> tuple[Assumed, ...]:
    """A string wound at its own radius b on a drum of rim radius R lies on the drum:
    R ≥ b (so does the axle a body rolls on at its ``radius``). Refused when the numbers
    break it; assumed when the signs do not decide it."""
    if c.radius is None:
        return ()
    dims = {k: names.scalar(v) for k, v in body_part(drum, c.pulley.part if c.pulley else c.part).dimensions}
    rim = dims.get("outer_radius", dims.get("radius"))
    if rim is None:
        return ()
    b = names.scalar(c.radius)
    room = sp.expand(rim - b)
    wound = "the string is wound" if c.string else f"{c.body} rolls"
    if room.is_negative or (room.is_number and room < 0):
        raise InputError(f"contact '{c.name}': {wound} at the radius {to_unicode(b)}, outside the rim of "
                         f"'{drum.name}' (radius {to_unicode(rim)}): a string winds on the body, and a body rolls "
                         "on its axle, at most at its rim", c.radius.loc)
    if not room.free_symbols or room.is_nonnegative:
        return ()
    where = "the string is wound on" if c.string else f"{c.body} rolls at a radius of"
    return (implied(c, rim, b, names, f"contact '{c.name}': {where} {drum.name}, inside its rim", strict=False),)


def implied(c: Contact, larger: sp.Expr, smaller: sp.Expr, names: Symbols, why: str, strict: bool = True) -> Assumed:
    """The assumption ``larger > smaller`` (≥ unless ``strict``) that contact ``c``'s
    geometry needs, located at the contact and saying ``why``."""
    reverse = reverse_names(names)
    op = ">" if strict else ">="
    text = f"{to_unicode(larger)} {'>' if strict else '≥'} {to_unicode(smaller)}"
    stated = Assumption(as_expr(larger, reverse, names, c), op, as_expr(smaller, reverse, names, c), text, c.loc)
    return Assumed(sp.expand(larger - smaller), strict, stated, why)


def _check_touches(c: Contact, e: Curved, s: _Surface, sigma) -> None:
    """At the reference configuration (angle 0) the edge's point facing the surface,
    −n in body axes, must lie on its arc."""
    facing = -s.normal.subs(sigma, 0)
    if e.arc is not None:
        middle, half = e.arc
        if sp.simplify(facing.dot(middle) - sp.cos(half)).is_negative:
            raise InputError(f"contact '{c.name}': body '{c.body}' does not touch the surface at the reference "
                             f"configuration ({c.coordinate} = 0): its {c.edge} edge faces away from it; turn the "
                             "shape with 'axis:' (for instance 'axis: -y', the curved side down)", c.loc)
