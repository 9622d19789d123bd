"""The reading context of one problem file: what the sections read so far, and how
an expression is read there.

The loader makes one ``Reading`` per file and hands it to each section's reader
(bodies, orientation, questions, impact). It holds the scopes of names an expression
may use (positions, velocities at an instant, constants), the names declared so far
(one name, one meaning), the points' expressions and the coordinates; its methods read
an expression, a constant, an axis or a configuration from a located YAML node, and
every refusal names file:line:column.
"""

from __future__ import annotations

import keyword
import re
from dataclasses import replace
from fractions import Fraction

from rbdsolve.errors import InputError, did_you_mean
from rbdsolve.problem import expr as ex
from rbdsolve.problem.instants import StateValue
from rbdsolve.problem.quantities.quantity import LENGTH, NUMBER, Dimension, parse_value
from rbdsolve.problem.readers import expect_mapping, expect_scalar
from rbdsolve.problem.yamlnodes import Node, Scalar, Seq

# t is time; pi the constant; E and I are what sympy reads back from JSON answers as e and i.
RESERVED = {"t", "pi", "E", "I"} | set(ex.SCALAR_FUNCTIONS) | set(
    ex.DERIVATIVE_FUNCTIONS
) | ex.VECTOR_FUNCTIONS
_AXES = {"x": (1, 0, 0), "y": (0, 1, 0), "z": (0, 0, 1),
         "-x": (-1, 0, 0), "-y": (0, -1, 0), "-z": (0, 0, -1)}


def identifier(key: Scalar, what: str) -> str:
    name = key.text
    if keyword.iskeyword(name):
        raise InputError(f"'{name}' is a Python keyword and cannot be a name; try '{name}_'", key.loc)
    if not (name.isascii() and name.isidentifier()):
        raise InputError(f"'{name}' is not a valid {what} name (ASCII letters, digits and _, "
                         "not starting with a digit; Greek letters are spelled: theta)", key.loc)
    if name.startswith("__"):
        raise InputError("names starting with '__' are not allowed", key.loc)
    if name in RESERVED:
        raise InputError(f"'{name}' is reserved ({_reserved_as(name)}); try '{_free_name(name)}'", key.loc)
    return name


def _reserved_as(name: str) -> str:
    if name == "t":
        return "time t"
    if name == "pi":
        return "the constant π"
    if name in ("E", "I"):
        return f"sympy reads {name} back from the JSON answers as {'e' if name == 'E' else 'i'}"
    return "a function"


def _free_name(name: str) -> str:
    """A name like it that is not reserved: E → E1, sin → sin_."""
    candidate = f"{name}1" if len(name) == 1 else f"{name}_"
    return candidate if candidate not in RESERVED else f"{name}_1"


def _check_point_name(node: Scalar, scope: ex.Scope) -> None:
    """A bare unknown name where a vector is expected is most likely a misspelt point."""
    name = node.text.strip()
    known = scope.all_names() | {n for n, _ in (*scope.refused, *scope.later)} | ex.CONSTANTS
    if name.isidentifier() and name not in known:
        raise InputError(f"unknown point '{name}'{did_you_mean(name, sorted(scope.vectors))}", node.loc)



# What a name declared twice most likely means, where the two kinds say it: a steady
# motion's rate asked for, written among the parameters too.
_MENDS = {("parameter", "unknown"): " (an unknown is what a question solves for: take it out of 'parameters')",
          ("parameter", "coordinate"): " (a coordinate changes with time, a parameter does not: take it out of "
                                       "'parameters')"}

class Reading:
    """One file's names, scopes and points, and the readers of its expressions."""

    def __init__(self, file: str):
        self.file = file
        self.coordinates: tuple[str, ...] = ()  # in the file's order
        self.scope = ex.Scope()
        self.positions = ex.Scope()
        self.rates = ex.Scope()  # velocities at one instant: parameters, dot(q), velocity points
        self.triad_vectors: frozenset[str] = frozenset()
        self.triad_names: tuple[str, ...] = ()
        self.point_exprs: dict[str, ex.Expr] = {}
        self.body_points: dict[str, str] = {}  # a body's name (its origin) and its own points -> the body
        self.later: tuple[tuple[str, str], ...] = ()  # bodies' points, refused before the bodies are placed, and why
        self.taken: dict[str, str] = {}  # name -> what declared it

    # --- expressions -------------------------------------------------------------------

    def constant(self, node: Node, what: str) -> ex.Expr:
        """A scalar that must not change with the motion: parameters and numbers only."""
        scope = self.scope.constants(f"{what} must be constant (parameters and numbers only)")
        try:
            return self.expr(node, ex.Kind.SCALAR, what, scope)
        except InputError as exc:
            raise _unit_hint(exc, node) from None

    def expr(self, node: Node, kind: ex.Kind, what: str, scope: ex.Scope | None = None) -> ex.Expr:
        if isinstance(node, Seq):  # a YAML list of components is a vector literal
            if kind != ex.Kind.VECTOR:
                raise InputError(f"expected {what}, found a list", node.loc)
            return self._vector_from_list(node, what, scope)
        scalar = expect_scalar(node, what)
        scope = scope or self.positions
        if kind == ex.Kind.VECTOR:
            _check_point_name(scalar, scope)
        parsed = ex.parse(scalar.text, scalar.loc, scope, scalar.plain)
        if parsed.kind != kind:
            raise InputError(f"expected {what}, found a {parsed.kind.value} '{parsed.text}'", scalar.loc)
        return parsed

    def _vector_from_list(self, node: Seq, what: str, scope: ex.Scope | None) -> ex.Expr:
        if len(node.items) not in (2, 3):
            raise InputError(f"a vector has 2 or 3 components, found {len(node.items)}", node.loc)
        parts = [self.expr(item, ex.Kind.SCALAR, "a number or scalar expression", scope)
                 for item in node.items]
        text = "[" + ", ".join(p.text for p in parts) + "]"
        return ex.Expr(ex.Vec(tuple(p.tree for p in parts)), ex.Kind.VECTOR, text, node.loc)

    def declare(self, key: Scalar, what: str) -> str:
        name = identifier(key, what)
        if name in self.taken:
            mend = _MENDS.get((self.taken[name], what), "")
            raise InputError(f"'{name}' is already declared as a {self.taken[name]}{mend}", key.loc)
        self.taken[name] = what
        return name

    def text(self, node: Node | None, what: str) -> str:
        if node is None or (isinstance(node, Scalar) and node.null):
            return ""
        return expect_scalar(node, what).text.strip()

    def optional_expr(self, node: Node | None, kind: ex.Kind, what: str) -> ex.Expr | None:
        if node is None or (isinstance(node, Scalar) and node.null):
            return None
        return self.expr(node, kind, what, self.positions)

    def optional_measured(self, node: Node | None, what: str, kinds: tuple[Dimension, ...],
                          example: str) -> ex.Expr | None:
        if node is None or (isinstance(node, Scalar) and node.null):
            return None
        return self.measured(node, what, kinds, example)

    def optional_constant(self, node: Node | None, what: str) -> ex.Expr | None:
        if node is None or (isinstance(node, Scalar) and node.null):
            return None
        return self.constant(node, what)

    def set_point_scopes(self, positions: frozenset[str], velocities: frozenset[str]) -> None:
        """Positions name position points; velocities at an instant name velocity points
        and the rates dot(q), never the coordinates themselves (the configuration of an
        instant is given by the question, with 'at:')."""
        positions = positions | self.triad_vectors
        bare = not self.scope.functions_of_time  # no coordinate (nor prescribed motion): a name may be one forgotten
        self.scope = ex.Scope(self.scope.scalars, positions, self.scope.functions_of_time, bare=bare)
        why_velocity = "it is given by its velocity; positions name points given by position"
        self.positions = ex.Scope(self.scope.scalars, positions,
                                  refused=tuple((n, why_velocity) for n in sorted(velocities)), later=self.later,
                                  bare=bare)
        coordinates = frozenset(self.coordinates)
        why = ("a velocity at the instant uses parameters, numbers and rates dot(q); "
               "give the configuration with the question's 'at:'")
        why_position = "it is given by its position; a velocity names points given by velocity"
        refused = [(n, why) for n in sorted(self.scope.functions_of_time | {"t"})]
        refused += [(n, why_position) for n in sorted(positions)]
        self.rates = ex.Scope(self.scope.scalars - self.scope.functions_of_time - {"t"}, velocities, coordinates,
                              tuple(refused), max_order=1, bare=bare)

    def add_positions(self, names: frozenset[str]) -> None:
        """Points the model derives, named after their declaration (a contact on a plane,
        C): the questions may take moments about them."""
        self.positions = replace(self.positions, vectors=self.positions.vectors | names)
        self.scope = replace(self.scope, vectors=self.scope.vectors | names)

    def add_body_points(self, bodies) -> None:
        """Each body's origin, named by the body, and its own points (``points:`` under the
        body) become points the later sections may name (springs, forces, questions). A
        body given by its velocities at an instant has none."""
        for b in bodies:
            if b.velocity is None:
                self.body_points[b.name] = b.name
                self.body_points.update({name: b.name for name, _ in b.points})
        self.add_positions(frozenset(self.body_points))

    def point_names(self, expr: ex.Expr) -> set[str]:
        """Every name an expression uses, through the points it names."""
        found, todo = set(), set(expr.names())
        while todo:
            name = todo.pop()
            found.add(name)
            todo |= (self.point_exprs[name].names() - found) if name in self.point_exprs else set()
        return found

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

    def coordinate_values(self, node: Node, what: str, complete: bool) -> tuple[tuple[str, ex.Expr], ...]:
        """coordinate -> constant value, in the coordinates' order."""
        return tuple((v.coordinate, v.value) for v in self.state(node, what, (0,), complete))

    def state(self, node: Node, what: str, orders: tuple[int, ...] = (0,), complete: bool = False,
              hint: str = "") -> tuple[StateValue, ...]:
        """The one reader of a state: coordinate q (order 0), ``dot(q)`` (1), ``ddot(q)``
        (2) -> a constant value, for the orders allowed; the key is matched as text, never
        parsed. ``complete``: every coordinate at every order allowed, a missing one named
        (``hint`` says what else the user may give). In the coordinates' order, order by order."""
        table = expect_mapping(node, f"{what}: " + " and ".join(
            {0: "coordinate", 1: "dot(coordinate)", 2: "ddot(coordinate)"}[k] for k in orders) + " -> value")
        names = list(self.coordinates)
        given: dict[tuple[int, str], ex.Expr] = {}
        for key, value in table.entries:
            order, name = _state_key(key.text)
            if name not in names or order not in orders:
                keys = [_state_name(k, n) for k in orders for n in names]  # dot(thta): dot(theta)
                raise InputError(f"'{key.text}' is not a coordinate{_ORDER_WORDS[orders]}"
                                 f"{did_you_mean(key.text.strip(), keys)}", key.loc)
            given[(order, name)] = self._state_value(value, order, f"{_WHAT[order]} in {what}")
        wanted = [(k, n) for k in orders for n in names]
        missing = [_state_name(k, n) for k, n in wanted if (k, n) not in given]
        if complete and missing:
            every = "every coordinate" + (" and rate" if 1 in orders else "")
            raise InputError(f"give a value for {every}; missing {', '.join(missing)}{hint}", table.loc)
        return tuple(StateValue(n, k, given[(k, n)]) for k, n in wanted if (k, n) in given)

    def coordinate_value(self, node: Node, what: str) -> ex.Expr:
        """A coordinate's value outside a state (an end of its search range), read as a
        state's is: parameters and numbers, or ``-90 deg``, ``20 cm``."""
        return self._state_value(node, 0, what)

    def _state_value(self, node: Node, order: int, what: str) -> ex.Expr:
        """A state's value: parameters and numbers, or a quantity with a unit of its
        order's kind, read in SI as exams write it: ``10 deg`` (π/18) or ``30 cm`` for a
        coordinate, ``120 rev/min`` or ``2 m/s`` for a rate, ``3 rad/s^2`` for an
        acceleration. Whether the coordinate is an angle or a length the scene does not
        say: either kind is taken for either coordinate, as a bare number is."""
        return self.measured(node, what, _STATE_KINDS[order], _KIND_EXAMPLES[order])

    def measured(self, node: Node, what: str, kinds: tuple[Dimension, ...], example: str) -> ex.Expr:
        """A constant (parameters and numbers, in SI as the rest of the file), or one
        quantity with a unit of one of ``kinds``, read in SI: ``60 deg`` is π/3 and
        ``20 cm`` is 1/5, as a student copies them from the statement."""
        try:
            return self.constant(node, what)
        except InputError as exc:
            value = _quantity(node)
            if value is None:
                raise exc from None
        if value.dimension not in kinds:
            raise InputError(f"'{ex._clip(node.text.strip())}' is {_kind_of(value.dimension)}, not {what} "
                             f"(write {example})", node.loc)
        return ex.Expr(value.tree, ex.Kind.SCALAR, node.text.strip(), node.loc)


def _quantity(node: Node):
    """The node as a quantity with a unit (``10 deg``), or None: no unit, or no quantity."""
    if not isinstance(node, Scalar):
        return None
    try:
        value = parse_value(node.text, node.loc, node.plain)
    except InputError:
        return None
    return value if value.dimension is not None else None


_PER_SECOND = Dimension(time=Fraction(-1))
# a coordinate is an angle (no dimension) or a length; its rate and acceleration per s and s²
_STATE_KINDS = {0: (NUMBER, LENGTH), 1: (_PER_SECOND, LENGTH * _PER_SECOND),
                2: (_PER_SECOND ** 2, LENGTH * _PER_SECOND ** 2)}
_KIND_EXAMPLES = {0: "an angle such as 30 deg, or a length such as 20 cm",
                  1: "a rate such as 120 rev/min, or a speed such as 2 m/s",
                  2: "an angular acceleration such as 3 rad/s^2, or an acceleration such as 9.81 m/s^2"}


def _kind_of(dimension: Dimension) -> str:
    unit = dimension.unit
    return f"a quantity in {unit}" if unit else "a pure number"


_STATE_KEY = re.compile(r"^\s*(dot|ddot)\s*\(\s*([A-Za-z_][A-Za-z0-9_]*)\s*\)\s*$")
_ORDER_WORDS = {(0,): "", (0, 1): ", nor dot() of one", (0, 1, 2): ", nor dot() or ddot() of one"}
_WHAT = {0: "a coordinate's value", 1: "a rate", 2: "an acceleration"}


def _state_key(text: str) -> tuple[int, str]:
    """(order, coordinate) of a state's key: theta (0), dot(theta) (1), ddot(theta) (2)."""
    match = _STATE_KEY.match(text)
    if match is None:
        return 0, text.strip()
    return (1 if match.group(1) == "dot" else 2), match.group(2)


def _state_name(order: int, name: str) -> str:
    return ("", "dot", "ddot")[order] + (f"({name})" if order else name)


def _unit_hint(error: InputError, node: Node) -> InputError:
    """A quantity with a unit (``10 rad/s``) where an expression is read: units are read in
    'values:', --set, a body's mass and sizes and a state, so say how to write it here,
    rather than 'invalid syntax'."""
    if not error.message.startswith("cannot read expression") or _quantity(node) is None:
        return error
    text = ex._clip(node.text.strip())
    return InputError(f"'{text}' has a unit, and units are read in 'values:', --set, a body's mass and sizes, "
                      f"a spring's natural length and rest angle, a coordinate's range and a question's states "
                      f"(at:, from_rest:, about:, to:), not here: write the value here in "
                      f"SI without one (an angle in radians: 30° is pi/6), or name it, with a parameter whose value "
                      f"is '{text}'", node.loc)
