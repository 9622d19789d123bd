"""The SI unit of each numeric answer, from the dimensions of the parameters.

A parameter's dimension is known from the file (``problem.quantities.dimensions``: a declared
unit, its place in the scene, the unit of its value); a coordinate declared (or found)
to be an angle, or by which a body turns (one a torsional spring winds up), is a pure
number, a length coordinate a length, and each time
derivative divides by a second. The dimension of an answer is then read off its
expression: a sum's terms share one, a product multiplies them, a power with a
rational exponent scales them, and a function (sin, acos, exp) takes and gives a pure
number. Where anything in it is of unknown dimension, or the expression mixes
dimensions, the answer gets no unit (None).

A numeric route's answers are floats, with no expression to read: a coordinate's value
(under ``at``, ``about`` or ``equivalent``) takes the coordinate's unit on every route,
and the small-oscillation numbers take theirs from what they are: λ = ω² in 1/s², ω in
rad/s, an inertia's J and moments in kg·m², a point's position, velocity and
acceleration in m, m/s, m/s².

On both routes, an answer whose meaning fixes its unit takes that unit first
(``fixed_units.py``: M_ij and K_ij per the coordinates' units, K over two angles in
N·m/rad, a moment in N·m, q̈ of an angle in rad/s², a growth rate in 1/s), and a
critical value takes its parameter's unit.
"""

from __future__ import annotations

import re
from fractions import Fraction
from typing import Mapping

import sympy as sp
from sympy.core.function import AppliedUndef

from rbdsolve.model.build import Model
from rbdsolve.model.state import t
from rbdsolve.model.symbols import to_sympy
from rbdsolve.problem import expr as ex
from rbdsolve.problem.quantities.quantity import LENGTH, NUMBER, Dimension
from rbdsolve.problem.schema import CoordinateKind
from rbdsolve.problem.usage import state_rate_parameters
from rbdsolve.report.numbers import Path
from rbdsolve.model.values.tree import map_paths
from rbdsolve.model.values.fixed_units import (TORSIONAL, couple_moments, fixed_unit,
                                                torsional_stiffnesses)
from rbdsolve.model.values.numbers import at
from rbdsolve.model.values.values import CONDITIONS

TIME = Dimension(time=Fraction(1))


def answer_units(answers: object, model: Model, kind: str = "", open_ones: frozenset = frozenset()) -> object:
    """The answers tree of a ``kind`` question with each numeric leaf's SI unit ('rad/s',
    'kg·m²', '' for a pure number, 'rad' for an angle coordinate's value), None where
    it is unknown or the leaf is not a number at the values (``open_ones``: parameters
    without a value a leaf may hold all the same — the numeric block's lines written
    with one parameter left open). A unit that the answer's meaning fixes comes first
    (fixed_units.py: N·m/rad for K over angles, N·m for a moment), then a critical
    value takes its parameter's unit."""
    dimensions = known_dimensions(model)
    angles = {c.name for c, q in zip(model.problem.coordinates, model.q) if dimensions.get(q) == NUMBER}
    coordinates = {c.name: dimensions.get(q) for c, q in zip(model.problem.coordinates, model.q)}
    numeric_unit, numeric_row = _memoized_numeric_unit(coordinates, angles, kind)
    # a parameter given in angle units (30 deg) is an angle: its critical values in rad, with their degrees
    parameters = {**parameter_units(model), **dict.fromkeys(model.problem.angle_values(), "rad")}

    zeros = []  # whether any entry is exactly 0 (its unit then comes from its list)

    def unit(path: Path, leaf: object) -> str | None:
        if isinstance(leaf, float):  # a numeric route's answer
            return numeric_unit(path)
        named = [p for p in path if isinstance(p, str)]
        if not isinstance(leaf, sp.Expr) or isinstance(leaf, CONDITIONS) or not _valued(leaf, model, open_ones):
            return None
        fixed = fixed_unit(kind, path, coordinates) or _critical_unit(answers, path, parameters)
        if fixed is not None:
            return fixed
        if _coordinate_value(named, coordinates):
            return _coordinate_unit(named[-1], coordinates, angles, named[-2] == "steady")
        if _kinematic(named):  # what it is fixes it: a state's bare rate 2 is 2 rad/s, not a pure number
            return _RATES[named[-1]].unit if named[-1] in _RATES else (LENGTH / TIME).unit
        if leaf == 0:
            zeros.append(path)
            return _ZERO
        found = dimension_of(leaf, dimensions)
        if found is None:
            return None
        return "rad" if found == NUMBER and named and named[-1] in angles else found.unit

    units = map_paths(answers, unit, row=numeric_row)
    return _zeros_filled(units) if zeros else units


MASS = Dimension(mass=Fraction(1))
INERTIA = MASS * LENGTH ** 2
ENERGY = INERTIA / TIME ** 2
_RATES = {  # a numeric route's answers whose unit is fixed by what they are
    "eigenvalues": TIME ** -2, "absolute_errors": TIME ** -2, "frequencies": TIME ** -1, "growth_rates": TIME ** -1,
    "mass": MASS, "J": INERTIA, "principal_moments": INERTIA, "J_axis": INERTIA, "absolute_error": INERTIA,
    "moments": INERTIA, "position": LENGTH, "velocity": LENGTH / TIME, "acceleration": LENGTH / TIME ** 2,
    "speed": LENGTH / TIME, "distance": LENGTH, "moment": INERTIA, "spin": TIME ** -1, "transverse": TIME ** -1,
    "omega": TIME ** -1, "body_rate": TIME ** -1, "space_rate": TIME ** -1, "angular_momentum": INERTIA / TIME,
    "roots": TIME ** -1, "root_errors": TIME ** -1,  # a gyroscopic system's s = iω and their bounds
    "mu": NUMBER,  # a friction coefficient at its largest over a motion (reactions' least_friction_over)
}
_RATE_UNITS = {k: d.unit for k, d in _RATES.items()}
_RATE_OF = re.compile(r"(d?dot)\((\w+)\)")  # dot(theta), ddot(theta): a state's rate or acceleration


def _kinematic(named: list[str]) -> bool:
    """A point's position, velocity, acceleration or speed, or a distance and its rate:
    their units are fixed, and a state's rates given as bare numbers carry none to read."""
    return bool(named) and ("points" in named and named[-1] in ("position", "velocity", "acceleration", "speed")
                            or "distances" in named and named[-1] in ("distance", "rate"))


def _coordinate_value(named: list[str], coordinates: Mapping[str, Dimension | None]) -> bool:
    """Is the leaf a coordinate's value, rate or acceleration (an equilibrium's, the one
    modes are about, a state's, where a push first reaches zero along a motion)?"""
    if len(named) < 2 or named[-2] not in ("at", "about", "equivalent", "steady", "lost_at", "turns_at", "to",
                                                "until"):
        return False
    rate = _RATE_OF.fullmatch(named[-1])
    return (rate.group(2) if rate else named[-1]) in coordinates


def _coordinate_unit(name: str, coordinates: Mapping[str, Dimension | None], angles, steady: bool = False) \
        -> str | None:
    """A coordinate's unit, or its rate's (``steady``: a cyclic coordinate's steady rate)."""
    rate = _RATE_OF.fullmatch(f"dot({name})" if steady else name)
    if rate is None:
        return "rad" if name in angles else None if coordinates[name] is None else coordinates[name].unit
    if rate.group(2) in angles:
        return "rad/s" if rate.group(1) == "dot" else "rad/s²"
    found = coordinates[rate.group(2)]
    return None if found is None else (found / TIME ** (1 if rate.group(1) == "dot" else 2)).unit


def _critical_unit(answers: object, path: Path, parameters: Mapping[str, str]) -> str | None:
    """A critical value's unit is its parameter's: path (…, 'critical', i, 'value'); rad
    for a parameter given in angle units, so its degrees print beside it."""
    if len(path) < 3 or path[-1] != "value" or path[-3] != "critical":
        return None
    return parameters.get(getattr(at(answers, path[:-1]), "parameter", None))


def _numeric_unit(path: Path, coordinates: Mapping[str, Dimension | None], angles, kind: str = "") -> str | None:
    """The unit of a numeric route's float, from what its key means (module docstring)."""
    fixed = fixed_unit(kind, path, coordinates)
    if fixed is not None:
        return fixed
    named = [p for p in path if isinstance(p, str)]
    if _coordinate_value(named, coordinates):
        return _coordinate_unit(named[-1], coordinates, angles, named[-2] == "steady")
    return _RATE_UNITS.get(named[-1]) if named else None


def _memoized_numeric_unit(coordinates: Mapping[str, Dimension | None], angles, kind: str = ""):
    """``_numeric_unit`` as a function of the leaf's path, computed once per distinct
    answer. The path but its last two steps, and those two with each index of a
    coordinate replaced by its dimension's place in a list, decide it (the keys, and the
    coordinates' dimensions for M_ij and K_ij): an n×n matrix repeats the same few."""
    dims = tuple(coordinates.values())
    kinds = list(dict.fromkeys(dims))
    kind_of = tuple(kinds.index(d) for d in dims)
    memo: dict = {}

    def unit(path: Path) -> str | None:
        tail = tuple(("kind", kind_of[p]) if isinstance(p, int) and p < len(dims) else p for p in path[-2:])
        key = (path[:-2], tail)
        if key not in memo:
            memo[key] = _numeric_unit(path, coordinates, angles, kind)
        return memo[key]

    def row(path: Path, values: tuple) -> list:
        """The units of a row of floats at once: they follow from the row's path but its
        last step, that step (as ``unit`` sees it) and the row's length."""
        last = ("kind", kind_of[path[-1]]) if path and isinstance(path[-1], int) and path[-1] < len(dims) else path[-1:]
        key = ("row", path[:-1], last, len(values))
        if key not in memo:
            memo[key] = [unit((*path, j)) for j in range(len(values))]
        return list(memo[key])

    return unit, row


_ZERO = object()  # an entry that is exactly 0: of the unit of its row or matrix, if any


def _zeros_filled(tree: object) -> object:
    """A 0 takes the one unit its list (a vector, a matrix) has, else None: a zero
    product of inertia is in kg·m² too."""
    if isinstance(tree, dict):  # a force's components (R_Ox, R_Oy) are one quantity, as a list's entries are
        return {k: _components_filled(v) if k == "components" else _zeros_filled(v) for k, v in tree.items()}
    if isinstance(tree, list):
        units = {u for u in _flat(tree) if u is not None and u is not _ZERO}
        shared = units.pop() if len(units) == 1 else None
        return _filled(tree, shared)
    return None if tree is _ZERO else tree


def _flat(tree: list):
    for item in tree:
        if isinstance(item, list):
            yield from _flat(item)
        elif not isinstance(item, dict):
            yield item


def _components_filled(tree: object) -> object:
    """A zero component (R_Ox = 0) takes the one unit of the force's other components."""
    if not isinstance(tree, dict):
        return _zeros_filled(tree)
    filled = _zeros_filled(list(tree.values()))
    return dict(zip(tree, filled))


def _filled(tree: list, shared: str | None) -> list:
    return [_filled(x, shared) if isinstance(x, list) else shared if x is _ZERO else _zeros_filled(x)
            for x in tree]


def _valued(expr: sp.Expr, model: Model, open_ones: frozenset = frozenset()) -> bool:
    return expr.free_symbols <= set(model.values) | set(model.q) | {t} | open_ones


def parameter_units(model: Model) -> dict[str, str]:
    """The SI unit of each parameter whose dimension is known ('' for a pure number); a
    torsional spring's stiffness in N·m/rad, a couple's moment in N·m."""
    return problem_units(model.problem)


def problem_units(problem) -> dict[str, str]:
    """``parameter_units`` read from the problem alone (a variants table has no model)."""
    torsional, torques = torsional_stiffnesses(problem), couple_moments(problem)
    return {name: TORSIONAL if name in torsional else "N·m" if name in torques and d == ENERGY else d.unit
            for name, d in problem.dimensions}


def known_dimensions(model: Model) -> dict[object, Dimension]:
    """Parameters, coordinates (as symbols and as functions of time) and t."""
    out: dict[object, Dimension] = {model.symbols.parameters[n]: d for n, d in model.problem.dimensions
                                    if n in model.symbols.parameters}
    turned = _turned_by_bodies(model) | _turned_in_point_trees(model)
    along = _along_contacts(model)
    for c, q in zip(model.problem.coordinates, model.q):
        # model.angles after the bodies' angles and the points' trees: it reads every
        # position (model/deferred.py), which a chain of n links writes out in n² terms
        found = (LENGTH if c.kind is CoordinateKind.LENGTH or (c.kind is not CoordinateKind.ANGLE and c.name in along)
                 else NUMBER if c.kind is CoordinateKind.ANGLE or q in turned or q in model.angles
                 or _turns_in_points(q, model)
                 else None)
        if found is not None:
            out[q] = out[c.name] = found
    for c, q in zip(model.problem.coordinates, model.q):
        if q not in out and _travels_in_points(q, model, out):
            out[q] = out[c.name] = LENGTH
    out[t] = TIME
    for name, dimension in _state_rates(model, out).items():
        out.setdefault(model.symbols.parameters[name], dimension)
    return out


def _state_rates(model: Model, known: Mapping[object, Dimension]) -> dict[str, Dimension]:
    """The parameters alone as a coordinate's rate in a state (``dot(x): v``, an impact's
    ``before``): the rate's dimension (m/s for a length x), where the coordinate's is known
    and every such place agrees."""
    out = {}
    for name, places in state_rate_parameters(model.problem).items():
        if any(known.get(c) is None for c, _ in places):
            continue
        found = {known[c] / TIME ** order for c, order in places}
        if len(found) == 1:
            out[name] = found.pop()
    return out


def rate_parameter_units(model: Model, among: frozenset[str]) -> dict[str, str]:
    """The units of those parameters ``among`` that are a state's rate (``_state_rates``):
    an open speed v beside an answer that holds it is "v in m/s", not "in SI units"."""
    if not among or not state_rate_parameters(model.problem).keys() & among:
        return {}
    known = known_dimensions(model)
    return {n: "rad/s" if d == TIME ** -1 else d.unit for n, d in _state_rates(model, known).items() if n in among}


def _travels_in_points(q: sp.Symbol, model: Model, dims: Mapping[object, Dimension]) -> bool:
    """Is q a length because a point's position (a length) moves by a pure number times
    it (P = [x, y], a centre x·[cos α, sin α] along a slope): ∂r/∂q free of the
    coordinates and of no dimension, in some component."""
    coordinates = set(model.q)
    for point in [*model.points.values(), *(c.point for c in model.contacts)]:
        for component in sp.Matrix(point):
            rate = sp.diff(component, q)
            if rate != 0 and not rate.free_symbols & coordinates and dimension_of(rate, dims) == NUMBER:
                return True
    return False


def _number_times(expr: sp.Expr, q: sp.Symbol) -> bool:
    """Is ``expr`` a number times q (plus what does not hold q)? ∂expr/∂q a nonzero number."""
    rate = sp.diff(expr, q)
    return rate != 0 and rate.is_number


def _along_contacts(model: Model) -> set[str]:
    """The coordinates a rolling contact measures ``along`` a straight line (or a body's
    straight edge, a plank's top): a distance,
    whatever turns by it (a disk of radius 1/10 written as a number turns by −10 x,
    which read x as an angle: ẍ in rad/s²). Along a circle the travel is an angle."""
    from rbdsolve.problem.surfaces import Measure, SurfaceKind

    return {c.source.coordinate for c in model.contacts if c.source.coordinate is not None
            and c.source.measure is Measure.ALONG and (c.source.surface.kind is SurfaceKind.LINE
                                                       or _flat_edge(model, c.source.surface))}


def _flat_edge(model: Model, surface) -> bool:
    """Whether a body's edge rolled on is straight (a plank's top), not round."""
    from rbdsolve.model.constraints.edges import Flat, body_part, part_edge
    from rbdsolve.problem.surfaces import SurfaceKind

    if surface.kind is not SurfaceKind.BODY or surface.body is None or surface.edge is None:
        return False
    spec = model.problem.body(surface.body)
    return isinstance(part_edge(body_part(spec, surface.part), surface.edge, model.symbols), Flat)


def _turned_by_bodies(model: Model) -> set:
    """The coordinates q that are angles, though perhaps not periodic ones (a torsional
    spring winds them up), because a body turns by a number times q: an angle is a pure
    number (in radians). Each body's angle is asked about its own coordinates only."""
    q = set(model.q)
    planar = {x for b in model.bodies if b.angle is not None for x in b.angle.free_symbols & q
              if _number_times(b.angle, x)}
    turned = {x for b in model.bodies if b.turns_3d for f in b.rotation.atoms(sp.sin, sp.cos)
              for x in f.free_symbols & q if _number_times(f.args[0], x)}  # a gimbal's ψ, θ
    return planar | turned


def _turned_in_point_trees(model: Model) -> set:
    """The coordinates q whose sine or cosine, of a number times q, a point's expression
    takes: read from the file's own trees, each argument folded alone, so that no point
    is written out. As ``_turns_in_points`` asks of the folded points, except that a
    sine the fold would cancel (sin q − sin q) still counts."""
    q = set(model.q)
    arguments = {to_sympy(a, model.symbols) for p in model.problem.points if p.position is not None
                 for a in _trig_arguments(p.position.tree)}
    return {x for a in arguments for x in a.free_symbols & q if _number_times(a, x)}


def _trig_arguments(tree: ex.Tree):
    """The argument of each sin and cos in ``tree``."""
    if isinstance(tree, ex.Call):
        if tree.func in ("sin", "cos"):
            yield tree.args[0]
        for a in tree.args:
            yield from _trig_arguments(a)
    elif isinstance(tree, ex.BinOp):
        yield from _trig_arguments(tree.left)
        yield from _trig_arguments(tree.right)
    elif isinstance(tree, ex.Neg):
        yield from _trig_arguments(tree.operand)
    elif isinstance(tree, ex.Vec):
        for item in tree.items:
            yield from _trig_arguments(item)


def _turns_in_points(q: sp.Symbol, model: Model) -> bool:
    """Is q an angle because a point's position takes sin or cos of a number times it
    (an argument of sin and cos is a pure number)? The points named in the file, and
    each rolling contact's point C (a body rolling on a circle: C = R (sin θ, −cos θ))."""
    points = [*model.points.values(), *(c.point for c in model.contacts)]
    return any(_number_times(f.args[0], q) for point in points
               for f in sp.Matrix(point).atoms(sp.sin, sp.cos) if f.has(q))


def dimension_of(expr: sp.Expr, dims: Mapping[object, Dimension]) -> Dimension | None:
    """The dimension of ``expr``, or None where it is unknown or inconsistent."""
    if expr.is_number:
        return NUMBER
    if isinstance(expr, sp.Symbol):
        return dims.get(expr)
    if isinstance(expr, AppliedUndef):
        return dims.get(expr.func.__name__)
    if isinstance(expr, sp.Derivative):
        inner = dimension_of(expr.expr, dims)
        return None if inner is None else inner / TIME ** expr.derivative_count
    if isinstance(expr, sp.Add):
        found = {dimension_of(a, dims) for a in expr.args}
        return found.pop() if len(found) == 1 else None
    if isinstance(expr, sp.Mul):
        return _product([dimension_of(a, dims) for a in expr.args])
    if isinstance(expr, sp.Pow):
        return _power(dimension_of(expr.base, dims), expr.exp, dims)
    if isinstance(expr, sp.Abs):
        return dimension_of(expr.args[0], dims)
    if isinstance(expr, sp.Function):
        pure = all(dimension_of(a, dims) == NUMBER for a in expr.args)
        return NUMBER if pure else None
    return None


def _product(found: list[Dimension | None]) -> Dimension | None:
    out = NUMBER
    for d in found:
        if d is None:
            return None
        out = out * d
    return out


def _power(base: Dimension | None, exponent: sp.Expr, dims) -> Dimension | None:
    if base is None:
        return None
    if isinstance(exponent, sp.Rational):
        return base ** Fraction(int(exponent.p), int(exponent.q))
    return NUMBER if base == NUMBER and dimension_of(exponent, dims) == NUMBER else None
