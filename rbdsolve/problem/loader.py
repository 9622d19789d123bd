"""Located nodes -> Problem. The schema is written out here, section by section.

Every error names file:line:column, the key path, what was expected and what was found.
The sections most files leave out (contacts, springs, forces and couples, frames,
prescribed quantities, assumptions) import their readers and problem/scene.py's classes
where a file has them: a file without them creates none of those classes (Python
generates each frozen dataclass's methods at import, ~0.3 ms a class).
"""

from __future__ import annotations

import re
from fractions import Fraction
from pathlib import Path
from typing import TYPE_CHECKING

from rbdsolve.errors import InputError, did_you_mean
from rbdsolve.problem import expr as ex
from rbdsolve.problem.schema import Body, Coordinate, Parameter, Point, Problem, Question, QuestionKind, ValueRange
from rbdsolve.problem.surfaces import SurfaceKind
from rbdsolve.problem.sections.bodies import BodyReader, refuse_negative
from rbdsolve.problem.context import Reading
from rbdsolve.problem.sections.coordinates import coordinate, declared_ranges
from rbdsolve.problem.sections.orientation import OrientationReader
from rbdsolve.problem.sections.questions import QuestionReader
from rbdsolve.problem.quantities.dimensions import scene_dimensions
from rbdsolve.problem.usage import time_rates
from rbdsolve.problem.quantities.quantity import LENGTH, NUMBER, Dimension, Value, parse_unit
from rbdsolve.problem.quantities.ranges import parameter_value, value_range
from rbdsolve.problem.readers import check_keys, describe, expect_mapping, expect_scalar, read_bool
from rbdsolve.problem.yamlnodes import Map, Node, Scalar, Seq, parse_yaml, read_bytes, read_text

if TYPE_CHECKING:
    from rbdsolve.problem.scene import Assumption, Contact, Couple, Force, Frame, Prescribed, Spring

RATE = Dimension(time=Fraction(-1))  # a rate, 1/s

TOP_KEYS = ("title", "source", "statement", "parameters", "prescribed", "unknowns", "coordinates", "triads",
            "points", "frames",
            "bodies", "contacts", "springs", "forces", "couples", "gravity", "values", "assumptions",
            "questions")  # fmt: skip
# keys a student may write for a section under another name: said so, not "unknown key"
SECTION_ALIASES = {"torques": "couples", "torque": "couples", "moments": "couples", "couple": "couples",
                   "force": "forces", "loads": "forces", "applied_forces": "forces", "applied": "forces"}


def load_file(path: str | Path) -> Problem:
    """Read and validate one problem file."""
    name = str(path)
    try:
        data = read_bytes(name)
    except FileNotFoundError:
        raise InputError(f"no such file: {name}") from None
    except IsADirectoryError:
        raise InputError(f"{name} is a folder; give a problem file") from None
    except OSError as exc:
        raise InputError(f"cannot read {name}: {exc.strerror}") from None
    return load_text(read_text(name, data), name)


def load_text(text: str, name: str = "<string>") -> Problem:
    return _Loader(name).problem(parse_yaml(text, name))


def _given(node: Node | None) -> Node | None:
    """A key's value, or None when the key is missing or null."""
    return None if node is None or (isinstance(node, Scalar) and node.null) else node


def _names_list(node: Node, what: str) -> list[tuple[Scalar, Node | None]]:
    """A list of names, or a mapping name -> options; returns (name node, options)."""
    if isinstance(node, Seq):
        return [(expect_scalar(item, f"a {what} name"), None) for item in node.items]
    if isinstance(node, Map):
        return [(k, None if isinstance(v, Scalar) and v.null else v) for k, v in node.entries]
    raise InputError(f"expected a list or mapping of {what}s, found {describe(node)}", node.loc)


class _Loader:
    def __init__(self, file: str):
        self.reading = Reading(file)

    # --- sections ----------------------------------------------------------------------

    def problem(self, root: Map) -> Problem:
        _section_aliases(root)
        check_keys(root, ("questions",), TOP_KEYS, "the problem")
        get = root.get
        parameters = self.parameters(get("parameters"))
        prescribed = self.prescribed(get("prescribed"), parameters)
        unknowns = self.unknowns(get("unknowns"))
        coordinates, range_nodes = self.coordinates(get("coordinates"))
        self.reading.coordinates = tuple(c.name for c in coordinates)
        # Positions and angles may use coordinates, prescribed functions and time t;
        # velocities at an instant use parameters and the rates dot(q).
        moving = {c.name for c in coordinates} | {p.name for p in prescribed}
        self.reading.scope = ex.Scope(
            scalars=frozenset({p.name for p in parameters} | set(unknowns) | moving | {"t"}),
            functions_of_time=frozenset(moving),
        )
        self.reading.set_point_scopes(frozenset(), frozenset())
        coordinates = declared_ranges(self.reading, coordinates, range_nodes)
        triads = OrientationReader(self.reading).triads(get("triads"))
        self.reading.triad_vectors = frozenset(v for tr in triads for v in tr.vectors)
        self.reading.triad_names = tuple(tr.name for tr in triads)
        self.reading.later = _later_points(get("bodies"))
        self.reading.set_point_scopes(frozenset(), frozenset())
        points = self.points(get("points"))
        frames = self.frames(get("frames"))
        bodies, contacts = self.bodies_and_contacts(get("bodies"), get("contacts"))
        self.reading.add_positions(frozenset(c.name for c in contacts if c.surface.kind is SurfaceKind.PLANE))
        self.reading.add_body_points(bodies)  # a body's origin (its name) and its own points, from here on
        springs, gravity = self.springs(get("springs")), self.gravity(get("gravity"))
        forces, couples = self.loads(get("forces"), get("couples"), bodies)
        questions = self.questions(get("questions"), coordinates, bodies, points + _body_points(bodies), frames,
                                   contacts)
        collisions = tuple(c for q in questions if q.kind is QuestionKind.IMPACT for c in q.options.collisions)
        known = _known_dimensions(parameters, bodies, springs, gravity, points, forces, couples, contacts, collisions)
        for name, where in time_rates((triads, frames, points, bodies, prescribed, forces, couples, contacts),
                                      frozenset(p.name for p in parameters)).items():
            known.setdefault(name, (RATE, where))  # Ω in a turn Ω t: 1/s (rad/s), as its unit would say
        values, ranges = self.values(get("values"), parameters, known)
        return Problem(
            file=self.reading.file,
            title=self.reading.text(get("title"), "a title") or Path(self.reading.file).stem,
            source=self.reading.text(get("source"), "a source"),
            statement=self.reading.text(get("statement"), "a statement"),
            parameters=parameters,
            coordinates=coordinates,
            points=points,
            bodies=bodies,
            springs=springs,
            gravity=gravity,
            values=values,
            questions=questions,
            prescribed=prescribed,
            frames=frames,
            unknowns=unknowns,
            triads=triads,
            ranges=ranges,
            assumptions=self.assumptions(get("assumptions")),
            contacts=contacts,
            dimensions=_dimensions(known, values, ranges),
            forces=forces,
            couples=couples,
        )

    def assumptions(self, node: Node | None) -> tuple[Assumption, ...]:
        """A list of inequalities between constant expressions: [R > r, a < 2*R]."""
        if node is None or (isinstance(node, Scalar) and node.null):
            return ()
        if not isinstance(node, Seq):
            raise InputError(f"'assumptions' takes a list of inequalities such as [R > r], found {describe(node)}",
                             node.loc)
        return tuple(self.assumption(item) for item in node.items)

    def assumption(self, node: Node) -> Assumption:
        scalar = expect_scalar(node, "an inequality such as R > r")
        text = scalar.text
        found = [(m.start(), m.group()) for m in re.finditer(r"<=|>=|<|>", text)]
        if len(found) != 1:
            raise InputError(f"an assumption is one inequality between parameter expressions, such as 'R > r' "
                             f"or 'a <= 2*R'; found {'no' if not found else len(found)} comparison"
                             f"{'s' if len(found) > 1 else ''} in '{text[:60]}'", scalar.loc)
        (at, op), = found
        scope = self.reading.scope.constants("an assumption is between constants (parameters and numbers only)")
        left = ex.parse(text[:at], scalar.loc, scope, scalar.plain)
        right = ex.parse(text[at + len(op):], scalar.loc.shifted(at + len(op)) if scalar.plain else scalar.loc,
                         scope, scalar.plain)
        for side in (left, right):
            if side.kind is not ex.Kind.SCALAR:
                raise InputError(f"an assumption compares scalars; '{side.text}' is a {side.kind.value}", scalar.loc)
        from rbdsolve.problem.scene import Assumption

        return Assumption(left, op, right, text.strip(), scalar.loc)

    def gravity(self, node: Node | None) -> ex.Expr | None:
        if node is None or (isinstance(node, Scalar) and node.null):
            return None
        scope = self.reading.scope.constants("gravity must be constant (parameters and numbers only)")
        return self.reading.expr(node, ex.Kind.VECTOR, "a gravity vector such as [0, -g]", scope)

    def parameters(self, node: Node | None) -> tuple[Parameter, ...]:
        if node is None:
            return ()
        out = []
        for key, options in _names_list(node, "parameter"):
            name = self.reading.declare(key, "parameter")
            description, positive, unit = "", True, None
            if isinstance(options, Scalar):
                description = options.text
                if ex.is_number_text(description):
                    raise InputError(f"a parameter's description is text; to give {name} a value "
                                     f"write 'values: {{{name}: {description}}}'", options.loc)
            elif options is not None:
                opts = expect_mapping(options, "parameter options")
                check_keys(opts, (), ("description", "positive", "unit"), f"parameter '{name}'")
                description = self.reading.text(opts.get("description"), "a description")
                if opts.get("positive") is not None:
                    positive = read_bool(opts.get("positive"), "true or false")
                if opts.get("unit") is not None:
                    written = expect_scalar(opts.get("unit"), "a unit such as cm, kg or rev/min")
                    unit = parse_unit(written.text, written.loc, written.plain)
            out.append(Parameter(name, description, positive, key.loc, unit))
        return tuple(out)

    def prescribed(self, node: Node | None, parameters: tuple[Parameter, ...]) -> tuple[Prescribed, ...]:
        """name -> 'unknown' (a function y_A(t) kept symbolic) or an expression in t."""
        if node is None:
            return ()
        from rbdsolve.problem.scene import Prescribed

        table = expect_mapping(node, "prescribed: name -> unknown, or an expression in t")
        scope = ex.Scope(frozenset({p.name for p in parameters} | {"t"}))
        out = []
        for key, value in table.entries:
            name = self.reading.declare(key, "prescribed function")
            if isinstance(value, Scalar) and value.text.strip() == "unknown":
                out.append(Prescribed(name, None, key.loc))
            else:
                what = f"'unknown' or an expression in t and the parameters for '{name}'"
                out.append(Prescribed(name, self.reading.expr(value, ex.Kind.SCALAR, what, scope), key.loc))
        return tuple(out)

    def unknowns(self, node: Node | None) -> tuple[str, ...]:
        """Constant unknowns (a steady spin rate), found by the questions that need them."""
        if node is None:
            return ()
        return tuple(self.reading.declare(key, "unknown") for key, _ in _names_list(node, "unknown"))

    def coordinates(self, node: Node | None) -> tuple[tuple[Coordinate, ...], dict[str, Node]]:
        """The coordinates, and the nodes of their ranges (read once the scope is set)."""
        if node is None:
            return (), {}
        out, range_nodes = [], {}
        for key, options in _names_list(node, "coordinate"):
            name = self.reading.declare(key, "coordinate")
            found, range_node = coordinate(self.reading, name, key, options)
            out.append(found)
            if range_node is not None:
                range_nodes[name] = range_node
        return tuple(out), range_nodes

    def points(self, node: Node | None) -> tuple[Point, ...]:
        if node is None:
            return ()
        table = expect_mapping(node, "points: name -> position vector, or {velocity: vector}")
        names = [self.reading.declare(key, "point") for key, _ in table.entries]
        moving = {k.text for k, v in table.entries if isinstance(v, Map)}
        self.reading.set_point_scopes(frozenset(n for n in names if n not in moving), frozenset(moving))
        positions, velocities = {}, {}
        for key, value in table.entries:
            if key.text in moving:
                check_keys(value, ("velocity",), (), f"point '{key.text}'")
                velocities[key.text] = self.reading.expr(value.get("velocity"), ex.Kind.VECTOR,
                                                 f"the velocity of point '{key.text}' (a vector)", self.reading.rates)
            else:
                positions[key.text] = self.reading.expr(value, ex.Kind.VECTOR,
                                                f"the position of point '{key.text}' (a vector)", self.reading.positions)
        self.reading.point_exprs = positions
        return (tuple(Point(name, positions[name]) for name in _dependency_order(positions))
                + tuple(Point(name, None, velocities[name]) for name in _dependency_order(velocities)))

    def frames(self, node: Node | None) -> tuple[Frame, ...]:
        """name -> {origin: point or vector in t, axis: x|y|z|vector, rate: constant}."""
        if node is None:
            return ()
        from rbdsolve.problem.scene import Frame

        table = expect_mapping(node, "frames: name -> frame")
        out = []
        for key, value in table.entries:
            name = self.reading.declare(key, "frame")
            spec = expect_mapping(value, f"frame '{name}'")
            check_keys(spec, (), ("origin", "axis", "rate"), f"frame '{name}'")
            origin, axis, rate = (_given(spec.get(k)) for k in ("origin", "axis", "rate"))
            if (axis is None) != (rate is None):
                raise InputError(f"a turning frame needs both 'axis' and 'rate' (frame '{name}')", spec.loc)
            if origin is not None:
                origin = self.reading.expr(origin, ex.Kind.VECTOR, "the frame's origin (a point or a vector)")
                moving = sorted(frozenset(self.reading.coordinates) & self.reading.point_names(origin))
                if moving:
                    raise InputError(f"frame '{name}' must move in a given way, but its origin depends on the "
                                     f"coordinate {moving[0]}", origin.loc)
            out.append(Frame(name, origin, self.reading.axis(axis) if axis is not None else None,
                             self.reading.constant(rate, "a rate of turning") if rate is not None else None, spec.loc))
        return tuple(out)

    def bodies(self, node: Node | None, placed: dict[str, str], hanging: frozenset[str] = frozenset()
               ) -> tuple[Body, ...]:
        """The bodies; those in ``placed`` (body -> contact) are placed by rolling, or
        hang from a drum (``hanging``)."""
        if node is None:
            return ()
        table = expect_mapping(node, "bodies: name -> body")
        reader = BodyReader(self.reading, placed, hanging)
        out = []
        for k, v in table.entries:
            out.append(reader.body(self.reading.declare(k, "body"), v))
            self.reading.add_body_points(out[-1:])  # a later body may sit at this one's points
        return tuple(out)

    def bodies_and_contacts(self, bodies: Node | None, contacts: Node | None
                            ) -> tuple[tuple[Body, ...], tuple[Contact, ...]]:
        """The bodies, and the contacts that place some of them (read before the bodies,
        so that those know they are placed by rolling or hang from a drum)."""
        if contacts is None:
            return self.bodies(bodies, {}), ()
        from rbdsolve.problem.sections.contacts import ContactReader, contact_bodies, hanging_bodies

        names = [k.text for k, _ in bodies.entries] if isinstance(bodies, Map) else None
        read = self.bodies(bodies, contact_bodies(contacts, names), hanging_bodies(contacts))
        return read, ContactReader(self.reading).contacts(contacts, read)

    def loads(self, forces: Node | None, couples: Node | None,
              bodies: tuple[Body, ...]) -> tuple[tuple[Force, ...], tuple[Couple, ...]]:
        """The applied forces and couples on the bodies."""
        if forces is None and couples is None:
            return (), ()
        from rbdsolve.problem.sections.loads import LoadReader

        loads = LoadReader(self.reading, bodies)
        return loads.forces(forces), loads.couples(couples)

    def springs(self, node: Node | None) -> tuple[Spring, ...]:
        if node is None:
            return ()
        table = expect_mapping(node, "springs: name -> spring")
        return tuple(self.spring(self.reading.declare(k, "spring"), v) for k, v in table.entries)

    def spring(self, name: str, node: Node) -> Spring:
        from rbdsolve.problem.scene import Spring

        what = f"spring '{name}'"
        spec = expect_mapping(node, what)
        check_keys(spec, ("stiffness",), ("between", "natural_length", "angle", "rest"), what)
        between, angle = spec.get("between"), spec.get("angle")
        if (between is None) == (angle is None):
            raise InputError(f"{what} needs either 'between: [A, B]' (linear) or 'angle:' (torsional)", spec.loc)
        stiffness = self.reading.constant(spec.get("stiffness"), "a stiffness")
        refuse_negative(stiffness, "stiffness")
        ends = None
        if between is not None:
            if not isinstance(between, Seq) or len(between.items) != 2:
                raise InputError(f"expected two ends [A, B], found {describe(between)}", between.loc)
            ends = tuple(self.reading.expr(e, ex.Kind.VECTOR, "a point name or position vector", self.reading.positions)
                         for e in between.items)
        elif spec.get("natural_length") is not None:
            raise InputError("'natural_length' belongs to a linear spring; use 'rest' with 'angle'", spec.get("natural_length").loc)
        if between is not None and spec.get("rest") is not None:
            raise InputError("'rest' belongs to a torsional spring; use 'natural_length' with 'between'", spec.get("rest").loc)
        return Spring(
            name=name,
            stiffness=stiffness,
            ends=ends,
            natural_length=self.reading.optional_measured(spec.get("natural_length"), "a natural length",
                                                          (LENGTH,), "a length such as 20 cm"),
            angle=self.reading.optional_expr(angle, ex.Kind.SCALAR, "an angle expression"),
            rest=self.reading.optional_measured(spec.get("rest"), "a rest angle", (NUMBER,), "an angle such as 30 deg"),
            loc=spec.loc,
        )

    def values(self, node: Node | None, parameters: tuple[Parameter, ...], dims: dict[str, tuple[Dimension, str]]
               ) -> tuple[tuple[tuple[str, Value], ...], tuple[ValueRange, ...]]:
        """Values, and the ranges or choices to draw per exam variant (problem/quantities/ranges.py)."""
        if node is None:
            return (), ()
        table = expect_mapping(node, "values: parameter -> number")
        known = [p.name for p in parameters]
        numbers, ranges = [], []
        for key, value in table.entries:
            if key.text not in known:
                raise InputError(f"'{key.text}' is not a parameter{did_you_mean(key.text, known)}", key.loc)
            param = next(p for p in parameters if p.name == key.text)
            if isinstance(value, Map):
                ranges.append(value_range(param, value, dims.get(param.name)))
                continue
            scalar = expect_scalar(value, "a number")
            numbers.append((key.text, parameter_value(param, scalar.text, scalar.loc, scalar.plain,
                                                      dims.get(param.name))))
        return tuple(numbers), tuple(ranges)

    def questions(self, node: Node, coordinates: tuple[Coordinate, ...], bodies: tuple[Body, ...],
                  points: tuple[Point, ...], frames: tuple[Frame, ...],
                  contacts: tuple = ()) -> tuple[Question, ...]:
        if not isinstance(node, Seq) or not node.items:
            found = "an empty list" if isinstance(node, Seq) else describe(node)
            raise InputError(f"expected a list of questions, found {found}", node.loc)
        reader = QuestionReader(self.reading, coordinates, bodies, points, tuple(f.name for f in frames), contacts)
        return tuple(reader.question(item) for item in node.items)




def _section_aliases(root: Map) -> None:
    """A section under a name the format does not use (``torques:``): name the one it uses."""
    for key, _ in root.entries:
        if key.text in SECTION_ALIASES:
            raise InputError(f"unknown key '{key.text}' in the problem: applied loads go under "
                             f"'{SECTION_ALIASES[key.text]}:' (forces: name -> {{on, at, force}}; couples, torques "
                             "and motors: name -> {on, by, moment})", key.loc)


def _later_points(node: Node | None) -> tuple[tuple[str, str], ...]:
    """The bodies' names and their own points, read ahead: the scene's points and the
    bodies' places are written before the bodies are placed, so they cannot name them
    (said so, rather than 'unknown symbol')."""
    if not isinstance(node, Map):
        return ()
    out = []
    for key, spec in node.entries:
        out.append((key.text, f"it names body '{key.text}', whose origin (its centre) springs, forces, the "
                              "questions and the bodies listed after it may use; the scene's points come before "
                              "the bodies are placed, so they cannot: write the position from the scene's points"))
        own = spec.get("points") if isinstance(spec, Map) else None
        if isinstance(own, Map):
            out += [(k.text, f"it is a point of body '{key.text}' (under its 'points:'), placed with the body: "
                             "springs, forces, the questions and the bodies listed after it may use it, but the "
                             "scene's points cannot; write the position from the scene's points")
                    for k, _ in own.entries]
    return tuple(out)


def _body_points(bodies: tuple[Body, ...]) -> tuple[Point, ...]:
    """The bodies' origins (by the body's name) and their own points, as named points the
    questions may ask about. The questions read only the names: each position here is
    the point's offset in its body (the model places it)."""
    out = []
    for b in bodies:
        if b.velocity is None:
            out.append(Point(b.name, b.at or ex.Expr(ex.Vec((ex.Num(Fraction(0)),) * 2), ex.Kind.VECTOR, "[0, 0]",
                                                      b.loc)))
            out += [Point(name, offset) for name, offset in b.points]
    return tuple(out)


def _known_dimensions(parameters: tuple[Parameter, ...], bodies: tuple[Body, ...], springs: tuple[Spring, ...],
                      gravity: ex.Expr | None, points: tuple[Point, ...], forces: tuple = (),
                      couples: tuple = (), contacts: tuple = (), collisions: tuple = ()) -> dict[str, tuple[Dimension, str]]:
    """Each parameter's dimension where the file fixes it: its declared unit first, then
    the scene (problem/quantities/dimensions.py)."""
    positions = tuple(p.position for p in points if p.position is not None)
    positions += tuple(b.at for b in bodies if b.at is not None)
    known = scene_dimensions(frozenset(p.name for p in parameters), bodies, springs, gravity, positions, forces,
                             couples, contacts, collisions)
    for p in parameters:
        if p.unit is not None:
            known[p.name] = (p.unit.dimension, f"its unit {p.unit.text}")
    return known


def _dimensions(known: dict[str, tuple[Dimension, str]], values: tuple[tuple[str, Value], ...],
                ranges: tuple[ValueRange, ...]) -> tuple[tuple[str, Dimension], ...]:
    """Every parameter's known dimension: from the file, else from its value's unit."""
    out = {name: dimension for name, (dimension, _) in known.items()}
    given = [*values, *((r.name, r.low) for r in ranges)]
    out.update({name: v.dimension for name, v in given if name not in out and v.dimension is not None})
    return tuple(sorted(out.items()))


def _dependency_order(points: dict[str, ex.Expr]) -> list[str]:
    """Points sorted so each one only names points before it; cycles are errors."""
    order: list[str] = []
    state: dict[str, str] = {}

    def visit(name: str, trail: list[str]) -> None:
        if state.get(name) == "done":
            return
        if state.get(name) == "active":
            cycle = trail[trail.index(name):] + [name]
            raise InputError(f"cyclic point definitions: {' -> '.join(cycle)}", points[name].loc)
        state[name] = "active"
        for other in sorted(points[name].names() & points.keys()):
            visit(other, [*trail, name])
        state[name] = "done"
        order.append(name)

    for name in points:
        visit(name, [])
    return order
