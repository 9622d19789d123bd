"""The Problem: what a problem file says, validated, located, and still free of sympy.

Every expression is a :class:`~rbdsolve.problem.expr.Expr` (a checked tree plus the
place it came from), so later stages can point back at the file when a value turns out
to be wrong (a negative length, a singular mass matrix).

Here: the Problem, its parameters, coordinates, points and bodies, its questions and
the options of eom, equilibria and modes. What a scene holds beyond its bodies
(contacts, springs, loads, frames, assumptions) is in problem/scene.py, the other
questions' options in problem/options.py: each loaded where a file has them. The
kinds of surface (problem/surfaces.py) and a state of the motion (problem/instants.py)
are modules of their own, which these share.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from enum import Enum
from fractions import Fraction
from typing import TYPE_CHECKING, Mapping

from rbdsolve.errors import Location
from rbdsolve.problem.expr import Expr
from rbdsolve.problem.instants import Instant
from rbdsolve.problem.quantities.quantity import Dimension, Unit, Value

if TYPE_CHECKING:
    from rbdsolve.problem.options import (EnergyOptions, ImpactOptions, InertiaOptions, KinematicsOptions,
                                          ReactionsOptions, SteadyMotionOptions, SteadySpinOptions)
    from rbdsolve.problem.scene import Assumption, Contact, Couple, Force, Frame, Prescribed, Spring


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
                 "semicircular_plate": Shape.HALF_DISK, "semicircular_wire": Shape.HALF_RING,
                 "solid_sphere": Shape.SPHERE, "solid_cylinder": Shape.CYLINDER, "solid_disk": Shape.DISK,
                 "hollow_sphere": Shape.SPHERICAL_SHELL, "hollow_cylinder": Shape.CYLINDRICAL_SHELL}  # fmt: skip


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


@dataclass(frozen=True)
class EomOptions:
    """What an ``eom`` question asks beyond Lagrange's equations: the equations in moving
    frames too, and q̈ at a state."""

    frames: tuple[str, ...]  # frames to write the Lagrangian and the equations in, too
    instant: Instant | None = None  # where to give q̈ too (numbers with values)


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

    def body(self, name: str) -> Body:
        return next(b for b in self.bodies if b.name == name)

    def dimension_map(self) -> dict[str, Dimension]:
        return dict(self.dimensions)

    def value_map(self) -> dict[str, Value]:
        return dict(self.values)

    def angle_values(self) -> frozenset[str]:
        """The parameters whose values are given in angle units (30 deg): angles, shown
        with their degrees."""
        return frozenset(name for name, value in self.values if value.angle)

    def with_values(self, values: Mapping[str, Value]) -> Problem:
        """The same problem with these values, as if written under ``values:`` (``--set``,
        the API's ``values=``): each overrides the file's in its place, the others follow
        in the order given. Values are the problem's data, not how it is solved: the
        model is built from them."""
        if not values:
            return self
        table = dict(self.values)
        table.update(values)
        # a unit given with the value makes the parameter's dimension known, as under 'values:'
        # (--set b="10 cm" on a file that says nothing of b: Ω = 2 g (L m − M b)/(m r² s) in rad/s)
        dimensions = dict(self.dimensions)
        dimensions.update({n: v.dimension for n, v in values.items() if n not in dimensions and v.dimension is not None})
        return replace(self, values=tuple(table.items()), dimensions=tuple(sorted(dimensions.items())))
