"""The ``bodies:`` section: shapes from the library, composite bodies, explicit inertias.

A body moves with the scene (``at`` a position, ``angle`` a planar rotation), or, in a
scene at one instant such as an impact, is given by ``velocity`` (of its centre of
mass) and ``angular_velocity``. A body that does not turn at the instant
(``angular_velocity: 0``) needs only its mass: its inertia cannot matter.
"""

from __future__ import annotations

import math

from rbdsolve.errors import InputError, did_you_mean
from rbdsolve.problem import expr as ex
from rbdsolve.problem.context import Reading
from rbdsolve.problem.quantities.quantity import LENGTH, MASS, NUMBER, approximate
from rbdsolve.problem.readers import check_keys, expect_mapping, expect_scalar, read_bool
from rbdsolve.problem.sections.orientation import OrientationReader
from rbdsolve.problem.schema import SHAPE_ALIASES, Body, Inertia, Part, Shape
from rbdsolve.problem.yamlnodes import Map, Node, Scalar, Seq

# Shape dimensions that are positions, not sizes: any sign is fine.
POSITIONS = {"apex"}
# the unit a shape's dimension may be given in, read in SI (half_angle: 60 deg is π/3)
_A_LENGTH = ((LENGTH,), "a length such as 20 cm")
_DIMENSION_KINDS = {"half_angle": ((NUMBER,), "an angle such as 60 deg")}
MOTION_KEYS = ("angle", "orientation", "velocity", "angular_velocity")



# Names a student writes for a shape the library has under another name and more
# parameters, where the closest spelling would mislead ('half_cylinder': 'cylinder').
_HALF_CYLINDER = (": a solid half-cylinder is shape: cylinder_segment with half_angle: pi/2 (and radius, "
                  "height); turning in its own plane only, a half_disk has the same moment about its axis")
_SHAPE_HINTS = {"half_cylinder": _HALF_CYLINDER, "semicylinder": _HALF_CYLINDER, "semi_cylinder": _HALF_CYLINDER,
                "half_sphere": " (did you mean 'hemisphere'?)"}

class BodyReader:
    def __init__(self, reading: Reading, placed: dict[str, str] | None = None,
                 hanging: frozenset[str] = frozenset()):
        self.reading = reading
        self.placed = placed or {}  # body -> the contact that places it
        self.hanging = hanging  # the bodies that hang straight from a drum

    def body(self, name: str, node: Node) -> Body:
        spec = expect_mapping(node, f"body '{name}'")
        what = f"body '{name}'"
        if name in self.placed:
            _refuse_placement(spec, name, self.placed[name], name in self.hanging)
            at, angle, velocity, omega = None, None, None, None
        else:
            at, angle, velocity, omega = self.motion(spec, what)
        orientation = self.orientation(spec)
        points = self.points(spec.get("points"), name)
        if spec.get("parts") is None:
            part = self.part(name, spec, what, (*MOTION_KEYS, "points"), simple=True, translating=_is_zero(omega))
            return Body(name, (part,), at, angle, spec.loc, velocity, omega, orientation, points)
        check_keys(spec, ("parts",), ("at", *MOTION_KEYS, "points"), what)
        table = expect_mapping(spec.get("parts"), "parts: name -> part")
        if not table.entries:
            raise InputError(f"{what} has no parts", table.loc)
        parts = tuple(self.part(k.text, expect_mapping(v, f"part '{k.text}'"), f"part '{k.text}' of {what}", (),
                                simple=False) for k, v in table.entries)
        if all(p.hole for p in parts):
            raise InputError(f"{what} is all holes: give at least one solid part", table.loc)
        return Body(name, parts, at, angle, spec.loc, velocity, omega, orientation, points)

    def points(self, node: Node | None, body: str) -> tuple[tuple[str, ex.Expr], ...]:
        """The body's own points, ``points: {B: [l/2, 0]}``: each a constant offset from
        the body's origin in body axes (it turns with the body); its name is a point of
        the scene like any other (springs, forces, questions)."""
        if node is None or (isinstance(node, Scalar) and node.null):
            return ()
        table = expect_mapping(node, f"the points of body '{body}': name -> position in the body")
        scope = self.reading.scope.constants(f"a point of body '{body}' is fixed in it: its position from the "
                                             "body's origin, in body axes, is constant (parameters and numbers)")
        return tuple((self.reading.declare(key, "point"),
                      self.reading.expr(value, ex.Kind.VECTOR, f"the position of point '{key.text}' in body "
                                        f"'{body}' (a vector in body axes)", scope))
                     for key, value in table.entries)

    def motion(self, spec: Map, what: str) -> tuple[ex.Expr | None, ...]:
        """(at, angle) for a body that moves with the scene, or (velocity,
        angular_velocity) for a body at one instant; never a mix of the two."""
        reading = self.reading
        get = spec.get
        if get("at") is None and get("velocity") is None:
            raise InputError(f"{what} needs 'at' (its position) or, in a scene at one instant, "
                             "'velocity'", spec.loc)
        if get("velocity") is None:
            if get("angular_velocity") is not None:
                raise InputError("'angular_velocity' goes with 'velocity'; a body placed with 'at' "
                                 "turns with its 'angle'", get("angular_velocity").loc)
            at = reading.expr(get("at"), ex.Kind.VECTOR, "a point name or position vector", reading.positions)
            return at, reading.optional_expr(get("angle"), ex.Kind.SCALAR, "an angle (a scalar expression)"), None, None
        for key in ("at", "angle"):
            if get(key) is not None:
                raise InputError(f"give either 'at'/'angle' (the motion) or 'velocity'/'angular_velocity' "
                                 f"(one instant), not both; found '{key}' with 'velocity'", get(key).loc)
        velocity = reading.expr(get("velocity"), ex.Kind.VECTOR,
                               "the velocity of the centre of mass (a velocity point's name or a vector)",
                               reading.rates)
        omega = get("angular_velocity")
        if omega is None:
            raise InputError(f"{what} gives 'velocity' but not 'angular_velocity' (0 if it does not "
                             "turn at this instant)", spec.loc)
        return None, None, velocity, self.angular_velocity(omega)

    def orientation(self, spec: Map) -> tuple:
        """A 3D orientation (turns), instead of a planar 'angle'."""
        node = spec.get("orientation")
        if node is None:
            return ()
        for key in ("angle", "velocity"):
            if spec.get(key) is not None:
                raise InputError(f"give either 'orientation' (3D turns) or '{key}', not both", spec.get(key).loc)
        return OrientationReader(self.reading).orientation(node, self.reading.triad_names)

    def angular_velocity(self, node: Node) -> ex.Expr:
        """A scalar ω (planar: about z) or a vector."""
        if isinstance(node, Seq):
            return self.reading.expr(node, ex.Kind.VECTOR, "an angular velocity", self.reading.rates)
        scalar = expect_scalar(node, "an angular velocity (a scalar about z, or a vector)")
        if scalar.text.strip() in self.reading.rates.vectors:
            raise InputError(f"'{scalar.text.strip()}' is a point; an angular velocity is a scalar (about z) "
                             "or a vector", scalar.loc)
        return ex.parse(scalar.text, scalar.loc, self.reading.rates, scalar.plain)

    def part(self, name: str, spec: Map, what: str, extra: tuple[str, ...], simple: bool,
             translating: bool = False) -> Part:
        _gyration(spec)
        shape = self.shape(spec, what, translating)
        dims = shape.dimensions if shape else ()
        _check_dimensions(spec, shape, what)
        required = ("mass", *dims)
        check_keys(spec, required, ("shape", "axis", "inertia", "at", *extra, *(() if simple else ("hole",))), what)
        measured = self.reading.measured
        mass = measured(spec.get("mass"), "a mass", (MASS,), "a mass such as 2 kg")
        refuse_negative(mass, "mass")
        dimensions = []
        for dim in dims:
            value = measured(spec.get(dim), f"a {dim}", *_DIMENSION_KINDS.get(dim, _A_LENGTH))
            if dim not in POSITIONS:
                refuse_negative(value, dim)
            if dim == "half_angle":
                _half_angle(value)
            dimensions.append((dim, value))
        axis_node = spec.get("axis")
        if axis_node is not None and shape is None:
            raise InputError("'axis' orients a shape; an explicit inertia is already in body axes",
                             axis_node.loc)
        at = None
        if not simple and spec.get("at") is not None:
            scope = self.reading.scope.constants("a part's position in its body must be constant")
            at = self.reading.expr(spec.get("at"), ex.Kind.VECTOR, "a position in the body (a vector)", scope)
        hole = read_bool(spec.get("hole"), "true or false") if spec.get("hole") is not None else False
        return Part(name, shape, mass, tuple(dimensions), at,
                    self.reading.axis(axis_node) if axis_node is not None else None,
                    self.inertia(spec.get("inertia")), hole, spec.loc)

    def shape(self, spec: Map, what: str, translating: bool = False) -> Shape | None:
        node = spec.get("shape")
        if node is None:
            if spec.get("inertia") is None:
                if translating:  # it does not turn at this instant: its inertia cannot matter
                    return Shape.PARTICLE
                turns = " since it turns at this instant" if spec.get("angular_velocity") is not None else ""
                raise InputError(f"{what} needs a 'shape' (or an explicit 'inertia'){turns}", spec.loc)
            return None
        if spec.get("inertia") is not None:
            raise InputError(f"{what}: give either 'shape' or 'inertia', not both", node.loc)
        word = expect_scalar(node, "a shape name").text
        names = [s.value for s in Shape] + list(SHAPE_ALIASES)
        if word in SHAPE_ALIASES:
            return SHAPE_ALIASES[word]
        try:
            return Shape(word)
        except ValueError:
            hint = _SHAPE_HINTS.get(word.lower()) or did_you_mean(word, names) or \
                f" (shapes: {', '.join(s.value for s in Shape)})"
            raise InputError(f"unknown shape '{word}'{hint}", node.loc) from None

    def inertia(self, node: Node | None) -> Inertia | None:
        if node is None:
            return None
        constant = self.reading.constant
        if isinstance(node, Scalar):
            return Inertia((constant(node, "a moment of inertia"),), node.loc)
        if isinstance(node, Seq) and len(node.items) == 3 and all(isinstance(i, Seq) for i in node.items):
            rows = [row for row in node.items]
            if any(len(r.items) != 3 for r in rows):
                raise InputError("an inertia matrix is 3x3", node.loc)
            entries = [constant(x, "an inertia matrix entry") for r in rows for x in r.items]
            return Inertia(tuple(entries), node.loc)
        if isinstance(node, Seq) and len(node.items) == 3:
            return Inertia(tuple(constant(x, "a principal moment") for x in node.items), node.loc)
        raise InputError(
            "expected an inertia: J (planar), [J1, J2, J3] or a 3x3 matrix", node.loc
        )


def _refuse_placement(spec: Map, name: str, contact: str, hanging: bool) -> None:
    """A body that rolls is placed by its contact: its position and angle follow. One
    that hangs from a drum does not turn, which the message says where it is given an
    angle (a yo-yo hung from a turning drum is not in the format)."""
    for key in ("at", *MOTION_KEYS):
        if spec.get(key) is not None:
            turning = hanging and key in MOTION_KEYS
            raise InputError(f"body '{name}' is placed by contact '{contact}' (the contact gives its position and "
                             f"angle); remove '{key}'" + (_HANGS_UNTURNED if turning else ""), spec.get(key).loc)


_HANGS_UNTURNED = (": a body hanging from a drum ('hangs_from') translates and does not turn. One that turns "
                   "as its own string unwinds (a yo-yo hung from a drum that turns too) is not in the format "
                   "yet; the nearest it has is a yo-yo on a string from a fixed point, 'string: {fixed_at: A, "
                   "direction: [0, -1]}'")


def _gyration(spec: Map) -> None:
    """A radius of gyration is said through the inertia it gives: J = m k²."""
    for key, _ in spec.entries:
        if key.text.replace("_", "") in ("radiusofgyration", "gyrationradius", "gyration"):
            raise InputError(f"'{key.text}': a body given by its radius of gyration k has J = m k²; write "
                             "'inertia: m*k**2' (its mass times k squared, about its centre of mass)", key.loc)


def _is_zero(expr: ex.Expr | None) -> bool:
    if expr is None:
        return False
    if isinstance(expr.tree, ex.Vec):
        return all(ex.constant_value(c) == 0 for c in expr.tree.items)
    return ex.constant_value(expr.tree) == 0


def _check_dimensions(spec: Map, shape: Shape | None, what: str) -> None:
    """A dimension that belongs to other shapes: say which ones this shape takes."""
    others = {d for s in Shape for d in s.dimensions}
    mine = shape.dimensions if shape else ()
    for key, _ in spec.entries:
        if key.text in others and key.text not in mine:
            takes = ", ".join(mine) if mine else "no dimensions"
            kind = f"a {shape.value}" if shape else "a body with an explicit inertia"
            raise InputError(f"{kind} takes {takes}, not '{key.text}' (in {what})", key.loc)


def _half_angle(value: ex.Expr) -> None:
    """A cylinder segment's half angle α: 0 < α ≤ π (α = π the whole cylinder), where a
    constant decides it (pi/3, 60 deg; a parameter is left to its value)."""
    number = approximate(value.tree)
    if number is not None and not 0 < number <= math.pi * (1 + 1e-12):
        raise InputError(f"a half_angle is an angle between 0 and π, or 0 and 180 deg (the segment's arc spans "
                         f"twice it), found {value.text}", value.loc)


def refuse_negative(value: ex.Expr, what: str) -> None:
    number = ex.constant_value(value.tree)
    if number is not None and number < 0:
        raise InputError(f"a {what} must not be negative, found {value.text}", value.loc)
