"""What the generator makes: a problem file's text, and beside it its own description
of the same scene for the oracle (bodies, where each is, springs, supports, applied
forces), in the expression language of the file but built by the generator, so that
the oracle never reads rbdsolve's model of the file.

Points and placements are expressions in the parameters, the coordinates and t; a body
placed by a contact in the file is placed here by the generator's own geometry (the
contact point, the rolling condition integrated by hand), which the oracle checks."""

from __future__ import annotations

from dataclasses import dataclass, field


@dataclass
class Param:
    """A parameter: its dimension (for sampling and the file's units), its value as the
    file writes it (``'20 cm'``) and in SI (``'1/5'``), or none (symbolic: the oracle
    samples it in [low, high] SI)."""

    name: str
    kind: str
    value: str | None = None
    si: str | None = None
    low: float = 0.5
    high: float = 2.0
    positive: bool = True
    description: str = ""


@dataclass
class Part:
    """A piece of a composite body, in body axes from the body's origin."""

    shape: str | None
    mass: str
    dims: dict[str, str] = field(default_factory=dict)
    at: tuple[str, ...] = ("0", "0", "0")
    axis: tuple[float, ...] | None = None
    inertia: str | None = None  # a planar J about its centre instead of a shape
    hole: bool = False


@dataclass
class Body:
    """A rigid body: mass and shape (or given inertia, or parts), its origin's position
    and its turn (a planar angle about z, or body-fixed turns [(axis, angle), …])."""

    name: str
    mass: str = "0"
    shape: str | None = None
    dims: dict[str, str] = field(default_factory=dict)
    axis: tuple[float, ...] | None = None
    inertia: str | tuple[str, ...] | None = None  # planar J_zz, or [J1, J2, J3]
    parts: tuple[Part, ...] = ()
    origin: str = "[0, 0]"
    angle: str | None = None
    turns: tuple[tuple[str, str], ...] | None = None


@dataclass
class Spring:
    """A linear spring between two points (each on a body or the ground: None), or a
    torsional one on an angle, which turns each body by its coefficient in it."""

    name: str
    stiffness: str
    ends: tuple[str, str] | None = None
    on: tuple[str | None, str | None] = (None, None)
    natural_length: str = "0"
    angle: str | None = None
    rest: str = "0"
    turns: dict[str, float] = field(default_factory=dict)  # body -> coefficient in the angle


@dataclass
class Support:
    """Where a support acts on ``body`` (and on ``by`` with the opposite sign): a pivot
    (two components), a guide (the normal), rolling (normal and e_z × normal), a string
    (along ``normal``: the pull on the body), with a moment about z where it cannot turn."""

    name: str
    body: str
    at: str
    kind: str
    by: str | None = None
    normal: str | None = None
    moment: bool = False
    two_sided: bool = False  # a bead on its wire: the push may take either sign


@dataclass
class Force:
    """An applied force at a point of a body, or a couple (about z) on it."""

    name: str
    body: str
    at: str | None = None
    force: str | None = None
    couple: str | None = None


@dataclass
class Coord:
    """A generalized coordinate and where its equilibria are looked for: an angle over
    one turn (periodic), or an interval [low, high] (expressions)."""

    name: str
    kind: str = "angle"
    periodic: bool = True
    low: str | None = None
    high: str | None = None


@dataclass
class Question:
    kind: str
    options: dict = field(default_factory=dict)


@dataclass
class Scene:
    """One generated problem: the file and the oracle's description of it."""

    family: str
    variant: str
    features: tuple[str, ...]
    text: str
    params: list[Param]
    coords: list[Coord]
    questions: list[Question]
    gravity: str | None = None
    points: dict[str, str] = field(default_factory=dict)
    bodies: list[Body] = field(default_factory=list)
    springs: list[Spring] = field(default_factory=list)
    supports: list[Support] = field(default_factory=list)
    forces: list[Force] = field(default_factory=list)
    assumptions: tuple[str, ...] = ()  # python-evaluable constraints on sampled parameters
    checks: tuple[str, ...] = ()       # oracle-side identities (expressions that must vanish for all q)
    planar: bool = True
    still_in: str | None = None        # a frame where the scene is still: its name
    future: str | None = None          # a feature the format does not have yet
    index: int = 0
    seed: int = 0

    @property
    def name(self) -> str:
        return f"{self.index:05d}-{self.family}-{self.variant}"
