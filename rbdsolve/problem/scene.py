"""What a scene may hold beyond its bodies and points: rolling contacts (on a line, a
circle, another body's edge, a plane) and strings wound on drums, over pulleys;
springs; applied forces and couples; moving frames; quantities prescribed as functions
of time; assumptions between the parameters. Validated and located, free of sympy, like
the rest of the Problem (problem/schema.py).

A module of their own, imported where a file has these sections (problem/loader.py)
and where they are modelled: a scene without them does not create their classes
(Python generates each frozen dataclass's methods at import, ~0.3 ms a class).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

from rbdsolve.errors import Location
from rbdsolve.problem.expr import Expr
from rbdsolve.problem.surfaces import Measure, SurfaceKind


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


@dataclass(frozen=True)
class Pulley:
    """A string wound on the round ``edge`` of body ``drum`` (or at ``radius`` about its
    centre) leaves it along the constant ``direction`` to a light pulley at ``over``,
    and hangs from there along ``down`` with the contact's body at its end, ``length``
    below ``over`` at the reference configuration (model/constraints/strings.py); a pulley
    with mass is the body ``wheel``, centred on a fixed axle and turned by the string
    without slipping (its angle the string's travel over its rim's radius). Without a pulley
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
    wheel: str | None = None  # the pulley at ``over`` has mass: this body, turned by the string without slipping
    wheel_loc: Location | None = None


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

    kind: ClassVar[str] = "force"  # what a message calls it


@dataclass(frozen=True)
class Couple:
    """A couple (a torque) ``moment`` on body ``on`` (a scalar about z, or a vector), and
    −moment on body ``by`` where it acts at a joint between the two (a motor)."""

    name: str
    on: str
    by: str | None
    moment: Expr
    loc: Location

    kind: ClassVar[str] = "couple"  # what a message calls it


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
class Prescribed:
    """A quantity that follows a given function of time, not a degree of freedom: an
    unknown function y_A(t) (``value`` None; its derivatives stay symbolic) or an
    explicit expression in t and the parameters."""

    name: str
    value: Expr | None
    loc: Location


@dataclass(frozen=True)
class Assumption:
    """``lhs op rhs`` between constant expressions, op one of < ≤ > ≥ (assumptions:)."""

    lhs: Expr
    op: str  # "<", "<=", ">" or ">="
    rhs: Expr
    text: str
    loc: Location
