"""The Problem: what a problem file says, validated, located, and still free of sympy.

Every expression is a :class:`~rbdsolve.problem.expr.Expr` (a checked tree plus the
place it came from), so later stages can point back at the file when a value turns out
to be wrong (a negative length, a singular mass matrix).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from enum import Enum
from fractions import Fraction
from typing import Mapping

from rbdsolve.errors import Location
from rbdsolve.problem.expr import Expr
from rbdsolve.problem.quantities.quantity import Dimension, Unit, Value


class Shape(Enum):
    """The shape library. Each shape lists its dimensions; its axes are documented in
    docs/format.md and its inertia formula lives in :mod:`rbdsolve.model.inertia`."""

    PARTICLE = "particle"
    ROD = "rod"
    RING = "ring"
    DISK = "disk"
    CYLINDRICAL_SHELL = "cylindrical_shell"
    CYLINDER = "cylinder"
    TUBE = "tube"
    SPHERICAL_SHELL = "spherical_shell"
    SPHERE = "sphere"
    HEMISPHERE = "hemisphere"
    HEMISPHERICAL_SHELL = "hemispherical_shell"
    HALF_DISK = "half_disk"
    HALF_RING = "half_ring"
    QUARTER_DISK = "quarter_disk"
    CYLINDER_SEGMENT = "cylinder_segment"
    CONE = "cone"
    BOX = "box"
    PLATE = "plate"
    TRIANGLE = "triangle"

    @property
    def dimensions(self) -> tuple[str, ...]:
        return _DIMENSIONS[self]

    @property
    def edges(self) -> tuple[str, ...]:
        """The named parts of its boundary a contact may use (model/constraints/edges.py gives
        their geometry); the first is the default when a contact names none."""
        return _EDGES.get(self, ())


_DIMENSIONS = {
    Shape.PARTICLE: (),
    Shape.ROD: ("length",),
    Shape.RING: ("radius",),
    Shape.DISK: ("radius",),
    Shape.CYLINDRICAL_SHELL: ("radius", "height"),
    Shape.CYLINDER: ("radius", "height"),
    Shape.TUBE: ("inner_radius", "outer_radius", "height"),
    Shape.SPHERICAL_SHELL: ("radius",),
    Shape.SPHERE: ("radius",),
    Shape.HEMISPHERE: ("radius",),
    Shape.HEMISPHERICAL_SHELL: ("radius",),
    Shape.HALF_DISK: ("radius",),
    Shape.HALF_RING: ("radius",),
    Shape.QUARTER_DISK: ("radius",),
    Shape.CYLINDER_SEGMENT: ("radius", "height", "half_angle"),
    Shape.CONE: ("radius", "height"),
    Shape.BOX: ("width", "depth", "height"),
    Shape.PLATE: ("width", "height"),
    Shape.TRIANGLE: ("base", "height", "apex"),
}

_ROUND = ("rim",)  # the whole circle of a round shape (a cylinder's or sphere's section)
_EDGES = {
    Shape.RING: _ROUND, Shape.DISK: _ROUND, Shape.CYLINDRICAL_SHELL: _ROUND, Shape.CYLINDER: _ROUND,
    Shape.TUBE: _ROUND, Shape.SPHERICAL_SHELL: _ROUND, Shape.SPHERE: _ROUND,
    Shape.HEMISPHERE: ("curved", "flat"), Shape.HEMISPHERICAL_SHELL: ("curved",),
    Shape.HALF_DISK: ("curved", "flat"), Shape.HALF_RING: ("curved",), Shape.QUARTER_DISK: ("curved",),
    Shape.CYLINDER_SEGMENT: ("curved", "flat"),
    Shape.PLATE: ("bottom", "top"), Shape.ROD: ("bottom", "top"),
}  # fmt: skip

SHAPE_ALIASES = {"point": Shape.PARTICLE, "hoop": Shape.RING, "slender_rod": Shape.ROD,
                 "rectangle": Shape.PLATE, "shell": Shape.CYLINDRICAL_SHELL,
                 "ball": Shape.SPHERE, "cuboid": Shape.BOX, "solid_hemisphere": Shape.HEMISPHERE,
                 "semicircular_plate": Shape.HALF_DISK, "semicircular_wire": Shape.HALF_RING}  # fmt: skip


class CoordinateKind(Enum):
    ANGLE = "angle"  # periodic: equilibria are reported modulo one turn
    LENGTH = "length"
    AUTO = "auto"  # decided from how the coordinate enters the energies


class QuestionKind(Enum):
    EOM = "eom"
    EQUILIBRIA = "equilibria"
    MODES = "modes"
    INERTIA = "inertia"
    IMPACT = "impact"
    STEADY_SPIN = "steady_spin"
    STEADY_MOTION = "steady_motion"
    KINEMATICS = "kinematics"
    REACTIONS = "reactions"
    ENERGY = "energy"

    @property
    def needs_coordinates(self) -> bool:
        return self not in (QuestionKind.INERTIA, QuestionKind.STEADY_SPIN, QuestionKind.STEADY_MOTION)

    @property
    def needs_positions(self) -> bool:
        """Does the question need the motion (positions as functions of the coordinates),
        not just the velocities at one instant?"""
        return self in (QuestionKind.EOM, QuestionKind.EQUILIBRIA, QuestionKind.MODES, QuestionKind.KINEMATICS,
                        QuestionKind.REACTIONS, QuestionKind.ENERGY)


@dataclass(frozen=True)
class Parameter:
    """A parameter of the problem: its name, what it is, whether it is positive, and its
    unit where one is declared."""

    name: str
    description: str
    positive: bool
    loc: Location
    unit: Unit | None = None  # declared (parameters: {r: {unit: cm}}): a bare value is in it


@dataclass(frozen=True)
class Prescribed:
    """A quantity that follows a given function of time, not a degree of freedom: an
    unknown function y_A(t) (``value`` None; its derivatives stay symbolic) or an
    explicit expression in t and the parameters."""

    name: str
    value: Expr | None
    loc: Location


@dataclass(frozen=True)
class Coordinate:
    """A generalized coordinate: an angle, a length, or decided from the energies; an
    angle may be declared not periodic, and a search range given."""

    name: str
    kind: CoordinateKind
    loc: Location
    periodic: bool | None = None  # an angle's 'periodic' (None: not declared; an angle is periodic)
    range: tuple[Expr, Expr] | None = None  # the declared search range [low, high], constants


@dataclass(frozen=True)
class Point:
    """A point given by its position (a vector that may name other points), or, in a
    scene at one instant, by its velocity (linear in the rates dot(q))."""

    name: str
    position: Expr | None
    velocity: Expr | None = None


@dataclass(frozen=True)
class Inertia:
    """An explicit inertia about the centre of mass in body axes: a planar moment J_zz,
    three principal moments, or a full symmetric 3x3 matrix (row-major, 9 entries)."""

    entries: tuple[Expr, ...]
    loc: Location


@dataclass(frozen=True)
class Part:
    """A piece of a body: a shape with its mass and dimensions (or an explicit inertia),
    its origin at ``at`` from the body's origin in body axes, its own axis along
    ``axis``. A hole is a part whose mass is removed."""

    name: str
    shape: Shape | None  # None when ``inertia`` is given instead
    mass: Expr
    dimensions: tuple[tuple[str, Expr], ...]
    at: Expr | None  # None: at the body's origin
    axis: Expr | None  # direction, in body axes, of the shape's own axis (None: its default)
    inertia: Inertia | None
    hole: bool
    loc: Location

    def dimension(self, name: str) -> Expr:
        return dict(self.dimensions)[name]


@dataclass(frozen=True)
class Turn:
    """One body-fixed turn of a rotation sequence: by ``angle`` about ``axis``."""

    axis: Expr
    angle: Expr


@dataclass(frozen=True)
class Triad:
    """A named frame by a sequence of body-fixed turns from the scene axes; its unit
    vectors get the names in ``vectors`` (e1, e2, e3) and may be used in positions."""

    name: str
    turns: tuple[Turn, ...]
    vectors: tuple[str, str, str]
    loc: Location


@dataclass(frozen=True)
class Body:
    """A rigid body: one part (a shape placed at ``at``) or several (``parts:``).

    A body in a scene at one instant (an impact) gives ``velocity`` (of its centre of
    mass) and ``angular_velocity`` instead of ``at`` and ``angle``.
    """

    name: str
    parts: tuple[Part, ...]
    at: Expr | None  # position of the body's origin (a simple body: the shape's origin)
    angle: Expr | None  # planar orientation: rotation about z
    loc: Location
    velocity: Expr | None = None
    angular_velocity: Expr | None = None  # a scalar (planar, about z) or a vector
    orientation: tuple[str | Turn, ...] = ()  # 3D: a triad's name first, if any, then turns
    points: tuple[tuple[str, Expr], ...] = ()  # its own points: name -> offset from its origin, in body axes


class SurfaceKind(Enum):
    LINE = "line"  # a straight line (a floor, an incline, a string)
    CIRCLE = "circle"  # a circle (a drum, a track, a bowl in its plane)
    BODY = "body"  # an edge of another body, moving with it (a turning disk, a sliding plank)
    PLANE = "plane"  # a fixed plane in 3D (a table): rolling there is not integrable, kept as a constraint


@dataclass(frozen=True)
class Surface:
    """A fixed (or translating) line or circle a body rolls on.

    A line passes through ``point`` along ``direction`` (a vector) and the body lies on
    its left (``flip``: on its right); a circle has its centre at ``point`` and the body
    rolls on its ``inside`` or outside. A body's edge (kind BODY) names the body and the
    edge; it moves and turns with that body. A plane (kind PLANE, in 3D) has the
    normal ``direction`` towards the body and passes through ``point`` (None: not said)."""

    kind: SurfaceKind
    point: Expr | None  # None: a body's edge, or a plane through no stated point
    direction: Expr | None  # line; a plane's normal
    radius: Expr | None  # circle
    inside: bool  # circle: inside; line: the body on the right of ``direction``
    loc: Location
    body: str | None = None  # BODY: the body whose edge it is
    edge: str | None = None  # BODY: which edge
    part: str | None = None  # BODY: the part of a composite body whose edge it is (None: its only part)


class Measure(Enum):
    """What a contact's coordinate measures."""

    ANGLE = "angle"  # the body's turn (counterclockwise)
    ALONG = "along"  # the contact point's travel: a distance along a line, an angle round a circle


@dataclass(frozen=True)
class Pulley:
    """A string wound on the round ``edge`` of body ``drum`` (or at ``radius`` about its
    centre) leaves it along the constant ``direction`` to a light pulley at ``over``,
    and hangs from there along ``down`` with the contact's body at its end, ``length``
    below ``over`` at the reference configuration (model/constraints/strings.py). Without a pulley
    (``over`` None) it runs straight along ``direction`` from the drum's ``side`` to the
    body, ``length`` from the rim at the reference."""

    drum: str
    edge: str
    radius: Expr | None
    over: Expr | None  # None: no pulley, the body hangs straight from the drum
    direction: Expr
    down: Expr | None  # None: straight down, [0, −1]
    length: Expr | None  # None: the straight part's length at the reference (0 without a pulley)
    loc: Location
    side: str | None = None  # without a pulley: left, right, above or below the drum's centre, as drawn
    part: str | None = None  # the drum's part the string is wound on (None: its only part)


@dataclass(frozen=True)
class Contact:
    """Body ``body`` rolls without slipping on ``surface`` with its ``edge``; the
    coordinate ``coordinate`` (a declared one) measures the motion as ``measure`` says,
    and rolling fixes the rest (model/constraints/contacts.py). A string wound on a drum is a
    line the drum rolls on (``string``), at the winding ``radius``. A composite body
    touches with one of its parts (``part``); a body given by its inertia rolls on the
    circle of ``radius`` about its centre of mass."""

    name: str  # the contact point C
    body: str
    edge: str
    surface: Surface
    coordinate: str | None  # None: a body hanging from a pulley (its place follows from the drum's)
    measure: Measure | None
    radius: Expr | None  # a string's winding radius, or the radius the body rolls at; None: the edge's own
    string: bool
    loc: Location
    pulley: Pulley | None = None  # the body hangs on a string from a drum, over a pulley
    part: str | None = None  # the part of a composite body that touches (None: its only part)


@dataclass(frozen=True)
class Spring:
    """A linear spring between two points, or a torsional spring on an angle.

    V = k/2 (|r_a - r_b| - natural_length)^2   or   V = k/2 (angle - rest)^2
    """

    name: str
    stiffness: Expr
    ends: tuple[Expr, Expr] | None
    natural_length: Expr | None
    angle: Expr | None
    rest: Expr | None
    loc: Location


@dataclass(frozen=True)
class Wound:
    """A string wound at ``radius`` about a force's point, leaving it tangentially on
    ``side`` (below, above, left or right of the point, as drawn) along the force."""

    radius: Expr
    side: str
    loc: Location


@dataclass(frozen=True)
class Force:
    """A force applied to body ``on``, taken by its material point at ``at`` (None: the
    body's origin): ``force`` a vector (constant, or a function of t and the
    coordinates), or, with ``towards``, a size along the line from that point to
    ``towards`` (a string pulled over a peg there); ``wound``: a string wound on the body
    about ``at``, so the force acts where the string leaves it (model/energies/loads.py)."""

    name: str
    on: str
    at: Expr | None
    force: Expr
    towards: Expr | None
    wound: Wound | None
    loc: Location


@dataclass(frozen=True)
class Couple:
    """A couple (a torque) ``moment`` on body ``on`` (a scalar about z, or a vector), and
    −moment on body ``by`` where it acts at a joint between the two (a motor)."""

    name: str
    on: str
    by: str | None
    moment: Expr
    loc: Location


@dataclass(frozen=True)
class Frame:
    """A frame moving relative to the scene's (inertial) axes: its origin follows
    ``origin`` (a point or a vector in t; None: the scene's origin), and it turns at the
    constant rate ``rate`` about the fixed direction ``axis`` through that origin (None:
    it does not turn)."""

    name: str
    origin: Expr | None
    axis: Expr | None
    rate: Expr | None
    loc: Location


@dataclass(frozen=True)
class Instant:
    """A state of the motion: every coordinate's value and every rate's (``at:``), or
    every coordinate's with the rates zero (``from_rest:``, just after release)."""

    coordinates: tuple[tuple[str, Expr], ...]  # coordinate -> value, in the coordinates' order
    rates: tuple[tuple[str, Expr], ...]  # coordinate -> its rate's value; () when from rest
    from_rest: bool
    loc: Location


@dataclass(frozen=True)
class EomOptions:
    """What an ``eom`` question asks beyond Lagrange's equations: the equations in moving
    frames too, and q̈ at a state."""

    frames: tuple[str, ...]  # frames to write the Lagrangian and the equations in, too
    instant: Instant | None = None  # where to give q̈ too (numbers with values)


class SupportKind(Enum):
    """What holds a body at a point, as the reactions question reads it."""

    POINT = "point"  # a point of a body held by the ground or another body: the kinematics decide
    CONTACT = "contact"  # a rolling contact or string from 'contacts:'


@dataclass(frozen=True)
class Support:
    """A force asked for: at point ``point`` on body ``on``, from the ground (``by`` None)
    or from body ``by``; or the contact named ``point``. ``normal``: the direction a
    one-sided push is counted positive along (None: against gravity). ``two_sided``: a
    guide that holds both ways (a bead threaded on its wire, a pin in a slot), so its
    push may change sign and no contact is lost."""

    kind: SupportKind
    point: str
    on: str
    by: str | None
    normal: Expr | None
    loc: Location
    two_sided: bool = False


@dataclass(frozen=True)
class ReactionsOptions:
    """A ``reactions`` question: the supports whose forces are asked, at a state or as
    functions of the state."""

    supports: tuple[Support, ...]
    instant: Instant | None  # None: the forces as functions of the state
    loc: Location


@dataclass(frozen=True)
class EnergyOptions:
    """The energy integral from a start state, and the speed it gives at ``to`` (a
    configuration: coordinate -> value) and of ``points`` along the motion."""

    start: Instant
    to: tuple[tuple[str, Expr], ...]  # () when not asked
    points: tuple[str, ...]
    loc: Location


@dataclass(frozen=True)
class EquilibriaOptions:
    """An ``equilibria`` question: relative equilibria in a moving frame, or in the
    scene's axes."""

    frame: str | None  # relative equilibria in a moving frame; None: the scene's axes
    for_parameter: str | None = None  # 'for: k': conditions solved for k first (docs/format.md)


@dataclass(frozen=True)
class ModesOptions:
    """A ``modes`` question: the equilibrium to linearize about (given, numbered, each,
    or the stable one), a frame, and amplitudes to check by simulation."""

    about: tuple[tuple[str, Expr], ...] | None  # the equilibrium (refined if near one); None: see equilibrium
    frame: str | None = None
    check_amplitudes: tuple[Fraction, ...] = ()  # amplitudes to simulate each mode at (solvers/modes/amplitude.py)
    equilibrium: int | None = None  # 'about: {equilibrium: N}', as 'equilibria' numbers them; neither: the stable one
    each: bool = False  # 'about: each': the modes at every equilibrium
    loc: Location | None = None  # where 'about' is
    steady: tuple[tuple[str, Expr], ...] = ()  # 'about: {dot(phi): s}': cyclic coordinates' steady rates
    for_parameter: str | None = None  # 'for: k': conditions solved for k first (docs/format.md)


@dataclass(frozen=True)
class StateValue:
    """One entry of a state ``at:``: a coordinate (order 0), its rate dot(q) (1) or its
    acceleration ddot(q) (2), and its constant value."""

    coordinate: str
    order: int
    value: Expr


@dataclass(frozen=True)
class KinematicsOptions:
    """A ``kinematics`` question: the points whose position, velocity and acceleration
    are asked, the state, and distances between points."""

    points: tuple[str, ...]  # the points whose position, velocity and acceleration are asked
    at: tuple[StateValue, ...]  # the state; what it leaves out stays symbolic
    distances: tuple[tuple[str, str], ...] = ()  # pairs of points: |r_B − r_A| and its rate


@dataclass(frozen=True)
class InertiaOptions:
    """An ``inertia`` question: the body, the point and axes (or one axis) the inertia
    tensor is asked about, at a configuration."""

    body: str  # the body asked about
    about: Expr | None  # a point (vector); None: the centre of mass only
    axes: tuple[Expr, Expr, Expr] | None  # unit vectors of a rotated frame; None: scene axes
    at: tuple[tuple[str, Expr], ...] = ()  # coordinate -> value: the configuration asked about
    axis: Expr | None = None  # a direction (scene axes) through 'about' (or G): J = eᵀ J_P e


@dataclass(frozen=True)
class Particle:
    """A particle that strikes the system: its mass, its velocity just before, and
    (optionally) just after, which makes the impulse known."""

    mass: Expr
    velocity: Expr
    after: Expr | None
    loc: Location


@dataclass(frozen=True)
class Collision:
    """Point ``point`` of the system hits a fixed surface (no particle) or is hit by a
    particle. The impulse on the system is along ``normal``; its size follows from
    Newton's law of restitution with coefficient ``restitution``, or from the
    particle's velocity ``after``."""

    point: str
    normal: Expr | None
    restitution: Expr | None
    particle: Particle | None
    loc: Location
    sticks: bool = False  # the particle embeds (or, without one, the point sticks): it moves with the point after
    to: str | None = None  # a sticking point of a body sticks to this point of another body (None: a fixed point)


@dataclass(frozen=True)
class ImpactOptions:
    """An ``impact`` question: the configuration and the rates just before, the impulses
    and collisions, the points asked about after, and a centre of percussion to find."""

    at: tuple[tuple[str, Expr], ...]  # the configuration at the instant (some coordinates)
    before: tuple[tuple[str, Expr], ...]  # generalized velocities just before (default 0)
    impulses: tuple[tuple[str, Expr], ...]  # known impulses: point -> vector
    collisions: tuple[Collision, ...]
    points: tuple[str, ...]  # points whose velocities after are asked for
    centre_of_percussion: str | None  # a parameter to solve "no impulse on the supports" for
    loc: Location


@dataclass(frozen=True)
class Reaction:
    """An unknown contact force: its point of application and its vector, in which
    declared unknowns (N, x_N) stand for what the balances must find."""

    at: Expr
    force: Expr


@dataclass(frozen=True)
class SteadyMotionOptions:
    """A ``steady_motion`` question: the body, the triad the motion is steady in, the
    point for angular momentum, rolling contacts, reactions and what to solve for."""

    body: str
    triad: str  # the turning triad the motion is steady in
    about: Expr  # the point to take angular momentum about
    contacts: tuple[Expr, ...]  # points where the body rolls without slipping on a fixed surface
    reactions: tuple[Reaction, ...]  # contact forces stated with unknowns; then both balances count
    solve_for: tuple[Expr, ...]  # constants to solve the relations for (omega0**2; or N, x_N)
    reactions_loc: Location | None = None  # where 'reactions' is, for errors about them
    for_parameter: str | None = None  # 'for: s': conditions solved for s first (docs/format.md)


@dataclass(frozen=True)
class PrecessionOptions:
    """The free motion of an axisymmetric body, seen from space: ω's component along the
    symmetry axis (``spin``) and either its component across it (``transverse``) or the
    angle between ω and the axis (``angle``)."""

    spin: Expr
    transverse: Expr | None
    angle: Expr | None


@dataclass(frozen=True)
class SteadySpinOptions:
    """A ``steady_spin`` question: the free body, and its torque-free precession where
    asked."""

    body: str  # the free body asked about
    precession: PrecessionOptions | None = None  # torque-free precession, asked with 'precession'


@dataclass(frozen=True)
class Question:
    """One question of the problem: its kind, its options, and where it is in the file."""

    kind: QuestionKind
    options: (EomOptions | EquilibriaOptions | ModesOptions | InertiaOptions | ImpactOptions
              | SteadySpinOptions | SteadyMotionOptions | KinematicsOptions | ReactionsOptions | EnergyOptions
              | None)
    loc: Location


@dataclass(frozen=True)
class ValueRange:
    """A parameter whose value is drawn per exam variant (``rbdsolve variants``): from
    the grid low, low + step, … ≤ high, or from ``choices``. ``rbdsolve solve`` keeps
    such a parameter symbolic, as if it had no value."""

    name: str
    low: Value
    high: Value
    step: Value | None  # None with choices
    choices: tuple[Value, ...]  # not empty: drawn from these instead of the grid
    loc: Location

    @property
    def size(self) -> int:
        """How many values there are to draw from: the grid's end is taken when it is
        within rounding of a step (π/12 … π/3 in steps of π/12 has 4)."""
        if self.choices:
            return len(self.choices)
        return int(math.floor((self.high.approx - self.low.approx) / self.step.approx + 1e-9)) + 1

    def value(self, k: int) -> Value:
        """The k-th value (0-based) of the grid or of the choices, exactly."""
        return self.choices[k] if self.choices else self.low.step(k, self.step)


@dataclass(frozen=True)
class Assumption:
    """``lhs op rhs`` between constant expressions, op one of < ≤ > ≥ (assumptions:)."""

    lhs: Expr
    op: str  # "<", "<=", ">" or ">="
    rhs: Expr
    text: str
    loc: Location


@dataclass(frozen=True)
class Problem:
    """A problem file, validated and located: parameters, coordinates, points, bodies,
    springs, gravity, values, the questions, and what frames, triads, contacts and
    assumptions add. Free of sympy."""

    file: str
    title: str
    source: str
    statement: str
    parameters: tuple[Parameter, ...]
    coordinates: tuple[Coordinate, ...]
    points: tuple[Point, ...]  # in dependency order: a point only names earlier ones
    bodies: tuple[Body, ...]
    springs: tuple[Spring, ...]
    gravity: Expr | None
    values: tuple[tuple[str, Value], ...]  # parameter values, exact, in SI units
    questions: tuple[Question, ...]
    prescribed: tuple[Prescribed, ...] = ()
    frames: tuple[Frame, ...] = ()
    unknowns: tuple[str, ...] = ()  # constant unknowns, such as a steady spin rate
    triads: tuple[Triad, ...] = ()
    ranges: tuple[ValueRange, ...] = ()  # parameters drawn per variant; symbolic otherwise
    assumptions: tuple[Assumption, ...] = ()  # inequalities between parameters (R > r)
    contacts: tuple[Contact, ...] = ()  # rolling contacts and strings (problem/sections/contacts.py)
    dimensions: tuple[tuple[str, Dimension], ...] = ()  # parameters whose dimension is known
    forces: tuple[Force, ...] = ()  # applied forces (problem/sections/loads.py)
    couples: tuple[Couple, ...] = ()  # applied couples and motor torques

    def frame(self, name: str) -> Frame:
        return next(f for f in self.frames if f.name == name)

    def dimension_map(self) -> dict[str, Dimension]:
        return dict(self.dimensions)

    def value_map(self) -> dict[str, Value]:
        return dict(self.values)

    def with_values(self, values: Mapping[str, Value]) -> Problem:
        """The same problem with these values, as if written under ``values:`` (``--set``,
        the API's ``values=``): each overrides the file's in its place, the others follow
        in the order given. Values are the problem's data, not how it is solved: the
        model is built from them."""
        if not values:
            return self
        table = dict(self.values)
        table.update(values)
        return replace(self, values=tuple(table.items()))
