"""Model -> a planar picture's geometry: 2-D primitives to scale at one configuration.

No matplotlib here (:mod:`rbdsolve.render.drawing.figures` draws a :class:`Sketch`): this module
turns a model, the coordinates' values and the parameters' values into frozen
dataclasses of segments, circles, polygons, dots, labelled points and spring zig-zags.

Each part of each body is placed as the model places it: its own axes turned onto its
``axis`` (``rotation_to``, as for its inertia), moved to its ``at`` in body axes, then
turned by the body's rotation and moved to the body's origin. The shape is then seen
along the scene's z axis: a shape whose own axis ends up along z (a disk in the plane)
is a circle; any other view is the convex hull of points sampled on the shape (every
shape in the library is convex), so a disk seen edge-on is a segment and a cone seen
from the side a triangle.

Only planar scenes are drawn: no 3D turns, nothing off the xy-plane, positions (not
velocities at an instant) for every body. Anything else raises :class:`NotDrawable`.
Time is taken at t = 0 and an unknown prescribed function y_A(t) as 0.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from itertools import pairwise
from typing import Iterable, Iterator, Mapping

import numpy as np
import sympy as sp
from sympy.core.function import AppliedUndef

from rbdsolve.form.printers import to_unicode
from rbdsolve.errors import InputError
from rbdsolve.model.build import Model, RigidBody
from rbdsolve.model.inertia import OWN_AXIS, rotation_to
from rbdsolve.model.state import t
from rbdsolve.problem import expr as ex
from rbdsolve.problem.schema import Part, QuestionKind, Shape

Vec2 = tuple[float, float]

CIRCLE_SAMPLES = 48  # points on a circle seen at a slant (its hull is an ellipse)
DOME_SAMPLES = 12  # latitudes on a hemisphere's dome
AXIAL = {Shape.RING, Shape.DISK, Shape.CYLINDRICAL_SHELL, Shape.CYLINDER, Shape.TUBE, Shape.HEMISPHERE,
         Shape.HEMISPHERICAL_SHELL, Shape.CONE}  # a circle when seen along their own axis
OUTLINES = {Shape.RING, Shape.CYLINDRICAL_SHELL, Shape.SPHERICAL_SHELL, Shape.HALF_RING,
            Shape.HEMISPHERICAL_SHELL}  # thin: drawn, not filled


class NotDrawable(InputError):
    """The scene has no planar picture (3D turns, out of the plane, velocities only)."""


@dataclass(frozen=True)
class Segment:
    start: Vec2
    end: Vec2
    body: str


@dataclass(frozen=True)
class Circle:
    centre: Vec2
    radius: float
    body: str
    filled: bool = True
    hole: bool = False


@dataclass(frozen=True)
class Polygon:
    vertices: tuple[Vec2, ...]  # counterclockwise; two for a flat shape seen edge-on
    body: str
    filled: bool = True
    hole: bool = False


@dataclass(frozen=True)
class Dot:
    """A particle, or a part with an explicit inertia and no shape: a marker, not to scale."""

    at: Vec2
    body: str


@dataclass(frozen=True)
class PointLabel:
    name: str
    at: Vec2


@dataclass(frozen=True)
class Link:
    """A thin line from the point a position is measured from to the point or body
    placed from it (``P1: O + l1*[...]``): the massless links and construction lines
    the scene's positions describe, which no body draws."""

    start: Vec2
    end: Vec2


@dataclass(frozen=True)
class Zigzag:
    name: str
    vertices: tuple[Vec2, ...]


@dataclass(frozen=True)
class Ground:
    """A surface a body rolls on: a stretch of a line (``start`` to ``end``) or a circle
    (``centre``, ``radius``); ``normal`` (a line's) points to the body's side, so the
    hatching goes on the other. A string is a line from its fixed point to the drum."""

    start: Vec2
    end: Vec2
    normal: Vec2
    centre: Vec2 | None = None
    radius: float = 0.0
    inside: bool = False
    string: bool = False


@dataclass(frozen=True)
class Strike:
    """A particle about to hit point ``point`` in an impact, drawn where it is at the
    instant: a small ball of ``radius`` at ``ball``, touching the point, and its velocity
    just before as an arrow from ``tail`` to ``head`` (behind the ball, pointing at it),
    labelled ``label`` (its speed as the file writes it: v₀)."""

    point: str
    ball: Vec2
    radius: float
    tail: Vec2
    head: Vec2
    label: str


Primitive = Segment | Circle | Polygon | Dot


@dataclass(frozen=True)
class Sketch:
    """A planar scene at one configuration, to scale, in the scene's x and y."""

    shapes: tuple[Primitive, ...]  # body by body, each body's solid parts before its holes
    points: tuple[PointLabel, ...]
    springs: tuple[Zigzag, ...]
    gravity: Vec2 | None  # unit vector along g; None without gravity
    configuration: tuple[tuple[str, float], ...]  # coordinate name -> value
    anchors: tuple[Vec2, ...] = ()  # points that move with the bodies: how far a mode moves the scene
    notes: tuple[str, ...] = ()
    bodies: tuple[str, ...] = field(default=())  # names, in the scene's order
    links: tuple[Link, ...] = ()
    grounds: tuple[Ground, ...] = ()  # the floors, inclines, tracks, drums and strings of the contacts
    pivots: tuple[Vec2, ...] = ()  # fixed points bodies turn about, marked as supports whether named or not
    strikes: tuple[Strike, ...] = ()  # the particles of an impact drawn at its instant, with their velocities

    def bounds(self) -> tuple[float, float, float, float]:
        """(x_min, y_min, x_max, y_max) of everything drawn."""
        xs, ys = zip(*self._extent())
        return min(xs), min(ys), max(xs), max(ys)

    def size(self) -> float:
        """The larger side of the bounds (1 for a scene that is one point)."""
        x0, y0, x1, y1 = self.bounds()
        return max(x1 - x0, y1 - y0) or 1.0

    def _extent(self) -> Iterator[Vec2]:
        yield (0.0, 0.0)  # the scene's origin: the positions are measured from it
        yield from (p.at for p in self.points)
        for s in self.shapes:
            if isinstance(s, Segment):
                yield from (s.start, s.end)
            elif isinstance(s, Circle):
                (x, y), r = s.centre, s.radius
                yield from ((x - r, y - r), (x + r, y + r))
            elif isinstance(s, Polygon):
                yield from s.vertices
            else:
                yield s.at
        for z in self.springs:
            yield from z.vertices
        for k in self.strikes:
            yield from (k.tail, (k.ball[0] - k.radius, k.ball[1] - k.radius), (k.ball[0] + k.radius, k.ball[1] + k.radius))
        for g in self.grounds:
            if g.centre is None:
                yield from (g.start, g.end)
            else:
                (x, y), r = g.centre, g.radius
                yield from ((x - r, y - r), (x + r, y + r))


def unvalued(model: Model) -> tuple[str, ...]:
    """The parameters without a numeric value: the picture takes them as 1."""
    return tuple(name for name, s in model.symbols.parameters.items() if s not in model.values)


def ones_note(names: Iterable[str]) -> tuple[str, ...]:
    names = tuple(names)
    if not names:
        return ()
    return (f"{' = '.join(names)} = 1: no value{'s' if len(names) > 1 else ''} given",)


def _time_note(model: Model) -> tuple[str, ...]:
    """Say that a scene moving by itself is drawn at t = 0, unknown functions of t as 0."""
    unknown = [n for n, f in model.symbols.prescribed.items() if isinstance(f, AppliedUndef)]
    notes = ["at t = 0"] if model.depends_on_time() or model.symbols.prescribed else []
    if unknown:
        notes.append(f"{', '.join(unknown)} = 0 (an unknown function of t)")
    return tuple(notes)


def require_planar(model: Model) -> None:
    """Refuse, saying why and where, a scene that has no planar picture."""
    for body in model.bodies:
        if body.position is None:
            raise NotDrawable(f"the scene cannot be drawn: body '{body.name}' is given by its velocity at one "
                              "instant, not by its position", body.source.loc)
        if body.turns_3d:
            raise NotDrawable(f"the scene cannot be drawn: body '{body.name}' turns in 3D (an orientation by "
                              "turns); only planar scenes are drawn", body.source.loc)
    names = model.symbols
    placed = [(f"point '{n}'", p, None) for n, p in model.points.items()]
    placed += [(f"body '{b.name}'", names.vector(b.source.at), b.source.loc) for b in model.bodies]
    placed += [("gravity", model.gravity, model.problem.gravity.loc)] if model.gravity is not None else []
    for what, vector, loc in placed:
        if vector[2] != 0 and sp.simplify(vector[2]) != 0:
            where = "" if loc is not None else f"{model.problem.file}: "
            raise NotDrawable(f"{where}the scene cannot be drawn: {what} leaves the xy-plane (z = "
                              f"{to_unicode(model.readable(vector[2]))}); only planar scenes are drawn", loc)


def default_configuration(model: Model) -> dict[str, float]:
    """Where to draw the scene when not told: a modes question's equilibrium
    (``about``) or an impact's ``at``, the rest of the coordinates 0."""
    out = {name: 0.0 for name in model.coordinate_names()}
    for question in model.problem.questions:
        if question.kind is QuestionKind.MODES and question.options.about:
            given = question.options.about
        elif question.kind is QuestionKind.IMPACT:
            given = question.options.at
        else:
            continue
        out.update({name: number(model, model.symbols.scalar(e)) for name, e in given})
        return out
    return out


def number(model: Model, expr) -> float:
    """A constant of the scene (an ``about`` or ``--at`` value) as the picture takes it:
    parameters at their values or 1; NotDrawable if it is not a real number."""
    return _Values(model, {}).scalar(expr)


def sketch(model: Model, at: Mapping[str, float] | None = None) -> Sketch:
    """The scene drawn at the coordinates ``at`` (missing ones: ``default_configuration``),
    parameters at their values or 1, t = 0; NotDrawable for a scene that is not planar."""
    require_planar(model)
    configuration = {k: float(v) for k, v in {**default_configuration(model), **(at or {})}.items()}
    values = _Values(model, configuration)
    shapes: list[Primitive] = []
    anchors: list[Vec2] = []
    for body in model.bodies:
        drawn, held = _body(body, model, values)
        shapes += drawn
        anchors += held
    points = tuple(PointLabel(n, _xy(values.vector(p))) for n, p in model.points.items())
    bodies = {b.name for b in model.bodies}  # a body's own points are labelled; its origin is the body
    points += tuple(PointLabel(n, _xy(values.vector(p))) for n, p in model.body_points.items() if n not in bodies)
    points += tuple(PointLabel(c.name, _xy(values.vector(c.point))) for c in model.contacts)
    gravity = _unit(values.vector(model.gravity)) if model.gravity is not None else None
    reach = max((math.dist(a, b) for a in anchors for b in anchors), default=1.0) or 1.0
    return Sketch(tuple(shapes), points, tuple(_springs(model, values)), gravity,
                  tuple(configuration.items()), (*anchors, *(p.at for p in points)),
                  ones_note(unvalued(model)) + _time_note(model), tuple(b.name for b in model.bodies),
                  tuple(_links(model, {p.name: p.at for p in points})),
                  tuple(_ground(c, model, values, reach) for c in model.contacts
                        if not c.moving_surface and not _straight(c))
                  + tuple(_hanging_part(c, model, values) for c in model.contacts if c.source.pulley is not None),
                  _pivots(model, values, shapes), _strikes(model, values, configuration, reach))


BALL, SHAFT = 0.035, 0.22  # a striking particle's radius and its velocity arrow's length, of the scene's reach


def _strikes(model: Model, values: _Values, configuration: Mapping[str, float], reach: float) -> tuple[Strike, ...]:
    """The particles of each impact drawn at its instant (only where the scene is drawn
    at the impact's configuration: elsewhere the particle is not there), each touching the
    point it strikes from the side it comes from, its velocity before behind it."""
    out = []
    for question in model.problem.questions:
        if question.kind is not QuestionKind.IMPACT:
            continue
        at = {name: number(model, model.symbols.scalar(e)) for name, e in question.options.at}
        if any(abs(configuration.get(name, 0.0) - x) > 1e-9 for name, x in at.items()):
            continue
        names = model.symbols.with_points(model.points)
        for c in question.options.collisions:
            if c.particle is None:
                continue
            v = values.vector(names.vector(c.particle.velocity))[:2]
            direction = _unit(np.append(v, 0.0))
            if direction is None:
                continue
            point = np.array(_xy(values.vector(model.point(c.point))))
            d, r = np.array(direction), BALL * reach
            ball = point - d * r
            out.append(Strike(c.point, _xy(ball), r, _xy(ball - d * (r * 1.6 + SHAFT * reach)),
                              _xy(ball - d * r * 1.6), _speed_label(names.vector(c.particle.velocity))))
    return tuple(out)


def _speed_label(velocity) -> str:
    """v₀ for [v0, 0] or [0, −v0]: the one component's size; else |v|."""
    parts = [x for x in velocity if x != 0]
    if len(parts) != 1:
        return "|v|"
    return to_unicode(-parts[0] if parts[0].could_extract_minus_sign() else parts[0])


def _pivots(model: Model, values: _Values, shapes: list[Primitive]) -> tuple[Vec2, ...]:
    """Each place a body turns about while it stays put, marked as a support whether or
    not the file names a point there: a point c fixed in the body whose place
    X(q) = r(q) + R(q) c does not move, ∂X/∂qᵢ = ∂r/∂qᵢ + ∂R/∂qᵢ c = 0 for every i,
    solved by least squares at this configuration and checked at another (a rolling
    contact's point is still only for an instant), and on the body as drawn (two rods
    sliding in a circle turn about its centre, which holds neither). Each place once."""
    if not model.q or any(model.symbols.vector(b.source.at).atoms(AppliedUndef) for b in model.bodies):
        return ()
    other = _Values(model, {n: v + 0.7 for n, v in values.configuration.items()})
    out: list[Vec2] = []
    for body in model.bodies:
        r = model.symbols.vector(body.source.at)
        if not (r.free_symbols | body.rotation.free_symbols) & set(model.q) or t in r.free_symbols:
            continue
        c = _still_point(r, body.rotation, model.q, values)
        if c is None or _still_point(r, body.rotation, model.q, other, c) is None:
            continue
        at = _xy(values.vector(r) + values.matrix(body.rotation) @ c)
        if not any(_on(at, shape) for shape in shapes if shape.body == body.name):
            continue
        if all(math.dist(at, p) > 1e-9 * (1 + math.hypot(*at)) for p in out):
            out.append(at)
    return tuple(out)


def _on(at: Vec2, shape: Primitive, tolerance: float = 1e-6) -> bool:
    """Is ``at`` on a drawn part (a segment's line, inside a circle or a polygon)?"""
    if isinstance(shape, Segment):
        (x0, y0), (x1, y1) = shape.start, shape.end
        length2 = (x1 - x0) ** 2 + (y1 - y0) ** 2
        k = 0.0 if length2 == 0 else max(0.0, min(1.0, ((at[0] - x0) * (x1 - x0) + (at[1] - y0) * (y1 - y0)) / length2))
        return math.dist(at, (x0 + k * (x1 - x0), y0 + k * (y1 - y0))) <= tolerance * (1 + math.sqrt(length2))
    if isinstance(shape, Circle):
        return not shape.hole and math.dist(at, shape.centre) <= shape.radius * (1 + tolerance)
    if isinstance(shape, Polygon) and len(shape.vertices) >= 3 and not shape.hole:
        v = shape.vertices
        return all(_cross(v[i], v[(i + 1) % len(v)], at) >= -tolerance for i in range(len(v)))
    return False


def _still_point(r, R, q, values: _Values, c: np.ndarray | None = None) -> np.ndarray | None:
    """The body point c with ∂r/∂qᵢ + ∂R/∂qᵢ c = 0 for all i (or whether the given c is
    one), None where there is none."""
    A = np.vstack([values.matrix(R.diff(qi)) for qi in q])
    b = -np.concatenate([values.vector(r.diff(qi)) for qi in q])
    if not np.any(A):
        return None  # the body does not turn: a slider, a particle
    found = np.linalg.lstsq(A, b, rcond=None)[0] if c is None else c
    scale = 1 + np.abs(b).max() + np.abs(A).max()
    return found if np.abs(A @ found - b).max() <= 1e-9 * scale else None


class _Values:
    """Numbers for the scene's expressions: coordinates and parameters (1 without a
    value) put in, t = 0, an unknown prescribed function 0."""

    def __init__(self, model: Model, configuration: Mapping[str, float]):
        self.configuration = dict(configuration)
        table: dict = {s: sp.Integer(1) for s in model.symbols.parameters.values()}
        table.update(model.values)
        table.update({q: sp.Float(configuration[n]) for q, n in zip(model.q, model.coordinate_names())
                      if n in configuration})
        unknown = [f for f in model.symbols.prescribed.values() if isinstance(f, AppliedUndef)]
        table.update({f: sp.Integer(0) for f in unknown})
        table[t] = sp.Integer(0)
        self.table = table
        self.readable = model.readable

    def scalar(self, expr) -> float:
        value = sp.N(sp.sympify(expr).xreplace(self.table), 17)
        if not value.is_number or not value.is_real:
            raise NotDrawable(f"the scene cannot be drawn: {to_unicode(self.readable(value))} is not a real number "
                              "there")
        return float(value)

    def vector(self, matrix) -> np.ndarray:
        return np.array([self.scalar(x) for x in matrix], dtype=float)

    def matrix(self, matrix) -> np.ndarray:
        return np.array([[self.scalar(x) for x in row] for row in matrix.tolist()], dtype=float)


def _body(body: RigidBody, model: Model, values: _Values) -> tuple[list[Primitive], list[Vec2]]:
    """A body's parts seen along z, solid parts first so holes are drawn over them; and
    its anchors (each part's origin and the ends of its own axes)."""
    names = model.symbols
    origin = values.vector(names.vector(body.source.at))
    turn = values.matrix(body.rotation)
    shapes: list[Primitive] = []
    anchors: list[Vec2] = []
    for part in sorted(body.source.parts, key=lambda p: p.hole):
        offset = values.vector(names.vector(part.at)) if part.at is not None else np.zeros(3)
        own = OWN_AXIS.get(part.shape, sp.Matrix([0, 0, 1]))
        Q = values.matrix(rotation_to(names.vector(part.axis), own)) if part.axis is not None else np.eye(3)
        placed = _Placed(origin + turn @ offset, turn @ Q)
        dims = {k: values.scalar(names.scalar(v)) for k, v in part.dimensions}
        shapes += _outline(part, dims, placed, body.name)
        anchors += placed.anchors(max(dims.values(), default=0.0, key=abs) / 2)
    return shapes, anchors


@dataclass(frozen=True)
class _Placed:
    """A part's own axes in the scene: x_scene = origin + turn @ x_own."""

    origin: np.ndarray
    turn: np.ndarray

    def xy(self, own) -> Vec2:
        return _xy(self.origin + self.turn @ np.asarray(own, dtype=float))

    def hull(self, own_points: Iterable) -> tuple[Vec2, ...]:
        return convex_hull([self.xy(p) for p in own_points])

    def faces_viewer(self) -> bool:
        """Is the own z axis along the scene's z (the shape seen along its own axis)?"""
        return abs(abs(self.turn[2, 2]) - 1) < 1e-9

    def anchors(self, size: float) -> list[Vec2]:
        return [self.xy((0, 0, 0)), *(self.xy(size * e) for e in np.eye(3))]


def _outline(part: Part, dims: Mapping[str, float], placed: _Placed, body: str) -> list[Primitive]:
    shape, hole = part.shape, part.hole
    filled = shape not in OUTLINES
    if shape is None or shape is Shape.PARTICLE:
        return [Dot(placed.xy((0, 0, 0)), body)]
    if shape is Shape.ROD:
        half = dims["length"] / 2
        return [Segment(placed.xy((-half, 0, 0)), placed.xy((half, 0, 0)), body)]
    if shape is Shape.HALF_RING:  # a wire: the arc alone, not closed by its diameter
        arc = [placed.xy(p) for p in _arc(dims["radius"], 0.0, math.pi)]
        return [Segment(a, b, body) for a, b in pairwise(arc)]
    if shape in (Shape.SPHERE, Shape.SPHERICAL_SHELL):
        return [Circle(placed.xy((0, 0, 0)), dims["radius"], body, filled, hole)]
    if shape in AXIAL and placed.faces_viewer():
        radius = dims.get("outer_radius", dims.get("radius"))
        out: list[Primitive] = [Circle(placed.xy((0, 0, 0)), radius, body, filled, hole)]
        if shape is Shape.TUBE:  # seen along its axis, a tube shows its bore
            out.append(Circle(placed.xy((0, 0, 0)), dims["inner_radius"], body, True, True))
        return out
    return [Polygon(placed.hull(_samples(shape, dims)), body, filled, hole)]


def _samples(shape: Shape, d: Mapping[str, float]) -> list[tuple[float, float, float]]:
    """Points on the shape, in its own axes, whose hull is the shape seen from any side."""
    if shape in (Shape.RING, Shape.DISK):
        return _circle(d["radius"], 0)
    if shape in (Shape.CYLINDRICAL_SHELL, Shape.CYLINDER, Shape.TUBE):
        r, h = d.get("outer_radius", d.get("radius")), d["height"]
        return _circle(r, -h / 2) + _circle(r, h / 2)
    if shape is Shape.CYLINDER_SEGMENT:  # the arc within α of +y (its ends make the chord), at both ends
        r, h, a = d["radius"], d["height"], d["half_angle"]
        return [(x, y, z) for z in (-h / 2, h / 2) for x, y, _ in _arc(r, math.pi / 2 - a, math.pi / 2 + a)]
    if shape in (Shape.HALF_DISK, Shape.QUARTER_DISK):  # the centre O and the arc
        return [(0.0, 0.0, 0.0), *_arc(d["radius"], 0.0, math.pi if shape is Shape.HALF_DISK else math.pi / 2)]
    if shape in (Shape.HEMISPHERE, Shape.HEMISPHERICAL_SHELL):
        r = d["radius"]
        rings = [_circle(r * math.cos(a), r * math.sin(a)) for a in np.linspace(0, math.pi / 2, DOME_SAMPLES)]
        return [p for ring in rings for p in ring]
    if shape is Shape.CONE:
        return _circle(d["radius"], 0) + [(0.0, 0.0, d["height"])]
    if shape is Shape.BOX:
        a, b, c = d["width"] / 2, d["depth"] / 2, d["height"] / 2
        return [(x, y, z) for x in (-a, a) for y in (-b, b) for z in (-c, c)]
    if shape is Shape.PLATE:
        a, b = d["width"] / 2, d["height"] / 2
        return [(-a, -b, 0), (a, -b, 0), (a, b, 0), (-a, b, 0)]
    if shape is Shape.TRIANGLE:
        return [(0, 0, 0), (d["base"], 0, 0), (d["apex"], d["height"], 0)]
    raise AssertionError(f"no outline for {shape}")  # every shape of the library is handled above


def _circle(radius: float, z: float) -> list[tuple[float, float, float]]:
    return [(radius * math.cos(a), radius * math.sin(a), z)
            for a in np.linspace(0, 2 * math.pi, CIRCLE_SAMPLES, endpoint=False)]


def _arc(radius: float, start: float, stop: float) -> list[tuple[float, float, float]]:
    return [(radius * math.cos(a), radius * math.sin(a), 0.0) for a in np.linspace(start, stop, CIRCLE_SAMPLES)]


def convex_hull(points: list[Vec2]) -> tuple[Vec2, ...]:
    """Andrew's monotone chain, counterclockwise; collinear points give the two ends."""
    pts = sorted(set((round(x, 12), round(y, 12)) for x, y in points))
    if len(pts) <= 2:
        return tuple(pts)

    def chain(seq):
        out: list[Vec2] = []
        for p in seq:
            while len(out) >= 2 and _cross(out[-2], out[-1], p) <= 0:
                out.pop()
            out.append(p)
        return out[:-1]

    return tuple(chain(pts) + chain(reversed(pts)))


def _cross(o: Vec2, a: Vec2, b: Vec2) -> float:
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def _links(model: Model, at: Mapping[str, Vec2]) -> Iterator[Link]:
    """A link from the point each point's position starts from (the first term of a sum
    ``O + …``) to that point."""
    for point in model.problem.points:
        base = _base_point(point.position.tree) if point.position is not None else None
        if base in at and point.name in at and math.dist(at[base], at[point.name]) > 0:
            yield Link(at[base], at[point.name])


def _base_point(tree) -> str | None:
    """'O' for O + l*[…] or O - …; None when the position does not start at a point."""
    while isinstance(tree, ex.BinOp) and tree.op in ("+", "-"):
        tree = tree.left
    return tree.id if isinstance(tree, ex.Name) else None


def _ground(contact, model: Model, values: _Values, reach: float) -> Ground:
    """The fixed surface of a contact (a moving one is a body, drawn as such) at the
    picture's configuration: a circle whole; a line
    as a stretch about the contact point C, ``reach`` (the bodies' size) each way; a
    string from its fixed point to C."""
    surface = contact.source.surface
    names = model.symbols
    at = _xy(values.vector(contact.point))
    base = values.vector(names.vector(surface.point))
    if surface.radius is not None:
        return Ground(at, at, (0.0, 0.0), _xy(base), values.scalar(names.scalar(surface.radius)), surface.inside)
    d = values.vector(names.vector(surface.direction))
    d = d / np.linalg.norm(d)
    normal = (-d[1], d[0]) if not surface.inside else (d[1], -d[0])
    if contact.source.string:
        return Ground(_xy(base), at, normal, string=True)
    half = 1.5 * reach
    return Ground((at[0] - half * d[0], at[1] - half * d[1]), (at[0] + half * d[0], at[1] + half * d[1]), normal)


def _straight(contact) -> bool:
    """A body hanging straight from its drum (no pulley): its string is its hanging part."""
    return contact.source.pulley is not None and contact.source.pulley.over is None


def _hanging_part(contact, model: Model, values: _Values) -> Ground:
    """A string over a pulley: its hanging part, from the pulley's point to the body; a
    string straight from its drum, from the point C where it leaves the drum."""
    body = next(b for b in model.bodies if b.name == contact.body)
    over = contact.source.pulley.over
    top = _xy(values.vector(model.symbols.vector(over) if over is not None else contact.point))
    end = values.vector(model.symbols.vector(body.source.at))
    return Ground(top, _xy(end), (0.0, 0.0), string=True)


def _springs(model: Model, values: _Values) -> Iterator[Zigzag]:
    """Linear springs as zig-zags between their ends; a torsional spring has no place to draw."""
    names = model.symbols
    for spring in model.springs:
        ends = spring.source.ends
        if ends is not None:
            a, b = (_xy(values.vector(names.vector(e))) for e in ends)
            yield Zigzag(spring.name, zigzag(a, b))


def zigzag(a: Vec2, b: Vec2, turns: int = 6, width: float = 0.06) -> tuple[Vec2, ...]:
    """A spring from a to b: straight ends, ``turns`` teeth of half-width ``width`` × length
    (at least a small absolute width, so a short spring still reads as one)."""
    (ax, ay), (bx, by) = a, b
    dx, dy = bx - ax, by - ay
    length = math.hypot(dx, dy)
    if length == 0:
        return (a, b)
    nx, ny = -dy / length, dx / length
    w = width * length
    out = [a, (ax + 0.15 * dx, ay + 0.15 * dy)]
    for k in range(2 * turns):
        s = 0.15 + 0.7 * (k + 0.5) / (2 * turns)
        side = w if k % 2 == 0 else -w
        out.append((ax + s * dx + side * nx, ay + s * dy + side * ny))
    out += [(ax + 0.85 * dx, ay + 0.85 * dy), b]
    return tuple(out)


def _xy(v: np.ndarray) -> Vec2:
    return float(v[0]), float(v[1])


def _unit(v: np.ndarray) -> Vec2 | None:
    n = math.hypot(v[0], v[1])
    return (float(v[0] / n), float(v[1] / n)) if n > 0 else None
