"""The options of the questions beyond Lagrange's equations, equilibria and small
oscillations (whose options are in problem/schema.py beside Question): reactions,
energy, kinematics, inertia, impact, steady motion and steady spin. Validated and
located, free of sympy.

A module of their own, imported where a file asks one of these questions
(problem/sections/questions.py) and by their solvers: a file that asks none does not
create their classes (Python generates each frozen dataclass's methods at import,
~0.3 ms a class).
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import Enum

from rbdsolve.errors import Location
from rbdsolve.problem.expr import Expr
from rbdsolve.problem.instants import Instant, StateValue


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
    to: tuple[tuple[str, Expr], ...] = ()  # from rest: the configuration the forces are asked at too


@dataclass(frozen=True)
class EnergyOptions:
    """The energy integral from a start state, and the speed it gives at ``to`` (a
    configuration: coordinate -> value) and of ``points`` along the motion."""

    start: Instant
    to: tuple[tuple[str, Expr], ...]  # () when not asked
    points: tuple[str, ...]
    loc: Location


@dataclass(frozen=True)
class KinematicsOptions:
    """A ``kinematics`` question: the points whose position, velocity and acceleration
    are asked, the state, and distances between points."""

    points: tuple[str, ...]  # the points whose position, velocity and acceleration are asked
    at: tuple[StateValue, ...]  # the state; what it leaves out stays symbolic
    distances: tuple[tuple[str, str], ...] = ()  # pairs of points: |r_B − r_A| and its rate
    bodies: tuple[str, ...] = ()  # bodies whose angular velocity and acceleration are asked
    lines: tuple[tuple[str, str], ...] = ()  # lines through two points: their rate and acceleration of turning


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
