"""Located nodes -> Problem. The schema is written out here, section by section.

Every error names file:line:column, the key path, what was expected and what was found.
"""

from __future__ import annotations

import keyword
from fractions import Fraction
from pathlib import Path

from rbdsolve.errors import InputError, did_you_mean
from rbdsolve.problem import expr as ex
from rbdsolve.problem.schema import (
    SHAPE_ALIASES,
    Body,
    Coordinate,
    CoordinateKind,
    Inertia,
    Parameter,
    Part,
    Point,
    Problem,
    Question,
    Shape,
    Spring,
)
from rbdsolve.problem.questions import QuestionReader
from rbdsolve.problem.readers import check_keys, describe, expect_mapping, expect_scalar, read_bool
from rbdsolve.problem.yamlnodes import Map, Node, Scalar, Seq, parse_yaml, read_text

TOP_KEYS = ("title", "source", "statement", "parameters", "coordinates", "points",
            "bodies", "springs", "gravity", "values", "questions")  # fmt: skip
# t is time; pi the constant; E and I are what sympy reads back from JSON answers as e and i.
RESERVED = {"t", "pi", "E", "I"} | set(ex.SCALAR_FUNCTIONS) | set(
    ex.DERIVATIVE_FUNCTIONS
) | ex.VECTOR_FUNCTIONS


def load_file(path: str | Path) -> Problem:
    """Read and validate one problem file."""
    name = str(path)
    try:
        data = Path(path).read_bytes()
    except FileNotFoundError:
        raise InputError(f"no such file: {name}") from None
    except IsADirectoryError:
        raise InputError(f"{name} is a folder; give a problem file") from None
    except OSError as exc:
        raise InputError(f"cannot read {name}: {exc.strerror}") from None
    return load_text(read_text(name, data), name)


def load_text(text: str, name: str = "<string>") -> Problem:
    return _Loader(name).problem(parse_yaml(text, name))


def _identifier(key: Scalar, what: str) -> str:
    name = key.text
    if keyword.iskeyword(name):
        raise InputError(f"'{name}' is a Python keyword and cannot be a name; try '{name}_'", key.loc)
    if not (name.isascii() and name.isidentifier()):
        raise InputError(f"'{name}' is not a valid {what} name (ASCII letters, digits and _, "
                         "not starting with a digit; Greek letters are spelled: theta)", key.loc)
    if name.startswith("__"):
        raise InputError("names starting with '__' are not allowed", key.loc)
    if name in RESERVED:
        raise InputError(f"'{name}' is reserved (a function, a constant or time t)", key.loc)
    return name


def _names_list(node: Node, what: str) -> list[tuple[Scalar, Node | None]]:
    """A list of names, or a mapping name -> options; returns (name node, options)."""
    if isinstance(node, Seq):
        return [(expect_scalar(item, f"a {what} name"), None) for item in node.items]
    if isinstance(node, Map):
        return [(k, None if isinstance(v, Scalar) and v.null else v) for k, v in node.entries]
    raise InputError(f"expected a list or mapping of {what}s, found {describe(node)}", node.loc)


class _Loader:
    def __init__(self, file: str):
        self.file = file
        self.scope = ex.Scope()
        self.positions = ex.Scope()
        self.taken: dict[str, str] = {}  # name -> what declared it

    # --- expressions -------------------------------------------------------------------

    def constant(self, node: Node, what: str) -> ex.Expr:
        """A scalar that must not change with the motion: parameters and numbers only."""
        scope = self.scope.constants(f"{what} must be constant (parameters and numbers only)")
        return self.expr(node, ex.Kind.SCALAR, what, scope)

    def expr(self, node: Node, kind: ex.Kind, what: str, scope: ex.Scope | None = None) -> ex.Expr:
        if isinstance(node, Seq):  # a YAML list of components is a vector literal
            if kind != ex.Kind.VECTOR:
                raise InputError(f"expected {what}, found a list", node.loc)
            return self._vector_from_list(node, what, scope)
        scalar = expect_scalar(node, what)
        if kind == ex.Kind.VECTOR:
            self._check_point_name(scalar)
        parsed = ex.parse(scalar.text, scalar.loc, scope or self.positions, scalar.plain)
        if parsed.kind != kind:
            raise InputError(f"expected {what}, found a {parsed.kind.value} '{parsed.text}'", scalar.loc)
        return parsed

    def _check_point_name(self, node: Scalar) -> None:
        name = node.text.strip()
        if name.isidentifier() and name not in self.scope.all_names() and name not in ex.CONSTANTS:
            hint = did_you_mean(name, sorted(self.scope.vectors))
            raise InputError(f"unknown point '{name}'{hint}", node.loc)

    def _vector_from_list(self, node: Seq, what: str, scope: ex.Scope | None) -> ex.Expr:
        if len(node.items) not in (2, 3):
            raise InputError(f"a vector has 2 or 3 components, found {len(node.items)}", node.loc)
        parts = [self.expr(item, ex.Kind.SCALAR, "a number or scalar expression", scope)
                 for item in node.items]
        text = "[" + ", ".join(p.text for p in parts) + "]"
        return ex.Expr(ex.Vec(tuple(p.tree for p in parts)), ex.Kind.VECTOR, text, node.loc)

    def declare(self, key: Scalar, what: str) -> str:
        name = _identifier(key, what)
        if name in self.taken:
            raise InputError(f"'{name}' is already declared as a {self.taken[name]}", key.loc)
        self.taken[name] = what
        return name

    # --- sections ----------------------------------------------------------------------

    def problem(self, root: Map) -> Problem:
        check_keys(root, ("questions",), TOP_KEYS, "the problem")
        get = root.get
        parameters = self.parameters(get("parameters"))
        coordinates = self.coordinates(get("coordinates"))
        # Positions and angles may use coordinates and time t; rates (dot, ddot) are for
        # questions that need velocities, and none does yet.
        self.scope = ex.Scope(
            scalars=frozenset({p.name for p in parameters} | {c.name for c in coordinates} | {"t"}),
            functions_of_time=frozenset(c.name for c in coordinates),
        )
        self.positions = ex.Scope(self.scope.scalars, self.scope.vectors)
        points = self.points(get("points"))
        bodies = self.bodies(get("bodies"))
        return Problem(
            file=self.file,
            title=self.text(get("title"), "a title") or Path(self.file).stem,
            source=self.text(get("source"), "a source"),
            statement=self.text(get("statement"), "a statement"),
            parameters=parameters,
            coordinates=coordinates,
            points=points,
            bodies=bodies,
            springs=self.springs(get("springs")),
            gravity=self.gravity(get("gravity")),
            values=self.values(get("values"), parameters),
            questions=self.questions(get("questions"), coordinates, bodies),
        )

    def text(self, node: Node | None, what: str) -> str:
        if node is None or (isinstance(node, Scalar) and node.null):
            return ""
        return expect_scalar(node, what).text.strip()

    def optional_expr(self, node: Node | None, kind: ex.Kind, what: str) -> ex.Expr | None:
        if node is None or (isinstance(node, Scalar) and node.null):
            return None
        return self.expr(node, kind, what, self.positions)

    def optional_constant(self, node: Node | None, what: str) -> ex.Expr | None:
        if node is None or (isinstance(node, Scalar) and node.null):
            return None
        return self.constant(node, what)

    def gravity(self, node: Node | None) -> ex.Expr | None:
        if node is None or (isinstance(node, Scalar) and node.null):
            return None
        scope = self.scope.constants("gravity must be constant (parameters and numbers only)")
        return self.expr(node, ex.Kind.VECTOR, "a gravity vector such as [0, -g]", scope)

    def parameters(self, node: Node | None) -> tuple[Parameter, ...]:
        if node is None:
            return ()
        out = []
        for key, options in _names_list(node, "parameter"):
            name = self.declare(key, "parameter")
            description, positive = "", True
            if isinstance(options, Scalar):
                description = options.text
                if ex.is_number_text(description):
                    raise InputError(f"a parameter's description is text; to give {name} a value "
                                     f"write 'values: {{{name}: {description}}}'", options.loc)
            elif options is not None:
                opts = expect_mapping(options, "parameter options")
                check_keys(opts, (), ("description", "positive"), f"parameter '{name}'")
                description = self.text(opts.get("description"), "a description")
                if opts.get("positive") is not None:
                    positive = read_bool(opts.get("positive"), "true or false")
            out.append(Parameter(name, description, positive, key.loc))
        return tuple(out)

    def coordinates(self, node: Node | None) -> tuple[Coordinate, ...]:
        if node is None:
            return ()
        out = []
        for key, options in _names_list(node, "coordinate"):
            name = self.declare(key, "coordinate")
            kind = CoordinateKind.AUTO
            if options is not None:
                word = expect_scalar(options, "a coordinate kind ('angle' or 'length')")
                try:
                    kind = CoordinateKind(word.text)
                except ValueError:
                    raise InputError(
                        f"unknown coordinate kind '{word.text}' (expected angle or length)"
                        f"{did_you_mean(word.text, ['angle', 'length'])}",
                        word.loc,
                    ) from None
            out.append(Coordinate(name, kind, key.loc))
        return tuple(out)

    def points(self, node: Node | None) -> tuple[Point, ...]:
        if node is None:
            return ()
        table = expect_mapping(node, "points: name -> position vector")
        names = [self.declare(key, "point") for key, _ in table.entries]
        self.scope = ex.Scope(self.scope.scalars, frozenset(names), self.scope.functions_of_time)
        self.positions = ex.Scope(self.scope.scalars, self.scope.vectors)
        parsed = {
            key.text: self.expr(value, ex.Kind.VECTOR, f"the position of point '{key.text}' (a vector)",
                                self.positions)
            for key, value in table.entries
        }
        return tuple(Point(name, parsed[name]) for name in _dependency_order(parsed))

    def bodies(self, node: Node | None) -> tuple[Body, ...]:
        if node is None:
            return ()
        table = expect_mapping(node, "bodies: name -> body")
        return tuple(self.body(self.declare(k, "body"), v) for k, v in table.entries)

    def body(self, name: str, node: Node) -> Body:
        spec = expect_mapping(node, f"body '{name}'")
        what = f"body '{name}'"
        at = self.expr(spec.get("at"), ex.Kind.VECTOR, "a point name or position vector", self.positions) \
            if spec.get("at") is not None else None
        angle = self.optional_expr(spec.get("angle"), ex.Kind.SCALAR, "an angle (a scalar expression)")
        if spec.get("parts") is None:
            part = self.part(name, spec, what, ("angle",), simple=True)
            return Body(name, (part,), at, angle, spec.loc)
        check_keys(spec, ("parts", "at"), ("angle",), what)
        table = expect_mapping(spec.get("parts"), "parts: name -> part")
        if not table.entries:
            raise InputError(f"{what} has no parts", table.loc)
        parts = tuple(self.part(k.text, expect_mapping(v, f"part '{k.text}'"), f"part '{k.text}' of {what}", (),
                                simple=False) for k, v in table.entries)
        if all(p.hole for p in parts):
            raise InputError(f"{what} is all holes: give at least one solid part", table.loc)
        return Body(name, parts, at, angle, spec.loc)

    def part(self, name: str, spec: Map, what: str, extra: tuple[str, ...], simple: bool) -> Part:
        shape = self.shape(spec, what)
        dims = shape.dimensions if shape else ()
        _check_dimensions(spec, shape, what)
        required = ("mass", "at", *dims) if simple else ("mass", *dims)
        check_keys(spec, required, ("shape", "axis", "inertia", *extra, *(() if simple else ("at", "hole"))), what)
        mass = self.constant(spec.get("mass"), "a mass")
        _refuse_negative(mass, "mass")
        dimensions = []
        for dim in dims:
            value = self.constant(spec.get(dim), f"a {dim}")
            if dim not in POSITIONS:
                _refuse_negative(value, dim)
            dimensions.append((dim, value))
        axis_node = spec.get("axis")
        if axis_node is not None and shape is None:
            raise InputError("'axis' orients a shape; an explicit inertia is already in body axes",
                             axis_node.loc)
        at = None
        if not simple and spec.get("at") is not None:
            scope = self.scope.constants("a part's position in its body must be constant")
            at = self.expr(spec.get("at"), ex.Kind.VECTOR, "a position in the body (a vector)", scope)
        hole = read_bool(spec.get("hole"), "true or false") if spec.get("hole") is not None else False
        return Part(name, shape, mass, tuple(dimensions), at,
                    self.axis(axis_node) if axis_node is not None else None,
                    self.inertia(spec.get("inertia")), hole, spec.loc)

    def axis(self, node: Node) -> ex.Expr:
        """x, y, z (or -x, …) or a direction vector in body axes."""
        if isinstance(node, Scalar) and node.text.strip() in _AXES:
            text = node.text.strip()
            tree = ex.Vec(tuple(ex.Num(Fraction(v)) for v in _AXES[text]))
            return ex.Expr(tree, ex.Kind.VECTOR, text, node.loc)
        if isinstance(node, Scalar) and node.text.strip().lstrip("-").isidentifier():
            raise InputError(f"expected an axis x, y, z, -x, -y, -z or a direction vector, "
                             f"found '{node.text.strip()}'", node.loc)
        scope = self.scope.constants("an axis must be constant (parameters and numbers only)")
        value = self.expr(node, ex.Kind.VECTOR, "an axis: x, y, z or a direction vector", scope)
        if isinstance(value.tree, ex.Vec) and all(ex.constant_value(c) == 0 for c in value.tree.items):
            raise InputError("an axis direction must not be the zero vector", value.loc)
        return value

    def shape(self, spec: Map, what: str) -> Shape | None:
        node = spec.get("shape")
        if node is None:
            if spec.get("inertia") is None:
                raise InputError(f"{what} needs a 'shape' (or an explicit 'inertia')", spec.loc)
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
            hint = did_you_mean(word, names) or f" (shapes: {', '.join(s.value for s in Shape)})"
            raise InputError(f"unknown shape '{word}'{hint}", node.loc) from None

    def inertia(self, node: Node | None) -> Inertia | None:
        if node is None:
            return None
        if isinstance(node, Scalar):
            return Inertia((self.constant(node, "a moment of inertia"),), node.loc)
        if isinstance(node, Seq) and len(node.items) == 3 and all(isinstance(i, Seq) for i in node.items):
            rows = [row for row in node.items]
            if any(len(r.items) != 3 for r in rows):
                raise InputError("an inertia matrix is 3x3", node.loc)
            entries = [self.constant(x, "an inertia matrix entry") for r in rows for x in r.items]
            return Inertia(tuple(entries), node.loc)
        if isinstance(node, Seq) and len(node.items) == 3:
            return Inertia(tuple(self.constant(x, "a principal moment") for x in node.items), node.loc)
        raise InputError(
            "expected an inertia: J (planar), [J1, J2, J3] or a 3x3 matrix", node.loc
        )

    def springs(self, node: Node | None) -> tuple[Spring, ...]:
        if node is None:
            return ()
        table = expect_mapping(node, "springs: name -> spring")
        return tuple(self.spring(self.declare(k, "spring"), v) for k, v in table.entries)

    def spring(self, name: str, node: Node) -> Spring:
        what = f"spring '{name}'"
        spec = expect_mapping(node, what)
        check_keys(spec, ("stiffness",), ("between", "natural_length", "angle", "rest"), what)
        between, angle = spec.get("between"), spec.get("angle")
        if (between is None) == (angle is None):
            raise InputError(f"{what} needs either 'between: [A, B]' (linear) or 'angle:' (torsional)", spec.loc)
        stiffness = self.constant(spec.get("stiffness"), "a stiffness")
        _refuse_negative(stiffness, "stiffness")
        ends = None
        if between is not None:
            if not isinstance(between, Seq) or len(between.items) != 2:
                raise InputError(f"expected two ends [A, B], found {describe(between)}", between.loc)
            ends = tuple(self.expr(e, ex.Kind.VECTOR, "a point name or position vector", self.positions)
                         for e in between.items)
        elif spec.get("natural_length") is not None:
            raise InputError("'natural_length' belongs to a linear spring; use 'rest' with 'angle'", spec.get("natural_length").loc)
        if between is not None and spec.get("rest") is not None:
            raise InputError("'rest' belongs to a torsional spring; use 'natural_length' with 'between'", spec.get("rest").loc)
        return Spring(
            name=name,
            stiffness=stiffness,
            ends=ends,
            natural_length=self.optional_constant(spec.get("natural_length"), "a natural length"),
            angle=self.optional_expr(angle, ex.Kind.SCALAR, "an angle expression"),
            rest=self.optional_constant(spec.get("rest"), "a rest angle"),
            loc=spec.loc,
        )

    def values(self, node: Node | None, parameters: tuple[Parameter, ...]) -> tuple[tuple[str, Fraction], ...]:
        if node is None:
            return ()
        table = expect_mapping(node, "values: parameter -> number")
        known = [p.name for p in parameters]
        out = []
        for key, value in table.entries:
            if key.text not in known:
                raise InputError(f"'{key.text}' is not a parameter{did_you_mean(key.text, known)}", key.loc)
            scalar = expect_scalar(value, "a number")
            number = ex.parse_number(scalar.text, scalar.loc, scalar.plain)
            param = next(p for p in parameters if p.name == key.text)
            if param.positive and number <= 0:
                raise InputError(f"'{key.text}' is declared positive, found {scalar.text}", scalar.loc)
            out.append((key.text, number))
        return tuple(out)

    def questions(self, node: Node, coordinates: tuple[Coordinate, ...],
                  bodies: tuple[Body, ...]) -> tuple[Question, ...]:
        if not isinstance(node, Seq) or not node.items:
            found = "an empty list" if isinstance(node, Seq) else describe(node)
            raise InputError(f"expected a list of questions, found {found}", node.loc)
        reader = QuestionReader(self, coordinates, bodies)
        return tuple(reader.question(item) for item in node.items)


_AXES = {"x": (1, 0, 0), "y": (0, 1, 0), "z": (0, 0, 1),
         "-x": (-1, 0, 0), "-y": (0, -1, 0), "-z": (0, 0, -1)}


def _check_dimensions(spec: Map, shape: Shape | None, what: str) -> None:
    """A dimension that belongs to other shapes: say which ones this shape takes."""
    others = {d for s in Shape for d in s.dimensions}
    mine = shape.dimensions if shape else ()
    for key, _ in spec.entries:
        if key.text in others and key.text not in mine:
            takes = ", ".join(mine) if mine else "no dimensions"
            kind = f"a {shape.value}" if shape else "a body with an explicit inertia"
            raise InputError(f"{kind} takes {takes}, not '{key.text}' (in {what})", key.loc)


# Shape dimensions that are positions, not sizes: any sign is fine.
POSITIONS = {"apex"}


def _refuse_negative(value: ex.Expr, what: str) -> None:
    number = ex.constant_value(value.tree)
    if number is not None and number < 0:
        raise InputError(f"a {what} must not be negative, found {value.text}", value.loc)


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
