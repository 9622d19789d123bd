"""The ``contacts:`` section: bodies that roll on lines and circles, and strings.

    contacts:
      C: {body: wheel, rolls_on: {line: {through: [0, 0], angle: -alpha}}, along: x}
      D: {body: cylinder, rolls_on: {circle: {centre: [0, 0], radius: R, side: inside}}, along: theta}
      E: {body: half, edge: curved, rolls_on: floor, angle: theta}
      S: {body: yoyo, string: {fixed_at: A, direction: [0, -1], radius: r}, along: y}
      H: {body: block, hangs_from: {drum: cylinder, direction: [1, 0], over: P}}
      K: {body: weight, hangs_from: {drum: pulley, side: left}}    # straight down from the rim
      P: {body: coin, rolls_on: {plane: {normal: z}}}     # in 3D: the coin has 'at' and 'orientation'

A body hanging on a string (``hangs_from``) from a drum, over a light pulley, names no
coordinate: the string's inextensibility places it from the drum's motion. Each other
contact names one declared coordinate, as ``along`` (the contact point's travel:
a distance along a line, the angle round a circle from its lowest point inside or its
top outside) or ``angle`` (the body's turn); the body gives neither ``at`` nor
``angle``: rolling places it (model/constraints/contacts.py). A body rolling on a plane in 3D keeps
its own ``at`` and ``orientation`` and names no coordinate: the condition does not
integrate, so it stays a constraint (model/constraints/plane_rolling.py). This module only reads and checks
names; the geometry (does the body fit, does it touch) is checked with sympy later.
"""

from __future__ import annotations

from fractions import Fraction

from rbdsolve.errors import InputError, did_you_mean
from rbdsolve.problem import expr as ex
from rbdsolve.problem.context import Reading
from rbdsolve.problem.readers import check_keys, describe, expect_mapping, expect_scalar
from rbdsolve.problem.sections.bodies import refuse_negative
from rbdsolve.problem.scene import Contact, Pulley, Surface
from rbdsolve.problem.schema import Body, Part
from rbdsolve.problem.surfaces import Measure, NOT_INTEGRABLE, SurfaceKind
from rbdsolve.problem.yamlnodes import Map, Node, Scalar

SIDES = {"line": ("left", "right"), "circle": ("inside", "outside"), "string": ("left", "right"),
         "hanging": ("left", "right", "above", "below")}


# a planar contact's rolling condition integrates; in 3D it does not
NOT_PLANAR = ("{what} is rolling in 3D, which a planar contact does not describe: a planar contact rolls in the "
              "xy-plane of the scene, where its rolling condition integrates; in 3D roll on a plane, "
              "'rolls_on: {{plane: {{normal: z}}}}', with the body placed by its own 'at' and 'orientation'")


def contact_bodies(node: Node | None, names: list[str] | None = None) -> dict[str, str]:
    """body name -> contact name, read before the bodies so they know they are placed;
    a name not among the bodies' ``names`` is refused here, at the contact, before the
    body it was meant for is read as placed by nothing ("body 'wheel' needs 'at'")."""
    if node is None or (isinstance(node, Scalar) and node.null):
        return {}
    table = expect_mapping(node, "contacts: name -> contact")
    out = {}
    for key, value in table.entries:
        body = value.get("body") if isinstance(value, Map) else None
        if _on_plane(value):  # in 3D: the body is placed by its own 'at' and 'orientation'
            continue
        if isinstance(body, Scalar) and not body.null:
            if names is not None and body.text not in names:
                raise InputError(f"no body '{body.text}'{did_you_mean(body.text, names)}", body.loc)
            if body.text in out:
                raise InputError(f"body '{body.text}' has two contacts ('{out[body.text]}' and '{key.text}'): "
                                 "that over-constrains it (one rolling contact or string per body)", body.loc)
            out[body.text] = key.text
    return out


def hanging_bodies(node: Node | None) -> frozenset[str]:
    """The bodies that hang straight from a drum (``hangs_from``): they do not turn."""
    if not isinstance(node, Map):
        return frozenset()
    return frozenset(v.get("body").text for _, v in node.entries
                     if isinstance(v, Map) and v.get("hangs_from") is not None and isinstance(v.get("body"), Scalar))


class ContactReader:
    def __init__(self, reading: Reading):
        self.reading = reading

    def contacts(self, node: Node | None, bodies: tuple[Body, ...]) -> tuple[Contact, ...]:
        if node is None or (isinstance(node, Scalar) and node.null):
            return ()
        table = expect_mapping(node, "contacts: name -> contact")
        named = {b.name: b for b in bodies}
        contacts = tuple(self.contact(self.reading.declare(key, "contact"), value, named)
                         for key, value in table.entries)
        _check_order(contacts)
        return contacts

    def contact(self, name: str, node: Node, bodies: dict[str, Body]) -> Contact:
        what = f"contact '{name}'"
        spec = expect_mapping(node, what)
        check_keys(spec, ("body",), ("edge", "rolls_on", "string", "hangs_from", "along", "angle", "part", "radius"),
                   what)
        if sum(spec.get(k) is not None for k in ("rolls_on", "string", "hangs_from")) != 1:
            raise InputError(f"{what} needs one of 'rolls_on' (a floor, a line, a circle or a body's edge), "
                             "'string' (a string wound on the body) or 'hangs_from' (the body hangs on a string "
                             "from a drum, over a pulley)", spec.loc)
        if spec.get("hangs_from") is not None:
            return self.hanging(name, spec, bodies, what)
        body = _body(spec.get("body"), bodies)
        part = touching_part(spec, body)
        if _on_plane(spec):
            return self.on_plane(name, spec, body, part, what)
        coordinate, measure = self.coordinate(spec, what)
        if spec.get("string") is not None:
            _string_radius_inside(spec)
            surface, radius = self.string(spec.get("string"))
            edge = _edge(spec, part, string=radius is not None)
            return Contact(name, body.name, edge, surface, coordinate, measure, radius, True, spec.loc, part=part.name)
        radius = self.rolling_radius(spec)
        surface = self.surface(spec.get("rolls_on"), bodies)
        if surface.body == body.name:
            raise InputError(f"{what}: body '{body.name}' cannot roll on itself", spec.get("rolls_on").loc)
        return Contact(name, body.name, _edge(spec, part, string=radius is not None), surface, coordinate, measure,
                       radius, False, spec.loc, part=part.name)

    def rolling_radius(self, spec: Map) -> ex.Expr | None:
        """``radius: R``: the body rolls on the circle of radius R about its centre (a body
        given by its inertia, a spool's rim); not with an ``edge``, which has its own."""
        radius = self.reading.optional_constant(spec.get("radius"), "the radius the body rolls at")
        if radius is not None:
            refuse_negative(radius, "radius")
            if spec.get("edge") is not None:
                raise InputError("give the edge that touches ('edge') or the radius the body rolls at "
                                 "('radius'), not both: an edge has its own radius", spec.get("radius").loc)
        return radius

    def hanging(self, name: str, spec: Map, bodies: dict[str, Body], what: str) -> Contact:
        """``hangs_from: {drum: D, direction: [dx, dy], over: P, radius, edge, down, length}``."""
        for key in ("along", "angle", "edge", "part", "radius"):
            if spec.get(key) is not None:
                raise InputError(f"{what}: a hanging body has no '{key}': the string places it from the drum's "
                                 "motion (the drum's own contact or coordinates)", spec.get(key).loc)
        word = expect_scalar(spec.get("body"), "a body name")
        if word.text not in bodies:
            raise InputError(f"no body '{word.text}'{did_you_mean(word.text, list(bodies))}", word.loc)
        hang = expect_mapping(spec.get("hangs_from"), "a string to a drum: {drum, side} or {drum, direction, over}")
        check_keys(hang, ("drum",), ("over", "direction", "side", "radius", "edge", "down", "length", "part",
                                     "pulley"), "a hanging string")
        drum = _body(hang.get("drum"), bodies)
        if drum.name == word.text:
            raise InputError(f"{what}: body '{drum.name}' cannot hang from itself", hang.get("drum").loc)
        radius = self.reading.optional_constant(hang.get("radius"), "the radius the string is wound at")
        part = touching_part(hang, drum)
        edge = _edge(hang, part, string=radius is not None)
        length = self.reading.optional_constant(hang.get("length"), "the hanging length at the reference")
        over, side, down = _hanging_keys(hang)
        direction = self.direction(hang) if over is not None or hang.get("direction") is not None else _down(hang)
        wheel = _wheel(hang, bodies, drum.name, word.text)
        pulley = Pulley(drum.name, edge, radius, self.place(over, hang.loc) if over is not None else None, direction,
                        self.reading.axis(down) if down is not None else None, length, hang.loc, side, part.name,
                        wheel.name if wheel else None, hang.get("pulley").loc if wheel else None)
        line = Surface(SurfaceKind.LINE, pulley.over, pulley.direction, None, False, hang.loc)
        return Contact(name, word.text, edge, line, None, None, radius, True, spec.loc, pulley)

    def on_plane(self, name: str, spec: Map, body: Body, part: Part, what: str) -> Contact:
        """``rolls_on: {plane: {normal: z, through: P}}``: a round body rolling on a fixed
        plane in 3D, placed by its own ``at`` and ``orientation``; no coordinate (the
        condition does not integrate), the contact point C is derived in the model."""
        for key in ("along", "angle"):
            if spec.get(key) is not None:
                raise InputError(f"{what}: {NOT_INTEGRABLE}, so the contact names no coordinate; the body keeps "
                                 f"its own 'at' and 'orientation' (remove '{key}')", spec.get(key).loc)
        if not body.orientation or body.at is None:
            raise InputError(f"{what}: body '{body.name}' rolls on a plane in 3D: give it its place 'at' and its "
                             "turns 'orientation' (the contact derives the point C where it touches)", spec.loc)
        node = expect_mapping(spec.get("rolls_on").entries[0][1], "a plane: {normal, through}")
        check_keys(node, (), ("normal", "through"), "a plane")
        normal = self.reading.axis(node.get("normal")) if node.get("normal") is not None else _unit_z(node)
        through = self.place(node.get("through"), node.loc) if node.get("through") is not None else None
        if spec.get("radius") is not None or part.shape is None:
            raise InputError(f"{what}: a body rolls on a plane on the rim of a round shape of its own (a disk, ring, "
                             "cylinder or sphere); a radius about a given inertia is for a contact in the plane of "
                             "the scene", spec.get("radius").loc if spec.get("radius") else spec.loc)
        edge = _edge(spec, part, string=False)
        if edge != "rim":
            raise InputError(f"{what}: a body rolls on a plane on a whole round edge ('rim' of a disk, ring, "
                             f"cylinder or sphere), not '{edge}'", spec.get("edge").loc if spec.get("edge") else
                             spec.loc)
        plane = Surface(SurfaceKind.PLANE, through, normal, None, False, node.loc)
        return Contact(name, body.name, edge, plane, None, None, None, False, spec.loc, part=part.name)

    def coordinate(self, spec: Map, what: str) -> tuple[str, Measure]:
        """The one coordinate the contact is measured by: 'along: x' or 'angle: theta'."""
        given = [(m, spec.get(m.value)) for m in Measure if spec.get(m.value) is not None]
        if len(given) != 1:
            raise InputError(f"{what} needs one coordinate: 'along: x' (the contact's travel along the "
                             "surface) or 'angle: theta' (the body's turn)"
                             + ("" if not given else ", not both"), spec.loc)
        measure, node = given[0]
        word = expect_scalar(node, "a coordinate name").text.strip()
        known = self.reading.coordinates
        if word not in known:
            raise InputError(f"'{word}' is not a declared coordinate{did_you_mean(word, list(known))}: a contact "
                             "leaves the body one degree of freedom, named in 'coordinates:'", node.loc)
        return word, measure

    def surface(self, node: Node, bodies: dict[str, Body]) -> Surface:
        if isinstance(node, Scalar) and node.text.strip() == "floor":
            origin = ex.Expr(ex.Vec((ex.Num(Fraction(0)), ex.Num(Fraction(0)))), ex.Kind.VECTOR, "[0, 0]", node.loc)
            return Surface(SurfaceKind.LINE, origin, _unit_x(node), None, False, node.loc)
        spec = expect_mapping(node, "a surface: floor, {line: {...}}, {circle: {...}} or {body: B, edge: E}")
        if spec.get("body") is not None:
            return _body_surface(spec, bodies, self.rolling_radius(spec))
        if len(spec.entries) == 1 and spec.entries[0][0].text == "sphere":
            raise InputError(NOT_PLANAR.format(what=f"rolling on a {spec.entries[0][0].text}"), spec.entries[0][0].loc)
        if len(spec.entries) != 1 or spec.entries[0][0].text not in ("line", "circle"):
            found = ", ".join(k.text for k, _ in spec.entries) or "nothing"
            raise InputError(f"a surface is 'floor', {{line: {{through, angle}}}}, {{circle: {{centre, radius, "
                             f"side}}}} or another body's edge {{body: B, edge: E}}; found {found}", spec.loc)
        key, value = spec.entries[0]
        body = expect_mapping(value, f"a {key.text}")
        if key.text == "line":
            check_keys(body, (), ("through", "angle", "direction", "side"), "a line")
            return Surface(SurfaceKind.LINE, self.place(body.get("through"), body.loc), self.direction(body),
                           None, self.side(body, "line") == "right", body.loc)
        check_keys(body, ("centre", "radius"), ("side",), "a circle")
        radius = self.reading.constant(body.get("radius"), "a radius")
        return Surface(SurfaceKind.CIRCLE, self.place(body.get("centre"), body.loc), None, radius,
                       self.side(body, "circle") == "inside", body.loc)

    def string(self, node: Node) -> tuple[Surface, ex.Expr | None]:
        """A string from the fixed point ``fixed_at`` along ``direction`` to the drum."""
        spec = expect_mapping(node, "a string: {fixed_at, direction, radius, side}")
        check_keys(spec, ("fixed_at", "direction"), ("radius", "side"), "a string")
        radius = self.reading.optional_constant(spec.get("radius"), "the radius the string is wound at")
        line = Surface(SurfaceKind.LINE, self.place(spec.get("fixed_at"), spec.loc), self.direction(spec),
                       None, self.side(spec, "string") == "right", spec.loc)
        return line, radius

    def place(self, node: Node | None, where) -> ex.Expr:
        if node is None:
            return ex.Expr(ex.Vec((ex.Num(Fraction(0)), ex.Num(Fraction(0)))), ex.Kind.VECTOR, "[0, 0]", where)
        return self.reading.expr(node, ex.Kind.VECTOR, "a point name or position vector", self.reading.positions)

    def direction(self, spec: Map) -> ex.Expr:
        """A constant direction: 'direction: [dx, dy]', or 'angle: alpha' from the x axis."""
        angle, direction = spec.get("angle"), spec.get("direction")
        if angle is not None and direction is not None:
            raise InputError("give the line's 'angle' or its 'direction', not both", direction.loc)
        if direction is not None:
            return self.reading.axis(direction)
        if angle is None:
            return _unit_x(spec)
        a = self.reading.constant(angle, "the line's angle from the x axis (a constant)")
        cos, sin = ex.Call("cos", (a.tree,)), ex.Call("sin", (a.tree,))
        return ex.Expr(ex.Vec((cos, sin)), ex.Kind.VECTOR, f"[cos({a.text}), sin({a.text})]", a.loc)

    def side(self, spec: Map, kind: str) -> str:
        node = spec.get("side")
        choices = SIDES[kind]
        if node is None:
            if kind == "circle":
                raise InputError("a circle needs 'side: inside' or 'side: outside' (which side the body rolls on)",
                                 spec.loc)
            return choices[0]
        word = expect_scalar(node, f"{' or '.join(choices)}").text.strip()
        if word not in choices:
            raise InputError(f"expected side {' or '.join(choices)}, found {describe(node)}"
                             f"{did_you_mean(word, list(choices))}", node.loc)
        return word


def _hanging_keys(hang: Map) -> tuple[Node | None, str | None, Node | None]:
    """(over, side, down) of a hanging string: over a light pulley at 'over' (the side
    follows from where the pulley is), or straight from the drum's rim on its 'side'."""
    over, side, down = hang.get("over"), hang.get("side"), hang.get("down")
    if over is not None:
        if side is not None:
            raise InputError("the string runs over the pulley at 'over', which fixes the side it leaves the drum on: "
                             "remove 'side'", side.loc)
        if hang.get("direction") is None:
            raise InputError("a string over a pulley needs 'direction', the way it leaves the drum towards the "
                             "pulley ([1, 0]: to the right)", hang.loc)
        return over, None, down
    if side is None:
        raise InputError("a body hanging from the drum says on which side of it the string comes down: "
                         "'side: left' or 'side: right' (or, over a light pulley, 'over: P' and 'direction')",
                         hang.loc)
    word = expect_scalar(side, "left, right, above or below").text.strip()
    if word not in SIDES["hanging"]:
        raise InputError(f"expected side {', '.join(SIDES['hanging'])} (where the string leaves the drum, as "
                         f"drawn), found {describe(side)}{did_you_mean(word, list(SIDES['hanging']))}", side.loc)
    if down is not None:
        raise InputError("'down' is the way the string runs after a pulley; straight from the drum it runs along "
                         "'direction' (default [0, -1])", down.loc)
    return None, word, None


def _wheel(hang: Map, bodies: dict[str, Body], drum: str, hanging: str) -> Body | None:
    """The pulley with mass a string runs over (``pulley: NAME``, beside ``over``): a
    round body of one shape (a disk, ring or cylinder) on a fixed axle, which the string
    turns (so it has no 'angle' of its own), neither the drum nor the hanging body."""
    node = hang.get("pulley")
    if node is None:
        return None
    if hang.get("over") is None:
        raise InputError("a pulley with mass ('pulley') is where the string turns down: give 'over: P', the point "
                         "of its rim the string reaches, with 'direction'", node.loc)
    body = _body(node, bodies)
    if body.name in (drum, hanging):
        raise InputError(f"body '{body.name}' is the {'drum' if body.name == drum else 'hanging body'}; the pulley "
                         "is a body of its own", node.loc)
    shape = body.parts[0].shape if len(body.parts) == 1 else None
    if shape is None or not shape.edges or shape.edges[0] != "rim":
        raise InputError(f"body '{body.name}' is not a round body of one shape: a pulley the string turns is a "
                         "disk, ring or cylinder (its rim's radius turns it)", node.loc)
    if body.angle is not None or body.orientation:
        key = "angle" if body.angle is not None else "orientation"
        raise InputError(f"body '{body.name}' is turned by the string over it, in the plane, which gives its angle: "
                         f"remove its '{key}'", (body.angle.loc if body.angle is not None else node.loc))
    if body.at is None:
        raise InputError(f"body '{body.name}' turns on a fixed axle: give its centre, 'at: [x, y]'", node.loc)
    return body


def _down(where: Map) -> ex.Expr:
    return ex.Expr(ex.Vec((ex.Num(Fraction(0)), ex.Num(Fraction(-1)))), ex.Kind.VECTOR, "[0, -1]", where.loc)


def _check_order(contacts: tuple[Contact, ...]) -> None:
    """A body rolled on or hung from is placed before the contact that uses it (by
    'at'/'angle', or by an earlier contact; a pulley with mass, by the string that turns
    it); two contacts between the same two bodies over-constrain them, and so do two
    strings that turn one pulley with mass."""
    for k, c in enumerate(contacts):
        used = c.pulley.drum if c.pulley is not None else c.surface.body
        where = c.pulley.loc if c.pulley is not None else c.surface.loc
        for d in contacts[k + 1:]:
            if d.body == used and d.surface.body == c.body:
                raise InputError(f"contacts '{c.name}' and '{d.name}' both say how '{c.body}' and '{d.body}' roll "
                                 "on each other: that over-constrains them (one contact for the pair)", d.loc)
            if d.body == used:
                raise InputError(f"contact '{c.name}' uses '{used}', which contact '{d.name}' places later: "
                                 f"list '{d.name}' first", where)
            if used is not None and d.pulley is not None and d.pulley.wheel == used:
                raise InputError(f"contact '{c.name}' hangs from '{used}', which the string of contact '{d.name}' "
                                 f"turns later: list '{d.name}' first", where)
        wheel = c.pulley.wheel if c.pulley is not None else None
        other = next((d for d in contacts[:k] if d.pulley is not None and d.pulley.wheel == wheel), None)
        if wheel is not None and other is not None:
            raise InputError(f"pulley '{wheel}' is turned by the string of contact '{other.name}' already: one "
                             "string over a pulley with mass (two, one on each side, hang from it as a drum: "
                             "'hangs_from: {drum: …, side: left}')", c.pulley.wheel_loc)


def _on_plane(spec: Node) -> bool:
    """Does the contact roll on a plane (``rolls_on: {plane: …}``)?"""
    surface = spec.get("rolls_on") if isinstance(spec, Map) else None
    return isinstance(surface, Map) and len(surface.entries) == 1 and surface.entries[0][0].text == "plane"


def _unit_z(where) -> ex.Expr:
    return ex.Expr(ex.Vec(tuple(ex.Num(Fraction(v)) for v in (0, 0, 1))), ex.Kind.VECTOR, "z", where.loc)


def _unit_x(where) -> ex.Expr:
    return ex.Expr(ex.Vec((ex.Num(Fraction(1)), ex.Num(Fraction(0)))), ex.Kind.VECTOR, "[1, 0]", where.loc)


def _body(node: Node, bodies: dict[str, Body]) -> Body:
    word = expect_scalar(node, "a body name")
    if word.text not in bodies:
        raise InputError(f"no body '{word.text}'{did_you_mean(word.text, list(bodies))}", word.loc)
    return bodies[word.text]


def touching_part(spec: Map, body: Body, solid: bool = True) -> Part:
    """The part of ``body`` that touches: ``part: NAME``, else the body's only part, else
    its only solid part with an edge (a half ring with a particle fixed on it). A hole
    has no material to roll (``solid``); it may be rolled in."""
    node = spec.get("part")
    if node is None:
        if len(body.parts) == 1:
            return body.parts[0]
        edged = [p for p in body.parts if not p.hole and p.shape is not None and p.shape.edges]
        if len(edged) == 1:
            return edged[0]
        solid_parts = ", ".join(p.name for p in body.parts if not p.hole)
        raise InputError(f"body '{body.name}' is made of parts: name the one that touches, 'part: NAME' "
                         f"(its parts: {solid_parts})", spec.loc)
    word = expect_scalar(node, "a part's name").text.strip()
    if len(body.parts) == 1 and body.parts[0].name == body.name:
        raise InputError(f"body '{body.name}' is one shape, with no parts to name: remove 'part'", node.loc)
    parts = {p.name: p for p in body.parts}
    if word not in parts:
        raise InputError(f"body '{body.name}' has no part '{word}'"
                         f"{did_you_mean(word, list(parts)) or ' (its parts: ' + ', '.join(parts) + ')'}", node.loc)
    if solid and parts[word].hole:
        raise InputError(f"part '{word}' of body '{body.name}' is a hole: it has no material to roll on; name a "
                         "solid part", node.loc)
    return parts[word]


def _where(spec: Map, *keys: str):
    """The location of the first of ``keys`` the mapping has, else its own."""
    return next((spec.get(k).loc for k in keys if spec.get(k) is not None), spec.loc)


def _string_radius_inside(spec: Map) -> None:
    """A string's winding radius is the string's: 'string: {…, radius: r}'."""
    if spec.get("radius") is not None:
        raise InputError("the radius a string is wound at goes in the string, 'string: {fixed_at, direction, "
                         "radius}'", spec.get("radius").loc)


def _body_surface(spec: Map, bodies: dict[str, Body], radius: ex.Expr | None) -> Surface:
    """Another body's edge: ``{body: B, edge: E, side: outside}`` (a rim: outside by
    default; a flat edge: the body on its outer side), of its ``part``; or the circle of
    ``radius`` about the part's centre (a body given by its inertia)."""
    check_keys(spec, ("body",), ("edge", "side", "part", "radius"), "a body's edge to roll on")
    body = _body(spec.get("body"), bodies)
    part = touching_part(spec, body, solid=False)
    edge = _edge(spec, part, string=radius is not None)
    side = spec.get("side")
    word = "outside" if side is None else expect_scalar(side, "inside or outside").text.strip()
    if word not in SIDES["circle"]:
        raise InputError(f"expected side inside or outside, found {describe(side)}"
                         f"{did_you_mean(word, list(SIDES['circle']))}", side.loc)
    return Surface(SurfaceKind.BODY, None, None, radius, word == "inside", spec.loc, body.name, edge, part=part.name)


def _edge(spec: Map, part: Part, string: bool) -> str:
    """The edge named, or the part's default; a string (or a rolling ``radius``) may wind
    at its own radius about the part's centre: the edge ``axle``. A part given by its
    inertia has no edge of its own, only such a radius."""
    shape = part.shape
    edges = shape.edges if shape is not None else ()
    node = spec.get("edge")
    if node is None:
        if string:
            return "axle"  # the string's own radius, about the shape's centre
        if shape is None:
            raise InputError(f"'{part.name}' is given by its inertia, with no edge of its own: give the radius it "
                             "touches at, 'radius: R' (about its centre of mass)", spec.loc)
        if not edges:
            raise InputError(f"a {shape.value} has no edge to roll on (shapes with edges: disk, ring, cylinder, "
                             "sphere, half_disk, hemisphere, plate, rod, …)", _where(spec, "body", "drum"))
        if edges[0] not in ("rim", "curved"):
            raise InputError(f"name the edge of the {shape.value} that touches ('edge: {edges[0]}'; its edges: "
                             f"{', '.join(edges)})", spec.loc)
        return edges[0]
    word = expect_scalar(node, "an edge name")
    if shape is None:
        raise InputError(f"'{part.name}' is given by its inertia, with no edges: give the radius it touches at, "
                         "'radius: R', instead of 'edge'", word.loc)
    if word.text not in edges:
        raise InputError(f"a {shape.value} has no edge '{word.text}' (its edges: {', '.join(edges) or 'none'})"
                         f"{did_you_mean(word.text, list(edges))}", word.loc)
    if (string or spec.get("string") is not None) and word.text not in ("rim", "curved"):
        raise InputError(f"a string winds on a round edge, not '{word.text}'", word.loc)
    return word.text
