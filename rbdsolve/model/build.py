"""Problem -> Model: the scene's kinematics in sympy, built only as far as asked.

The model is 3D underneath: a point is a 3-vector (a planar [x, y] gets z = 0) and a
planar ``angle`` is a rotation about z. Energies are computed on demand
(:mod:`rbdsolve.model.energies.energy`), so a question that needs only V never builds T.
"""

from __future__ import annotations

from collections import ChainMap
from dataclasses import dataclass, field, replace
from functools import cached_property
from fractions import Fraction
from typing import Mapping, TYPE_CHECKING

import sympy as sp

from rbdsolve.form.arrange import Reading
from rbdsolve.form.printers import to_unicode
from rbdsolve.errors import InputError
from rbdsolve.model.assumptions import assumed, decided_by, substitutions
from rbdsolve.model.energies.spring_length import as_square_root, polar_distances, signed_length
from rbdsolve.model.assumptions import check as check_assumptions
from rbdsolve.model.deferred import Deferred, Later, Points
from rbdsolve.model.constraints.lengths import body_dimensions
from rbdsolve.model.inertia import OWN_AXIS, MassProperties, body_properties, combine, explicit_inertia
from rbdsolve.model.state import State, t
from rbdsolve.model.rotation import Turns, angular_velocity, sequence_rotation, turns_angular_velocity, \
    turns_conjugate, unit_turns
from rbdsolve.model.symbols import Symbols, exact_number, plainly_real
from rbdsolve.form.tidy import tidy
from rbdsolve.problem.expr import Expr, Kind
from rbdsolve.problem.quantities.quantity import Value
from rbdsolve.problem.sections.bodies import POSITIONS
from rbdsolve.problem.schema import Body, CoordinateKind, Part, Problem
from rbdsolve.form.zero import simplifies_to_zero

if TYPE_CHECKING:
    from rbdsolve.problem.scene import Spring


@dataclass(frozen=True)
class RigidBody:
    """A body's mass, centre of mass, orientation and inertia, as sympy objects.

    ``rotation`` maps body axes to scene axes; ``inertia`` is J_G in body axes. A body
    in a scene at one instant has no position: its velocities are given instead.
    """

    name: str
    mass: sp.Expr
    position: sp.Matrix | None = Deferred()  # r_G, scene axes; made on first read (model/deferred.py)
    rotation: sp.Matrix
    angle: sp.Expr | None  # planar rotation about z (None: no rotation)
    inertia: sp.Matrix
    source: Body
    given_velocity: sp.Matrix | None = None  # v_G at the instant, linear in q̇
    given_angular_velocity: sp.Matrix | None = None
    turns_3d: bool = False  # oriented by a sequence of turns: ω from Ṙ Rᵀ
    turns: Turns = ()  # those turns, a triad's first (model/rotation.py): ω and R J Rᵀ turn by turn

    @property
    def placed(self) -> bool:
        """Has the body a position (it is not given by its velocities at an instant)?
        Told without making a deferred position."""
        return not Deferred.made(self, "position") or self.position is not None

    def velocity(self, state: State) -> sp.Matrix:
        """v_G in scene axes: given, or dr_G/dt."""
        if self.position is None:
            return self.given_velocity
        return state.d_dt(self.position)

    def angular_velocity(self, state: State) -> sp.Matrix:
        """ω in scene axes: given, or, for a planar body turning by angle α(q, t), α̇ e_z."""
        if self.given_angular_velocity is not None:
            return self.given_angular_velocity
        if self.turns:
            return turns_angular_velocity(self.turns, state)
        if self.turns_3d:
            return angular_velocity(self.rotation, state)
        if self.angle is None:
            return sp.zeros(3, 1)
        return sp.Matrix([0, 0, state.d_dt(self.angle)])

    def inertia_in_scene(self) -> sp.Matrix:
        """J_G in scene axes: R J Rᵀ (a fresh matrix: a caller may change it in place);
        turn by turn where the body is turned by a sequence (a spin about an axis of
        symmetry then leaves no trace of its angle)."""
        return sp.Matrix(self._inertia_in_scene)

    @cached_property  # once per body: T, the Jacobians, M at each configuration and the balances ask for it
    def _inertia_in_scene(self) -> sp.ImmutableMatrix:
        if self.turns:
            return sp.ImmutableMatrix(turns_conjugate(self.turns, self.inertia))
        return sp.ImmutableMatrix(self.rotation * self.inertia * self.rotation.T)


@dataclass(frozen=True)
class SpringModel:
    """A spring as sympy objects: its stiffness and its stretch, |r_a − r_b| − l₀ (or
    α − α₀ for a torsional spring)."""

    name: str
    stiffness: sp.Expr
    stretch: sp.Expr  # |r_a − r_b| − l₀ for a linear spring, α − α₀ for a torsional one
    source: Spring
    lengths: tuple = ()  # model/energies/spring_length.py Length's: each |u| of the length, written ±u where its sign is known

    def signed(self, expr: sp.Expr) -> sp.Expr:
        """expr with each |u| of the length written as the stretch writes it (±u where
        its sign is known): the direction d/|d| of the pull, as the stretch has it."""
        if self.lengths:
            expr = expr.xreplace({r: as_square_root(r) for r in _roots(expr)})
        return expr.xreplace({sp.Abs(x.inside): x.sign * x.inside for x in self.lengths if x.sign is not None})


@dataclass(frozen=True)
class Moving:
    """A part of the scene that holds t (``Model.moving_parts``): as a message names it,
    and whether it is a body's planar angle (a turn about z in the scene's axes, which a
    frame turning with the body does not carry)."""

    text: str
    planar_angle: bool = False


@dataclass(frozen=True, eq=False)  # identity equality: energies are memoized per model
class Model:
    """A scene as sympy objects, the input of every solver: the problem and its symbols,
    the points, bodies and springs, gravity, the parameter values, and what triads,
    moving frames, assumptions and contacts add."""

    problem: Problem
    symbols: Symbols
    angles: frozenset[sp.Symbol] = Deferred()  # the coordinates that are periodic angles; made on first read
    points: Mapping[str, sp.Matrix]
    bodies: tuple[RigidBody, ...]
    springs: tuple[SpringModel, ...]
    gravity: sp.Matrix | None
    values: Mapping[sp.Symbol, sp.Rational]
    velocities: Mapping[str, sp.Matrix] = field(default_factory=dict)  # points given by velocity
    triads: Mapping[str, sp.Matrix] = field(default_factory=dict)  # rotation: triad axes -> scene axes
    inertial: tuple = ()  # EnergyTerm's: inertial potentials, for a model seen in a moving frame
    gyroscopic: tuple = ()  # EnergyTerm's: L's terms linear in q̇ that T does not hold (a frame's Coriolis terms)
    assumptions: tuple = ()  # model/assumptions.py Assumed's, from 'assumptions:' and implied by contacts
    contacts: tuple = ()  # model/constraints/contacts.py Rolling's: each contact's point and rolling condition
    plane_contacts: tuple = ()  # model/constraints/plane_rolling.py PlaneRolling's: 3D contacts, kept as constraints
    loads: tuple = ()  # model/energies/loads.py Load's: applied forces and couples
    body_points: Mapping[str, sp.Matrix] = field(default_factory=dict)  # each body's origin (by its name), its points

    @cached_property  # asked in every sign decision; the model never changes
    def decided_by(self) -> dict:
        """What sign decisions may use: the values, and the assumptions' substitutions
        (R = r + δ under R > r) for the parameters without one (model/assumptions.py)."""
        return decided_by(self.assumed, self.values)

    @cached_property
    def assumed(self) -> dict:
        """The assumptions' substitutions alone (signs that hold for every value allowed)."""
        return substitutions(self.assumptions, self.symbols) if self.assumptions else {}

    @property
    def instant(self) -> bool:
        """A scene at one instant: some velocities are given, not positions."""
        return bool(self.velocities) or any(not b.placed for b in self.bodies)

    def point(self, name: str) -> sp.Matrix:
        """The position of a named point: the file's (or a contact's), or a body's own
        (its origin by the body's name, or a point under its ``points:``)."""
        return self.points[name] if name in self.points else self.body_points[name]

    def has_point(self, name: str) -> bool:
        return name in self.points or name in self.body_points

    def point_velocity(self, name: str) -> sp.Matrix:
        """v_P: given, or dr_P/dt."""
        if name in self.velocities:
            return self.velocities[name]
        return self.state.d_dt(self.point(name))

    @property
    def state(self) -> State:
        return self.symbols.state

    @property
    def q(self) -> tuple[sp.Symbol, ...]:
        return self.state.q

    @property
    def qd(self) -> tuple[sp.Symbol, ...]:
        return self.state.qd

    @property
    def qdd(self) -> tuple[sp.Symbol, ...]:
        return self.state.qdd

    def coordinate_names(self) -> list[str]:
        return list(self.state.names)

    def to_time(self, expr):
        return self.state.to_time(expr)

    def reading(self) -> Reading:
        """How the exam form arranges this model's energies and equations
        (form/arrange.py): by the rates q̈, q̇, ordered by q, the parameters' common scale
        pulled out, each coordinate shown as a function of time."""
        return Reading((*self.qdd, *self.qd), tuple(self.q), frozenset(self.symbols.parameters.values()),
                       self.to_time)

    def depends_on_time(self) -> bool:
        """Does the scene move by itself (t in a body's position or angle, a spring, gravity
        or an inertial potential)? Points alone carry no energy."""
        return _holds([x for _, x in self._parts_in_time()], t) or any(
            turning_holds_time(b, self.state) for b in self.bodies if b.turns)

    def moving_parts(self) -> tuple[Moving, ...]:
        """What of the scene moves by itself (``depends_on_time``'s parts that hold t), for
        a message: "the angle of body 'disk'", "spring 's'", "gravity"."""
        found = [part for part, x in self._parts_in_time() if _holds([x], t)]
        found += [Moving(f"the turns of body '{b.name}'") for b in self.bodies
                  if b.turns and turning_holds_time(b, self.state)]
        return tuple(dict.fromkeys(found))

    def _parts_in_time(self) -> list[tuple[Moving, object]]:
        """Each part that may hold t, with its name. A position not made yet is made from
        the file's points and origins, which cannot bring in t where none of them names t
        or a prescribed motion (``_timed``): it is then not made here."""
        placed = self.bodies if _timed(self.problem) else [b for b in self.bodies if Deferred.made(b, "position")]
        parts = [(Moving(f"the position of body '{b.name}'"), b.position) for b in placed if b.position is not None]
        parts += [(Moving(f"the angle of body '{b.name}'", planar_angle=True), b.rotation)
                  for b in self.bodies if not b.turns]
        parts += [(Moving(f"spring '{s.name}'"), s.stretch) for s in self.springs]
        parts += [(Moving(x.name), x.value) for x in self.inertial]
        parts += [(Moving(f"{x.kind} '{x.name}'"), q) for x in self.loads for q in x.generalized]  # a force of t
        return parts + ([(Moving("gravity"), self.gravity)] if self.gravity is not None else [])

    def _positions(self) -> list[sp.Matrix]:
        return [b.position for b in self.bodies if b.position is not None]

    def readable(self, expr):
        """Coordinates as plain named symbols, for messages: 2*c*theta + …"""
        return expr.xreplace({q: sp.Symbol(n) for q, n in zip(self.q, self.coordinate_names())})

    def with_values(self, values: Mapping[str, Value | Fraction]) -> Model:
        """The same model with numeric parameter values (``--set`` beats ``values:``)."""
        table = dict(self.values)
        for name, value in values.items():
            table[self.symbols.parameters[name]] = exact_number(value)
        check_values(self.problem, self.symbols, table)
        check_assumptions(self.assumptions, table, self.symbols)
        return replace(self, values=table)


def build_model(problem: Problem) -> Model:
    """Turn a validated Problem into sympy objects."""
    names = Symbols.of(problem)
    triads = {tr.name: _turns(tr.turns, names) for tr in problem.triads}
    triad_turns = {tr.name: tuple(tr.turns) for tr in problem.triads}
    unit_vectors = {v: triads[tr.name][:, k] for tr in problem.triads for k, v in enumerate(tr.vectors)}
    names = names.with_points(unit_vectors)
    velocities: dict[str, sp.Matrix] = {}
    symbols = names
    for point in problem.points:  # dependency order: each names only earlier points
        if point.position is None:
            velocities[point.name] = _affine_in_rates(symbols.with_points(velocities).vector(point.velocity),
                                                      point.velocity, symbols)
    given = {p.name: p.position for p in problem.points if p.position is not None}
    points = Points(tuple(given), lambda name: within.vector(given[name]))  # folded on first read
    names = within = symbols.with_points(points)
    specs = {b.name: b for b in problem.bodies}  # the bodies as placed so far (contacts place some)
    own = body_points(specs, names, triads)
    if own:  # a body's origin (its name) and its own points: later bodies, springs, loads, questions
        names = names.with_points(own)
    _check_real(given, problem, symbols, tuple(own))
    problem, contacts = _place_contacts(problem, names)  # rolling places its bodies: at and angle
    specs.update({b.name: b for b in problem.bodies})
    masses: dict = {}
    bodies = tuple(_body(b, names, symbols.with_points(velocities), triads, masses, triad_turns)
                   for b in problem.bodies)
    springs = tuple(_spring(s, names) for s in problem.springs)
    gravity = names.vector(problem.gravity) if problem.gravity else None
    values = {names.parameters[k]: exact_number(v) for k, v in problem.values}
    check_values(problem, names, values)
    body_dimensions(problem, names)  # under the assumptions too (model/constraints/lengths.py)
    planes = _plane_contacts(problem, names, bodies, values)
    if planes:  # C, named in questions (steady_motion's about, rolling_at)
        points = ChainMap({c.name: c.point for c in planes}, points)
    names = names.with_points(points)
    stated = assumed(problem, names)
    contacts, planes = _implied(contacts, stated, names), _implied(planes, stated, names)
    assumptions = stated + tuple(a for c in contacts + planes for a in c.requires)
    springs = signed_springs(springs, names, assumptions, problem.coordinates, values)
    model = Model(problem, names, Later(lambda: _angles(model)), points, bodies, springs, gravity, values,
                  velocities, triads=triads, assumptions=assumptions, contacts=contacts, plane_contacts=planes,
                  loads=_loads(problem, names, bodies, assumptions, values), body_points=own)
    check_assumptions(model.assumptions, values, names)
    _refuse_winding_angles(model)
    return model


def body_points(specs: dict[str, Body], names: Symbols, triads: Mapping[str, sp.Matrix]) -> Points:
    """Each placed body's origin, named by the body, and its own points: r_P = r_at + R c,
    c the point's offset from the origin in body axes (R the body's turn), each made on
    first read, from ``specs`` as they are then (a body a contact places has its place
    once the contacts are placed; a body's ``at`` names only bodies before it)."""
    where: dict[str, tuple[str, Expr | None]] = {}
    for spec in specs.values():
        if spec.velocity is None:
            where[spec.name] = (spec.name, None)
            where.update({name: (spec.name, offset) for name, offset in spec.points})

    def place(name: str) -> sp.Matrix:
        body, offset = where[name]
        spec = specs[body]
        if spec.at is None:  # read while the contacts are placed, before this body is
            raise InputError(f"'{name}' is a point of body '{body}', which a contact places: a contact's "
                             "geometry cannot use it (its place is not known yet)", spec.loc)
        origin = within.vector(spec.at)  # a body may sit at an earlier body's point
        return origin if offset is None else origin + _rotation(spec, within, triads) * within.vector(offset)

    points = Points(tuple(where), place)
    within = names.with_points(points)
    return points


def _rotation(spec: Body, names: Symbols, triads: Mapping[str, sp.Matrix]) -> sp.Matrix:
    """R, body axes to scene axes: the planar angle's turn about z, or the 3D turns."""
    if spec.orientation:
        start = triads[spec.orientation[0]] if isinstance(spec.orientation[0], str) else None
        return _turns([x for x in spec.orientation if not isinstance(x, str)], names, start)
    return sp.rot_axis3(-names.scalar(spec.angle)) if spec.angle is not None else sp.eye(3)


def _loads(problem: Problem, names: Symbols, bodies: tuple[RigidBody, ...], every: tuple, values) -> tuple:
    """The applied forces and couples (model/energies/loads.py, imported only for a scene with
    some), each sign they need decided by the values and the assumptions."""
    if not (problem.forces or problem.couples):
        return ()
    from rbdsolve.model.assumptions import implies
    from rbdsolve.model.energies.loads import build_loads

    table = decided_by(substitutions(every, names) if every else {}, values)

    def decide(expr: sp.Expr) -> int | None:
        value = sp.factor(expr.xreplace(table))
        if value.is_positive or value.is_negative:
            return 1 if value.is_positive else -1
        return next((sign for sign in (1, -1) if implies(every, sp.StrictGreaterThan(sign * expr, 0))), None)

    return build_loads(problem, names, bodies, decide)


def _check_real(given: Mapping[str, Expr], problem: Problem, names: Symbols, own: tuple[str, ...] = ()) -> None:
    """Each point's and each body origin's own terms are real numbers (``Symbols.vector``),
    with the points it names standing for one real vector (x, y, z): the check a fold
    makes, here at the cost of one term a link of a chain rather than of the whole sum
    that its point is (the fold, on first read, checks the whole sum again). A located
    InputError, as from the fold."""
    exprs = [*given.values(), *(b.at for b in problem.bodies if b.at is not None and not b.orientation)]
    asked = [e for e in exprs if not plainly_real(e.tree)]  # most are sums of sin and cos: nothing to ask
    if asked:
        stand_in = sp.Matrix(sp.symbols("x y z", real=True, cls=sp.Dummy))
        within = names.with_points({name: stand_in for name in (*given, *own)})
        for expr in asked:
            within.vector(expr)


def _angles(model: Model) -> frozenset:
    """The coordinates that are periodic angles: declared so, or AUTO and entering the
    scene only through sin and cos of integer multiples (``_periodic_coordinates``). A
    declared angle that a contact rolls by (``rolled``) is one only where the scene
    still repeats after its turn: rolling lays off the arc R θ, which a slab on a drum
    holds outside sin and cos."""
    periodic = _periodic_coordinates(model)
    rolled = rolled_coordinates(model)
    return frozenset(qi for c, qi in zip(model.problem.coordinates, model.q)
                     if (c.kind is CoordinateKind.ANGLE and c.periodic is not False
                         and (qi not in rolled or qi in periodic))
                     or (c.kind is CoordinateKind.AUTO and qi in periodic))


def rolled_coordinates(model: Model) -> frozenset:
    """The coordinates of the contacts: rolling by them places a body, its travel (the
    arc laid off) entering its position outside sin and cos."""
    return frozenset(c.coordinate for c in model.contacts if c.coordinate is not None)


def _timed(problem: Problem) -> bool:
    """Does a point or a body's origin of the file name t or a prescribed motion? Where
    none does, positions made from them are free of t."""
    timed = {"t", *(p.name for p in problem.prescribed)}
    exprs = [p.position for p in problem.points if p.position is not None]
    exprs += [b.at for b in problem.bodies if b.at is not None]
    return any(not timed.isdisjoint(e.names()) for e in exprs)


def turning_holds_time(body: RigidBody, state: State) -> bool:
    """Does a body turned by a sequence bring t into T? Its rotational energy
    ω·J_scene ω, not its rotation: a top spun at a constant rate about its axis of
    symmetry (a last turn [z, s t]) turns with t, yet its T holds none (model/rotation.py).
    Where tidying leaves t, ∂/∂t of it is simplified to tell."""
    if body.inertia == sp.zeros(3, 3):
        return False
    omega = body.angular_velocity(state)
    energy = tidy((omega.T * body.inertia_in_scene() * omega)[0, 0])
    return energy.has(t) and not simplifies_to_zero(sp.diff(energy, t))


def _holds(parts: list, symbol: sp.Symbol) -> bool:
    """Does ``symbol`` occur in any of the expressions or matrices? As ``has``, but each
    shared subexpression looked at once: a chain's positions repeat the terms of the
    ones above them, so asking each position alone walks n² terms."""
    stack = [x for p in parts for x in (p if isinstance(p, sp.MatrixBase) else [sp.sympify(p)])]
    seen = set(stack)
    while stack:
        expr = stack.pop()
        if expr == symbol:
            return True
        for arg in expr.args:
            if arg not in seen:
                seen.add(arg)
                stack.append(arg)
    return False


def _place_contacts(problem: Problem, names: Symbols) -> tuple[Problem, tuple]:
    """model/constraints/contacts.py's ``place_contacts``, its machinery (edges, strings) imported
    only for a scene with contacts: ~4 ms of start-up that a scene without them skips."""
    if not problem.contacts:
        return problem, ()
    from rbdsolve.model.constraints.contacts import place_contacts

    return place_contacts(problem, names)


def _plane_contacts(problem: Problem, names: Symbols, bodies: tuple[RigidBody, ...], values) -> tuple:
    """The contacts on a plane (model/constraints/plane_rolling.py, imported only for a scene with contacts)."""
    if not problem.contacts:
        return ()
    from rbdsolve.model.constraints.plane_rolling import plane_contacts

    return plane_contacts(problem, names, {b.name: b.rotation for b in bodies}, values)


def _implied(contacts: tuple, stated: tuple, names: Symbols) -> tuple:
    """The contacts with what their geometry needs of the parameters (R > r for a body
    inside a circle) kept where the file's own assumptions do not already give it (put
    in as substitutions, R = r + δ, it is then positive), each once."""
    given = substitutions(stated, names) if stated else {}
    kept, out = [], []
    for c in contacts:
        needed = tuple(a for a in c.requires if not sp.factor(a.difference.xreplace(given)).is_positive
                       and all(sp.expand(a.difference - b.difference) != 0 for b in kept))
        kept += needed
        out.append(replace(c, requires=needed))
    return tuple(out)


def _refuse_winding_angles(model: Model) -> None:
    """A coordinate declared a (periodic) angle must leave V unchanged after a turn, since
    its equilibria are then reported in (−π, π]: one that a spring's stretch or a
    weight's height holds outside sin and cos (a torsion spring counts turns) is refused,
    with the term that holds it. A contact's coordinate is not: rolling is what holds it
    there, and it is taken as an angle that does not repeat (``_angles``), with a note."""
    rolled = rolled_coordinates(model)  # rolling makes them non-periodic: not refused (``_angles``)
    declared = [(c, qi) for c, qi in zip(model.problem.coordinates, model.q)
                if c.kind is CoordinateKind.ANGLE and c.periodic is not False and qi not in rolled]
    if not declared:
        return
    terms = [(f"spring '{s.name}'", s.stretch) for s in model.springs]
    if model.gravity is not None:
        terms += [(f"the height of body '{b.name}'", model.gravity.dot(b.position))
                  for b in model.bodies if b.position is not None]
    for what, term in terms:
        usage = _Usage(frozenset(model.q))
        usage.walk(sp.sympify(term))
        for c, qi in declared:
            if qi in usage.aperiodic:
                raise InputError(f"'{c.name}' is declared an angle, which repeats after a turn, but {what} holds "
                                 f"it outside sin and cos, so the potential energy does not (it counts turns); "
                                 f"declare '{c.name}: {{kind: angle, periodic: false}}', with a 'range' for the "
                                 "search", c.loc)


def check_values(problem: Problem, names: Symbols, values: Mapping[sp.Symbol, sp.Expr]) -> None:
    """Masses, dimensions, stiffnesses and natural lengths keep their signs at the values,
    as they must for any values: a parameter declared ``positive: false`` may make a
    mass 0 there (a singular mass matrix, every route).
    The same checks as with symbols (``_require``), with the numbers put in; located
    InputErrors."""
    if not values:
        return
    numbers = replace(names, parameters={k: values.get(s, s) for k, s in names.parameters.items()})
    try:
        for part in (p for body in problem.bodies for p in body.parts):
            _require(numbers.scalar(part.mass), part.mass, "a mass")
            for key, dimension in part.dimensions if part.inertia is None else ():
                if key not in POSITIONS:
                    _require(numbers.scalar(dimension), dimension, _article(key))
        for spring in problem.springs:
            _require(numbers.scalar(spring.stiffness), spring.stiffness, "a stiffness", zero_ok=True)
            if spring.natural_length:
                _require(numbers.scalar(spring.natural_length), spring.natural_length, "a natural length",
                         zero_ok=True)
    except InputError as exc:
        given = ", ".join(f"{k} = {v}" for k, v in values.items())
        raise InputError(f"{exc.message} at the values given ({given})", exc.location) from None


def _affine_in_rates(value: sp.Matrix, expr: Expr, names: Symbols) -> sp.Matrix:
    """A velocity at an instant is affine in the rates q̇: a + Σ b_j q̇_j."""
    qd = names.state.qd
    for item in value:
        if any(sp.diff(item, a, b) != 0 for a in qd for b in qd if item.has(a)):
            raise InputError(f"a velocity must be linear in the rates dot(q), found {expr.text}", expr.loc)
    return value


def _require(value: sp.Expr, expr, what: str, zero_ok: bool = False) -> sp.Expr:
    """A physical constant with the sign it needs, as far as the parameters' signs tell."""
    wrong = value.is_negative if zero_ok else value.is_nonpositive
    if wrong:
        need = "negative" if zero_ok else "zero or negative"
        raise InputError(f"{what} must not be {need}, found {expr.text}", expr.loc)
    return value


def _turns(turns, names: Symbols, start: sp.Matrix | None = None) -> sp.Matrix:
    R = sequence_rotation([(names.axis(turn.axis), names.scalar(turn.angle)) for turn in turns])
    return R if start is None else (start * R).applyfunc(tidy)


def _body(body: Body, names: Symbols, rates: Symbols, triads: Mapping[str, sp.Matrix], masses: dict,
          triad_turns: Mapping[str, tuple]) -> RigidBody:
    """A body's mass properties combined from its parts (once per distinct description,
    ``masses`` keeps them by ``parts_key``); its centre of mass is its origin plus the
    parts' combined centre, turned with the body: r_G = r_at + R c.
    A body at an instant has v_G and ω given instead (a scalar ω turns about z)."""
    key = parts_key(body)
    if key not in masses:
        masses[key] = body_mass_properties(body, names)
    props = masses[key]
    if body.velocity is not None:
        velocity = _affine_in_rates(rates.vector(body.velocity), body.velocity, rates)
        w = body.angular_velocity
        omega = rates.vector(w) if w.kind is Kind.VECTOR else sp.Matrix([0, 0, rates.scalar(w)])
        omega = _affine_in_rates(omega, w, rates)
        return RigidBody(body.name, props.mass, None, sp.eye(3), None, props.inertia, body, velocity, omega)
    if body.orientation:
        start = triads[body.orientation[0]] if isinstance(body.orientation[0], str) else None
        own = [x for x in body.orientation if not isinstance(x, str)]
        rotation = _turns(own, names, start)
        position = names.vector(body.at) + rotation * props.centre
        every = [*(triad_turns[body.orientation[0]] if start is not None else ()), *own]
        turns = unit_turns([(names.axis(x.axis), names.scalar(x.angle)) for x in every])
        return RigidBody(body.name, props.mass, position, rotation, None, props.inertia, body, turns_3d=True,
                         turns=turns)
    angle = names.scalar(body.angle) if body.angle is not None else None
    rotation = sp.rot_axis3(-angle) if angle is not None else sp.eye(3)
    return RigidBody(body.name, props.mass, Later(lambda: _placed(names.vector(body.at), rotation, props.centre)),
                     rotation, angle, props.inertia, body)


def _placed(at: sp.Matrix, rotation: sp.Matrix, centre: sp.Matrix) -> sp.Matrix:
    """r_G = r_at + R c."""
    if any(c != 0 for c in centre):  # adding R·0 would rebuild every sum of r_at for nothing
        return at + rotation * centre
    return at


def parts_key(body: Body) -> tuple:
    """What a body's mass properties depend on besides the names: its parts' trees. Two
    bodies with equal keys have equal properties (a chain of equal links: one key)."""
    tree = lambda e: None if e is None else e.tree  # noqa: E731
    return tuple((p.shape, tree(p.mass), tuple((k, v.tree) for k, v in p.dimensions), tree(p.at), tree(p.axis),
                  tuple(e.tree for e in p.inertia.entries) if p.inertia else None, p.hole) for p in body.parts)


def body_mass_properties(body: Body, names: Symbols) -> MassProperties:
    """A body's mass, centre of mass (from its origin, in body axes) and J about that
    centre, combined from its parts (:func:`rbdsolve.model.inertia.combine`). With
    ``names`` mapping parameters to numbers, the same formulas give numbers."""
    props = combine([(p, p.centre) for p in (part_properties(x, names) for x in body.parts)])
    if props.mass.is_nonpositive:
        raise InputError(f"the total mass of body '{body.name}' is {to_unicode(props.mass)}: the holes "
                         "weigh as much as the parts or more", body.loc)
    return props


def part_properties(part: Part, names: Symbols) -> MassProperties:
    """A part's mass, centre (from the body's origin) and J about that centre, in body
    axes; a hole's mass and inertia count negative."""
    mass = _require(names.scalar(part.mass), part.mass, "a mass")
    if part.inertia is not None:
        props = MassProperties(mass, sp.zeros(3, 1), _explicit(part, names))
    else:
        dims = {k: names.scalar(v) if k in POSITIONS else _require(names.scalar(v), v, _article(k))
                for k, v in part.dimensions}
        _check_tube(part, dims)
        axis = names.axis(part.axis) if part.axis is not None else OWN_AXIS.get(part.shape, sp.Matrix([0, 0, 1]))
        props = body_properties(part.shape, mass, dims, axis)
    offset = names.vector(part.at) if part.at is not None else sp.zeros(3, 1)
    sign = -1 if part.hole else 1
    return MassProperties(sign * props.mass, props.centre + offset, sign * props.inertia)


def _article(noun: str) -> str:
    return f"{'an' if noun[0] in 'aeiou' else 'a'} {noun.replace('_', ' ')}"


def _check_tube(part: Part, dims: dict[str, sp.Expr]) -> None:
    if "inner_radius" in dims and (dims["outer_radius"] - dims["inner_radius"]).is_negative:
        expr = part.dimension("inner_radius")
        raise InputError("a tube's inner_radius must not exceed its outer_radius", expr.loc)


def _explicit(part: Part, names: Symbols) -> sp.Matrix:
    entries = part.inertia.entries
    values = [names.scalar(e) for e in entries]
    diagonal = values if len(values) < 9 else [values[0], values[4], values[8]]
    where = entries if len(values) < 9 else [entries[0], entries[4], entries[8]]
    for value, expr in zip(diagonal, where):
        _require(value, expr, "a moment of inertia", zero_ok=True)
    inertia = explicit_inertia(values)
    if sp.expand(inertia - inertia.T) != sp.zeros(3, 3):
        raise InputError("an inertia matrix must be symmetric (J_xy = J_yx, …)", part.inertia.loc)
    return inertia


def _spring(spring: Spring, names: Symbols) -> SpringModel:
    k = _require(names.scalar(spring.stiffness), spring.stiffness, "a stiffness", zero_ok=True)
    if spring.ends is not None:
        a, b = (names.vector(e) for e in spring.ends)
        d = a - b
        length = sp.sqrt(d.dot(d))
        rest = sp.Integer(0)
        if spring.natural_length:
            rest = _require(names.scalar(spring.natural_length), spring.natural_length,
                            "a natural length", zero_ok=True)
        stretch = length - rest
    else:
        rest = names.scalar(spring.rest) if spring.rest else sp.Integer(0)
        stretch = names.scalar(spring.angle) - rest
    return SpringModel(spring.name, k, stretch, spring)


def declared_ranges(coordinates: tuple, names: Symbols) -> dict[sp.Symbol, tuple[sp.Expr, sp.Expr]]:
    """Each coordinate's declared ``range`` [low, high], by its symbol (q), the ends as
    expressions of the parameters: where it lives, for a spring's sign, the equilibria
    listed and the model's notes."""
    by_name = dict(zip(names.state.names, names.state.q))
    return {by_name[c.name]: (names.scalar(c.range[0]), names.scalar(c.range[1]))
            for c in coordinates if c.range is not None and c.name in by_name}


def signed_springs(springs: tuple[SpringModel, ...], names: Symbols, assumptions: tuple,
                   coordinates: tuple = (), values: dict | None = None) -> tuple[SpringModel, ...]:
    """Each linear spring's length with |u| written ±u where u's sign at the reference
    configuration (q = 0), or over a coordinate's declared range (its ends at the
    parameters' ``values`` too), or a polar distance's r ≥ 0, is known
    (model/energies/spring_length.py)."""
    reference = {q: sp.Integer(0) for q in names.state.q}
    assumed = substitutions(assumptions, names) if assumptions else {}
    ranges = declared_ranges(coordinates, names)
    out = []
    for s in springs:
        if s.source.ends is not None and not s.stretch.has(sp.Abs):  # along a slope: √(u²) = |u| once joined
            s = replace(s, stretch=s.stretch.xreplace({r: as_square_root(r) for r in _roots(s.stretch)}))
        if s.source.ends is not None and sp.expand(s.stretch**2).has(sp.Abs):  # |x|² = x²: nothing to say
            a, b = (names.vector(e) for e in s.source.ends)
            stretch, lengths = signed_length(s.stretch, reference, assumed,
                                             polar_distances(a - b, names.state.q) | ranges, values)
            s = replace(s, stretch=stretch, lengths=lengths)
        out.append(s)
    return tuple(out)


def _roots(expr: sp.Expr) -> set:
    """The square roots in expr (a linear spring's length √(d·d))."""
    return {x for x in expr.atoms(sp.Pow) if x.exp == sp.S.Half}


def _periodic_coordinates(model: Model) -> frozenset:
    """The coordinates q that enter the scene, and only through sin/cos of integer
    multiples of q, so the scene repeats after one turn of q (an AUTO coordinate is then
    an angle). One walk over the scene's expressions serves every coordinate."""
    exprs = [*model.points.values(), *model._positions()]
    exprs += [b.rotation for b in model.bodies]  # ω = α̇ is periodic whatever α is
    exprs += [s.stretch for s in model.springs]
    usage = _Usage(frozenset(model.q))
    for e in exprs:
        for item in (e if isinstance(e, sp.MatrixBase) else [e]):
            usage.walk(sp.sympify(item))
    return frozenset(usage.seen - usage.aperiodic)


class _Usage:
    """Which coordinates occur (``seen``), and which occur other than inside sin/cos of an
    integer multiple of themselves (``aperiodic``); shared subexpressions walked once."""

    def __init__(self, q: frozenset):
        self.q, self.seen, self.aperiodic, self.done = q, set(), set(), set()

    def walk(self, expr: sp.Expr) -> None:
        if expr in self.done:
            return
        self.done.add(expr)
        if expr in self.q:
            self.seen.add(expr)
            self.aperiodic.add(expr)
        elif isinstance(expr, (sp.sin, sp.cos)) and expr.free_symbols & self.q:
            argument = expr.args[0]
            for q in argument.free_symbols & self.q:
                coeff = sp.diff(argument, q)
                self.seen.add(q)
                if not (coeff.is_integer is True and not coeff.has(q)):
                    self.aperiodic.add(q)
        else:
            for arg in expr.args:
                self.walk(arg)
