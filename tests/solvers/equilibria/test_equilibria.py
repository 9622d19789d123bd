"""Equilibria on small scenes whose answers are known by hand: refusals, neutral
directions, equilibria that exist only for some parameters."""

from __future__ import annotations

import sympy as sp

from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.solvers import solve_problem

from conftest import CART_PENDULUM, ROD_PENDULUM

ROD = "\n" + ROD_PENDULUM
CART = "\n" + CART_PENDULUM

def solve(text: str):
    return solve_problem(build_model(load_text(text, "scene.yaml")))


def test_transcendental_equilibria_give_their_evident_roots_with_the_reason() -> None:
    """A hanging rod with a torsion spring: ∂V/∂θ = c θ + ½ m g l sin θ (by hand) has no
    closed form for every root, but θ = 0 makes each term vanish; V''(0) = c + ½ m g l > 0,
    so it is stable. θ = π is no root (c π ≠ 0). The list is said to be partial."""
    scene = ROD + "springs:\n  s: {stiffness: c, angle: theta}\nquestions: [equilibria]\n"
    result = solve(scene).solutions[0]
    assert result.solved and result.route.value == "exact", result.error
    assert [(e.at["theta"], e.stability.value) for e in result.answers.equilibria] == [(0, "stable")]
    (note,) = [w for w in result.warnings if "evident roots" in w]
    assert "transcendental" in note and "c θ" in note  # the equation, printed as the answers are
    assert "other equilibria may exist" in note.lower() and "θ in ±10π" in note  # where the numeric route looks


def test_transcendental_equilibria_without_an_evident_root_are_refused_with_the_reason() -> None:
    """The same rod whose spring rests at θ = 1: ∂V/∂θ = c (θ − 1) + ½ m g l sin θ vanishes
    at none of 0, ±π/2, π (c (−1), c (π/2 − 1) + ½ m g l, …: not zero for every value)."""
    scene = ROD + "springs:\n  s: {stiffness: c, angle: theta, rest: 1}\nquestions: [equilibria]\n"
    result = solve(scene).solutions[0]
    assert not result.solved
    assert "transcendental" in result.error and "no evident root" in result.error


def test_a_coordinate_that_v_ignores_is_neutral() -> None:
    # A cart (x) carrying a pendulum (θ): V depends on θ only; x is a neutral direction.
    report = solve(CART + "questions: [equilibria, modes]\n")
    equilibria = report.solutions[0]
    stable = [e for e in equilibria.answers.equilibria if e.at["theta"] == 0]
    assert stable[0].stability.value == "neutral"
    assert any("does not depend on x" in w for w in equilibria.warnings)
    # Modes: λ = 0 (the cart drifts) and λ = (M + m) g/(M l) (by hand: K = diag(0, m g l),
    # M = [[M + m, m l], [m l, m l²]], det(K − λM) = λ (λ M m l² − (M + m) m g l)).
    # With no stable equilibrium (only neutral ones) the default 'modes' refuses.
    assert not report.solutions[1].solved
    assert "no stable equilibrium" in report.solutions[1].error


COND = """
parameters: {m: mass, l: length, g: gravity, k: stiffness}
coordinates: [theta]
gravity: [0, -g]
points:
  P: l * [sin(theta), -cos(theta)]
  A: [0, -l*cos(theta)]
bodies:
  bob: {shape: particle, mass: m, at: P}
springs:
  s: {stiffness: k, between: [P, A]}
questions: [equilibria]
"""


def test_equilibria_that_exist_only_for_some_parameters() -> None:
    # By hand: ∂V/∂θ = l (m g + k l cos θ) sin θ: θ = 0, π, and cos θ = −m g/(k l),
    # which exists only when k l ≥ m g.
    found = solve(COND).solutions[0].answers.equilibria
    assert len(found) == 4
    conditional = [e for e in found if e.conditions]
    assert len(conditional) == 2
    g, m, k, l = sp.symbols("g m k l", positive=True)
    assert sp.simplify(conditional[0].conditions[0] - (1 - (m * g / (k * l)) ** 2)) == 0
    low = solve(COND + "values: {m: 1, l: 1, g: 10, k: 1}\n").solutions[0].answers.equilibria
    assert sorted(float(e.at["theta"]) for e in low) == [0.0, float(sp.pi)]
    high = solve(COND + "values: {m: 1, l: 1, g: 10, k: 20}\n").solutions[0].answers.equilibria
    assert len(high) == 4


def test_a_rolling_coordinate_with_a_periodic_potential_is_solved_completely_and_the_repeat_said() -> None:
    """A cylinder rolling in a cylinder: θ enters the cylinder's angle bare (φ = −(R − r) θ/r),
    so the scene is not 2π-periodic in θ, but V = −m g (R − r) cos θ is: by hand the
    equilibria are θ = 0 and π, and θ₀ + 2kπ repeat them (the cylinder rolled on)."""
    from rbdsolve.problem import load_file
    from rbdsolve.solvers.equilibria.exact import find_equilibria, repeating

    from conftest import PROBLEMS

    model = build_model(load_file(PROBLEMS / "contacts" / "cylinder-in-cylinder.yaml"))
    (theta,) = model.q
    assert theta not in model.angles and repeating(model) == {theta}
    solutions, warnings = find_equilibria(model)
    assert sorted(s[theta] for s in solutions) == [0, sp.pi]
    assert not any("may miss solutions" in w for w in warnings)
    assert any("∂V/∂θ is 2π-periodic in θ though" in w and "rolling body's travel" in w
               and "repeats at θ₀ + 2kπ" in w for w in warnings)


def test_a_spring_of_zero_length_at_an_equilibrium_is_no_internal_error() -> None:
    """A particle on a circle of radius a tied by a spring to the point (a, 0) of it (the
    fuzzer's scene): V = ½ k |a(cos θ − 1, sin θ)|² = k a² (1 − cos θ), so by hand θ = 0 is
    stable (the spring's length is zero there, where |r| is not differentiable) and π
    unstable."""
    text = """
parameters: {m: mass, k: stiffness, a: offset}
coordinates: [theta]
points:
  A: [a, 0]
  P0: a * [cos(theta), sin(theta)]
bodies: {b0: {shape: particle, mass: m, at: P0}}
springs: {s: {stiffness: k, between: [P0, A]}}
questions: [equilibria]
"""
    (solution,) = solve_problem(build_model(load_text(text))).solutions
    assert solution.error is None, solution.error
    got = {sp.sympify(e.at["theta"]): e.stability.value for e in solution.answers.equilibria}
    assert got == {sp.Integer(0): "stable", sp.pi: "unstable"}


def test_a_circle_of_equilibria_is_refused_as_a_continuum() -> None:
    # A particle at (x, y) on a spring from O of natural length L: V = ½ k (√(x² + y²) − L)²,
    # ∂V/∂x = k (r − L) x/r and ∂V/∂y = k (r − L) y/r vanish all round the circle r = L:
    # no isolated equilibrium to list (sympy's solve leaves y free there).
    scene = """\
parameters: {m: mass, k: stiffness, L: natural length}
coordinates: [x, y]
points: {O: [0, 0], P: [x, y]}
bodies: {bead: {shape: particle, mass: m, at: P}}
springs: {s: {between: [O, P], stiffness: k, natural_length: L}}
questions: [equilibria]
"""
    result = solve(scene).solutions[0]
    assert not result.solved
    assert "continuum" in result.error


def test_an_angle_declared_not_periodic_is_said_so_where_its_equilibria_repeat() -> None:
    """A rod on a pivot with θ declared 'periodic: false' (a new user's, turned by a
    couple): ∂V/∂θ = ½ m g l sin θ − C repeats every 2π, so do its equilibria; the
    warning gave a rolling body's travel as the reason, and said V repeats (it need not)."""
    from rbdsolve.problem import load_text
    from rbdsolve.solvers.equilibria.exact import find_equilibria

    model = build_model(load_text("""
parameters: [m, l, g, C]
coordinates: {theta: {kind: angle, periodic: false}}
gravity: [0, -g]
bodies:
  rod: {shape: rod, mass: m, length: l, at: "l/2*[sin(theta), -cos(theta)]", angle: theta, axis: y}
couples:
  turn: {on: rod, moment: C}
questions: [equilibria]
"""))
    _, warnings = find_equilibria(model)
    (said,) = [w for w in warnings if "2π-periodic" in w]
    assert said.startswith("∂V/∂θ is 2π-periodic in θ") and "declared 'periodic: false'" in said
