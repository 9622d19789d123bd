"""Independent oracle for the equations of motion of scenes with prescribed motion and
moving frames: a driven or accelerated support, a frame that turns at a constant rate.

What is compared. For each scene rbdsolve's ``eom`` answers (``EomAnswers``) are checked
against a derivation with ``sympy.physics.mechanics``:

* ``equations`` (Lagrange's equations in the scene's inertial axes) and, for every frame
  asked for, that frame's ``equations`` against the equations of LagrangesMethod;
* for every frame, ``equivalent`` is True, and L − L' − dF/dt simplifies to 0, where L is
  the oracle's own Lagrangian T − V, L' is rbdsolve's ``lagrangian`` in the frame, F its
  ``total_derivative``, and d/dt is sympy's ``diff`` with respect to t with the functions
  of time left as they are (an ``Integral(..., t)`` in F differentiates to its integrand).

Why it is independent. No rbdsolve model code is used for the expected side: every scene
is derived from scratch in the INERTIAL frame N with ReferenceFrame / Point / Particle /
RigidBody / dynamicsymbols; velocities are P.pos_from(O).dt(N) (a moving support or a
turning hoop is a prescribed position or orientation in N, never a frame of rbdsolve's),
angular velocities come from orientnew, and the equations from
LagrangesMethod(Lagrangian(N, ...), q).form_lagranges_equations(). rbdsolve is only run
on the YAML (``load_file`` / ``load_text``, ``build_model``, ``solve_problem``).

Symbols. rbdsolve writes t = Symbol('t', real=True), coordinates and unknown prescribed
functions as Function(name, real=True)(t), and parameters as positive Symbols. The
oracle creates its parameters as the same positive Symbols, and its dynamicsymbols (of
dynamicsymbols._t) are rewritten into rbdsolve's functions of rbdsolve's t
(``to_rbdsolve``): every derivative d^k f/dt^k, then f(t), then t itself.

Normalisation. An equation may legitimately differ from LagrangesMethod's by an overall
nonzero constant factor (or sign). Both sides are rewritten in plain real Symbols for q,
q', q'' (and y_A, y_A', y_A'', ...); for the equation of coordinate q_i the factor is
k = (coefficient of q_i'' in the oracle's equation) / (coefficient of q_i'' in
rbdsolve's). k must be nonzero and free of the coordinates, of the prescribed functions
and of t, and simplify(k * rbdsolve − oracle) must be 0.
"""

from __future__ import annotations

import dataclasses
import functools
from pathlib import Path
from typing import Callable

import pytest
import sympy as sp
from sympy.core.function import AppliedUndef
from sympy.physics.mechanics import (
    LagrangesMethod,
    Lagrangian,
    Particle,
    Point,
    ReferenceFrame,
    RigidBody,
    dynamicsymbols,
    inertia,
)

from rbdsolve.model.build import build_model
from rbdsolve.problem import load_file, load_text
from rbdsolve.solvers import solve_problem

ROOT = Path(__file__).resolve().parents[2]
P5 = ROOT / "problems" / "sg2150-2015-10-29" / "p5-accelerated-pendulum.yaml"
PIVOT = ROOT / "problems" / "examples" / "pendulum-oscillating-pivot.yaml"
HOOP_FILES = sorted((ROOT / "problems" / "frames").glob("rotating-hoop*.yaml"))
HOOP_FILES = [p for p in HOOP_FILES if not p.name.endswith(".expected.yaml")]

T = sp.Symbol("t", real=True)  # rbdsolve's time
_t = dynamicsymbols._t  # mechanics' time


def positive(names: str):
    return sp.symbols(names, positive=True)


# --------------------------------------------------------------------------- symbols


def to_rbdsolve(expr):
    """A mechanics expression in rbdsolve's symbols: d^k f(_t)/d_t^k ->
    Derivative(f_r(t), (t, k)), f(_t) -> f_r(t), _t -> t, with f_r = Function(name, real=True)."""
    expr = sp.sympify(expr)

    def fn(f):
        return sp.Function(f.func.__name__, real=True)(T)

    derivatives = {}
    for d in expr.atoms(sp.Derivative):
        assert isinstance(d.expr, AppliedUndef) and d.variables == (_t,) * d.derivative_count, d
        derivatives[d] = sp.Derivative(fn(d.expr), (T, d.derivative_count))
    expr = expr.xreplace(derivatives)
    functions = {f: fn(f) for f in expr.atoms(AppliedUndef) if f.args == (_t,)}
    return expr.xreplace(functions).xreplace({_t: T})


def plain(expr):
    """rbdsolve's functions of t as plain real Symbols: Derivative(q(t), (t, k)) -> q_dk,
    q(t) -> q. Time t itself stays."""
    expr = sp.sympify(expr)
    derivatives = {}
    for d in expr.atoms(sp.Derivative):
        f = d.expr
        assert isinstance(f, AppliedUndef) and f.args == (T,) and d.variables == (T,) * d.derivative_count, d
        derivatives[d] = sp.Symbol(f"{f.func.__name__}_d{d.derivative_count}", real=True)
    expr = expr.xreplace(derivatives)
    for f in expr.atoms(AppliedUndef):
        assert f.args == (T,), f"unexpected function {f}"
    return expr.xreplace({f: sp.Symbol(f.func.__name__, real=True) for f in expr.atoms(AppliedUndef)})


def dynamic_names(expr) -> set[sp.Symbol]:
    """The plain symbols standing for functions of time (coordinates, prescribed)."""
    return {s for s in expr.free_symbols if not s.is_positive and s != T}


def assert_same_equation(oracle, theirs, q: str, what: str) -> None:
    """Equal up to a nonzero constant factor fixed by the coefficients of q''."""
    a, b = plain(oracle), plain(theirs)
    qdd = sp.Symbol(f"{q}_d2", real=True)
    ka, kb = sp.simplify(sp.diff(a, qdd)), sp.simplify(sp.diff(b, qdd))
    assert ka != 0, f"{what}: the oracle's equation has no {q}'': {oracle}"
    assert kb != 0, f"{what}: rbdsolve's equation has no {q}'': {theirs}"
    k = sp.simplify(ka / kb)
    assert k != 0 and not dynamic_names(k) and not k.has(T), (
        f"{what}: the factor between the equations is not a nonzero constant: k = {k}\n"
        f"  oracle:   {oracle} = 0\n  rbdsolve: {theirs} = 0")
    diff = sp.simplify(k * b - a)
    assert diff == 0, (f"{what}: k*rbdsolve − oracle = {diff} (k = {k})\n"
                       f"  oracle:   {oracle} = 0\n  rbdsolve: {theirs} = 0")


# --------------------------------------------------------------------------- oracle


@dataclasses.dataclass(frozen=True)
class Mechanics:
    L: sp.Expr  # T − V, in mechanics' dynamicsymbols
    equations: tuple[sp.Expr, ...]  # LagrangesMethod's, one per coordinate
    coordinates: tuple[str, ...]


def lagrange(N: ReferenceFrame, q: list, *bodies) -> Mechanics:
    L = Lagrangian(N, *bodies)
    eqs = LagrangesMethod(L, q).form_lagranges_equations()
    # doit(): sympy writes ∂|r|/∂r as sign(r) * Derivative(r(t), r(t)), which is 1.
    return Mechanics(L, tuple(e.doit() for e in eqs), tuple(x.func.__name__ for x in q))


def inertial_origin():
    N = ReferenceFrame("N")
    O = Point("O")
    O.set_vel(N, 0)
    return N, O


def moving(point: Point, origin: Point, N: ReferenceFrame) -> Point:
    """The point's velocity in N, from its position: v = d/dt(r_P − r_O) in N."""
    point.set_vel(N, point.pos_from(origin).dt(N))
    return point


def mech_accelerated_pendulum() -> Mechanics:
    """p5: particle B on a massless rod of length l from A = (0, y_A(t)); gravity −g y."""
    m, l, g = positive("m l g")
    phi, y_A = dynamicsymbols("phi y_A")
    N, O = inertial_origin()
    A = O.locatenew("A", y_A * N.y)
    B = moving(A.locatenew("B", l * (sp.sin(phi) * N.x - sp.cos(phi) * N.y)), O, N)
    bob = Particle("bob", B, m)
    bob.potential_energy = m * g * (B.pos_from(O) & N.y)
    return lagrange(N, [phi], bob)


def mech_oscillating_pivot() -> Mechanics:
    """Particle on a rod of length l from O' = (a cos Ω t, 0); gravity −g y."""
    m, l, g, a, Omega = positive("m l g a Omega")
    phi = dynamicsymbols("phi")
    N, O = inertial_origin()
    pivot = O.locatenew("pivot", a * sp.cos(Omega * _t) * N.x)
    P = moving(pivot.locatenew("P", l * (sp.sin(phi) * N.x - sp.cos(phi) * N.y)), O, N)
    bob = Particle("bob", P, m)
    bob.potential_energy = m * g * (P.pos_from(O) & N.y)
    return lagrange(N, [phi], bob)


def mech_rotating_hoop() -> Mechanics:
    """Bead on a hoop of radius R whose plane is turned about N.y by the prescribed angle
    Ω t; θ from the lowest point; gravity −g y. The velocity is the inertial one."""
    m, R, g, Omega = positive("m R g Omega")
    theta = dynamicsymbols("theta")
    N, O = inertial_origin()
    H = N.orientnew("H", "Axis", (Omega * _t, N.y))  # the hoop's plane, a prescribed orientation
    P = moving(O.locatenew("P", R * sp.sin(theta) * H.x - R * sp.cos(theta) * H.y), O, N)
    bead = Particle("bead", P, m)
    bead.potential_energy = m * g * (P.pos_from(O) & N.y)
    return lagrange(N, [theta], bead)


def mech_rod_on_carriage() -> Mechanics:
    """Uniform rod (mass m, length l) hanging from A = (x_A(t), 0), at angle φ from the
    downward vertical; its centre G is l/2 from A; gravity −g y."""
    m, l, g = positive("m l g")
    phi, x_A = dynamicsymbols("phi x_A")
    N, O = inertial_origin()
    B = N.orientnew("B", "Axis", (phi, N.z))  # the rod lies along B.y
    A = O.locatenew("A", x_A * N.x)
    G = moving(A.locatenew("G", -l / 2 * B.y), O, N)
    rod = RigidBody("rod", G, B, m, (inertia(B, m * l**2 / 12, 0, m * l**2 / 12), G))
    rod.potential_energy = m * g * (G.pos_from(O) & N.y)
    return lagrange(N, [phi], rod)


def mech_turntable_slot() -> Mechanics:
    """Particle at distance r along a radial slot turned about N.z by Ω t, held by a
    spring (k, natural length l0) from the centre O; no gravity. r may be negative (the
    slot runs through O), so r is real and |OP| = |r|."""
    m, k, l0, Omega = positive("m k l0 Omega")
    r = dynamicsymbols("r", real=True)
    N, O = inertial_origin()
    S = N.orientnew("S", "Axis", (Omega * _t, N.z))  # the slot's direction, prescribed
    P = moving(O.locatenew("P", r * S.x), O, N)
    slider = Particle("slider", P, m)
    slider.potential_energy = k * (P.pos_from(O).magnitude() - l0) ** 2 / 2
    return lagrange(N, [r], slider)


# --------------------------------------------------------------------------- scenes

HOOP_INLINE = """\
parameters: {m: mass, R: radius, g: gravity, Omega: rate}
coordinates: [theta]
gravity: [0, -g, 0]
frames:
  hoop: {axis: y, rate: Omega}
points:
  P: R * [sin(theta)*cos(Omega*t), -cos(theta), -sin(theta)*sin(Omega*t)]
bodies:
  bead: {shape: particle, mass: m, at: P}
questions:
  - eom: {frames: [hoop]}
"""

CARRIAGE = """\
title: A rod pendulum hanging from a carriage driven horizontally
parameters: {m: mass, l: length, g: gravity}
prescribed:
  x_A: unknown
coordinates: [phi]
gravity: [0, -g]
frames:
  carriage: {origin: A}
points:
  A: [x_A, 0]
  G: A + l/2 * [sin(phi), -cos(phi)]
bodies:
  rod: {shape: rod, mass: m, length: l, at: G, angle: phi, axis: y}
questions:
  - eom: {frames: [carriage]}
"""

TURNTABLE = """\
title: A particle on a spring in a radial slot of a turntable
parameters: {m: mass, k: stiffness, l0: natural length, Omega: rate}
coordinates: [r]
frames:
  turntable: {axis: z, rate: Omega}
points:
  O: [0, 0]
  P: r * [cos(Omega*t), sin(Omega*t)]
bodies:
  slider: {shape: particle, mass: m, at: P}
springs:
  s: {between: [O, P], stiffness: k, natural_length: l0}
questions:
  - eom: {frames: [turntable]}
"""


@dataclasses.dataclass(frozen=True)
class Scene:
    id: str
    source: Path | str  # a file, or inline YAML
    mechanics: Callable[[], Mechanics]
    frames_required: bool  # the scene must ask for at least one frame

    def load(self):
        if isinstance(self.source, Path):
            return load_file(self.source)
        return load_text(self.source, f"{self.id}.yaml")


SCENES = [
    Scene("p5-accelerated-pendulum", P5, mech_accelerated_pendulum, True),
    Scene("pendulum-oscillating-pivot", PIVOT, mech_oscillating_pivot, False),
    *([Scene(p.stem, p, mech_rotating_hoop, True) for p in HOOP_FILES]
      or [Scene("rotating-hoop-inline", HOOP_INLINE, mech_rotating_hoop, True)]),
    Scene("rod-on-carriage", CARRIAGE, mech_rod_on_carriage, True),
    Scene("turntable-slot-spring", TURNTABLE, mech_turntable_slot, True),
]
BY_ID = {s.id: s for s in SCENES}


@functools.lru_cache(maxsize=None)
def mechanics(scene_id: str) -> Mechanics:
    return BY_ID[scene_id].mechanics()


@functools.lru_cache(maxsize=None)
def solved(scene_id: str):
    """(the frames the eom question asks for, rbdsolve's EomAnswers)."""
    problem = BY_ID[scene_id].load()
    report = solve_problem(build_model(problem))
    solution = report.solutions[0]
    assert solution.question == "eom", f"the first question is {solution.question}, not eom"
    assert solution.answers is not None, f"eom not answered: {solution.error}"
    options = problem.questions[0].options
    asked = tuple(options.frames) if options is not None else ()
    return asked, solution.answers


@pytest.fixture(params=[s.id for s in SCENES])
def scene(request) -> Scene:
    return BY_ID[request.param]


# --------------------------------------------------------------------------- tests


def test_equations_match_mechanics(scene):
    mech = mechanics(scene.id)
    _, eom = solved(scene.id)
    assert len(eom.equations) == len(mech.coordinates)
    for q, ours, theirs in zip(mech.coordinates, mech.equations, eom.equations):
        assert_same_equation(to_rbdsolve(ours), theirs, q, f"{scene.id}: equation for {q}")


def test_every_frame_asked_is_answered(scene):
    asked, eom = solved(scene.id)
    if scene.frames_required:
        assert asked, f"{scene.id}: the eom question asks for no frame"
    assert tuple(f.frame for f in eom.frames) == asked
    if asked:
        assert eom.equivalent is True


def test_frame_equations_match_mechanics(scene):
    mech = mechanics(scene.id)
    _, eom = solved(scene.id)
    for frame in eom.frames:
        assert len(frame.equations) == len(mech.coordinates)
        for q, ours, theirs in zip(mech.coordinates, mech.equations, frame.equations):
            assert_same_equation(to_rbdsolve(ours), theirs, q, f"{scene.id}, frame {frame.frame}: equation for {q}")


def test_frame_lagrangian_differs_by_a_total_derivative(scene):
    """L − L' − dF/dt = 0 with the oracle's L and sympy's own d/dt of F(q(t), t)."""
    L = to_rbdsolve(mechanics(scene.id).L)
    _, eom = solved(scene.id)
    for frame in eom.frames:
        assert frame.equivalent is True, f"{scene.id}, frame {frame.frame}: rbdsolve says not equivalent"
        rest = sp.simplify(L - frame.lagrangian - sp.diff(frame.total_derivative, T))
        assert rest == 0, (f"{scene.id}, frame {frame.frame}: L − L' − dF/dt = {rest}\n"
                           f"  L  = {L}\n  L' = {frame.lagrangian}\n  F  = {frame.total_derivative}")


def test_oracle_knows_the_textbook_results():
    """Sanity of the oracle itself: the textbook forms of two of its equations."""
    m, l, g, R, Omega = positive("m l g R Omega")
    phi, theta, y_A = (sp.Function(n, real=True)(T) for n in ("phi", "theta", "y_A"))
    p5 = to_rbdsolve(mechanics("p5-accelerated-pendulum").equations[0])
    assert sp.simplify(p5 - m * l * (l * phi.diff(T, 2) + (g + y_A.diff(T, 2)) * sp.sin(phi))) == 0
    hoop = to_rbdsolve(mech_rotating_hoop().equations[0])
    expected = m * R**2 * (theta.diff(T, 2) - Omega**2 * sp.sin(theta) * sp.cos(theta)) + m * g * R * sp.sin(theta)
    assert sp.simplify(hoop - expected) == 0
