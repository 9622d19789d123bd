"""What every check shares: the parameter points the oracle judges at (the file's
values, or samples of the symbolic parameters that keep the assumptions), a System per
point in 40 digits and in floats, reading rbdsolve's answers there, and comparing."""

from __future__ import annotations

from dataclasses import dataclass, field

import mpmath
import numpy as np

from benchmarks.neighbours.expr import FLOAT, MP, Env, evaluate
from benchmarks.neighbours.oracle.mechanics import System, sample_values
from benchmarks.neighbours.read import Reader
from benchmarks.neighbours.scene import Scene

RTOL_EXACT = 1e-8     # an exact answer evaluated at the values, against the oracle (40 digits)
RTOL_NUMERIC = 1e-6   # a numeric route's float


class Mismatch(Exception):
    """rbdsolve's answer disagrees with the oracle (the message says where and by how much)."""


class Partial(Exception):
    """rbdsolve's answer is right as far as it goes and says itself that it is not complete
    (a warning that other solutions may exist): the part missing is a refusal, with the
    warning as its reason, not a mismatch."""

    def __init__(self, reason: str, detail: str):
        super().__init__(detail)
        self.reason = reason


@dataclass
class Context:
    scene: Scene
    obj: dict
    reader: Reader
    points: list[dict]               # parameter values (mpf), the file's first when all are given
    all_given: bool
    rng: np.random.Generator
    _systems: dict = field(default_factory=dict)

    def system(self, i: int, ns=MP) -> System:
        key = (i, ns is MP)
        if key not in self._systems:
            self._systems[key] = System(self.scene, self.points[i], ns)
        return self._systems[key]

    def const(self, text, i: int):
        """A constant of the question's options (parameters and numbers) at point i."""
        if isinstance(text, (int, float)):
            return mpmath.mpf(text)
        return evaluate(str(text), Env(MP, dict(self.points[i]), {}))

    def state(self, options: dict, i: int):
        """(q, q̇, q̈) from a question's ``from_rest`` or ``at`` option at point i."""
        coords = [c.name for c in self.scene.coords]
        if "from_rest" in options:
            q = [self.const(options["from_rest"][c], i) for c in coords]
            return q, [mpmath.mpf(0)] * len(coords), None
        at = options.get("at", {})
        q = [self.const(at[c], i) for c in coords]
        qd = [self.const(at[f"dot({c})"], i) for c in coords]
        qdd = [self.const(at[f"ddot({c})"], i) if f"ddot({c})" in at else None for c in coords]
        return q, qd, (qdd if all(x is not None for x in qdd) else None)


def context(scene: Scene, obj: dict, draws: int = 2) -> Context:
    coords = [c.name for c in scene.coords]
    reader = Reader(obj.get("symbols", [p.name for p in scene.params]), coords)
    rng = np.random.default_rng([scene.seed, scene.index, 7])
    given = all(p.si is not None for p in scene.params)
    points = [sample_values(scene, rng)] if given else [sample_values(scene, rng) for _ in range(draws)]
    return Context(scene, obj, reader, points, given, rng)


def close(got, want, scale, rtol: float) -> bool:
    """|got − want| ≤ rtol · (|want| + scale): relative, with a floor for zeros."""
    if got is None or want is None:
        return got is None and want is None
    return abs(got - want) <= rtol * (abs(want) + abs(scale))


def fmt(x) -> str:
    if isinstance(x, (list, tuple)):
        return "[" + ", ".join(fmt(y) for y in x) + "]"
    if x is None:
        return "None"
    try:
        return mpmath.nstr(x, 10)
    except Exception:  # noqa: BLE001 - anything printable
        return str(x)


def rtol(result: dict) -> float:
    return RTOL_NUMERIC if result.get("route") == "numeric" else RTOL_EXACT


def points_for(ctx: Context, result: dict) -> list[int]:
    """The parameter points an answer can be read at: a numeric route's numbers hold only
    at the file's values (point 0 when every value is given)."""
    if result.get("route") == "numeric":
        return [0] if ctx.all_given else []
    return list(range(len(ctx.points)))


def boundary_points(ctx: Context, result: dict) -> list[int]:
    """Each printed critical value, crossed: at the first point, its parameter set to 0.9 and
    1.1 times the critical value there (the other parameters kept, the assumptions too), so
    that every condition is judged on both sides of its boundary. The new points are
    added to ctx.points; their indices are returned."""
    from benchmarks.neighbours.oracle.mechanics import _holds
    if result.get("route") == "numeric" or not ctx.points:
        return []
    answers = result.get("answers") or {}
    crit = list(answers.get("critical") or [])
    for entry in answers.get("modes") or [] if isinstance(answers.get("modes"), list) else []:
        crit += entry.get("critical") or []
    out = []
    fixed = {p.name for p in ctx.scene.params if p.si is not None}
    for c in crit:
        name = c.get("parameter")
        if name not in ctx.points[0] or name in fixed:
            continue
        try:
            value = ctx.reader.value(c["value"], ctx.points[0])
        except (ValueError, TypeError):
            continue
        if isinstance(value, mpmath.mpc) or value <= 0:
            continue
        for f in ("0.9", "1.1"):
            point = {**ctx.points[0], name: value * mpmath.mpf(f)}
            if all(_holds(a, point) for a in ctx.scene.assumptions):
                ctx.points.append(point)
                out.append(len(ctx.points) - 1)
    return out


def random_state(ctx: Context, i: int):
    """q, q̇, q̈ drawn in the coordinates' scales, q on the side of every spring along one
    axis that the reference configuration is on (``System.spring_crossed``)."""
    s = ctx.system(i)
    n = s.n
    for _ in range(50):
        q = [mpmath.mpf(float(x) * sc) for x, sc in zip(ctx.rng.uniform(-1, 1, n), s.scale)]
        if not s.spring_crossed(q):
            break
    qd = [mpmath.mpf(float(x)) for x in ctx.rng.uniform(-2, 2, n)]
    qdd = [mpmath.mpf(float(x)) for x in ctx.rng.uniform(-2, 2, n)]
    return q, qd, qdd
