"""Solver behaviour at the edges, on small scenes whose answers are known by hand."""

from __future__ import annotations

import sympy as sp

from conftest import CART_PENDULUM
from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.solvers import solve_problem

ROD = """
parameters: {m: mass, l: length, g: gravity, c: stiffness}
coordinates: [theta]
gravity: [0, -g]
points:
  G: l/2 * [sin(theta), -cos(theta)]
bodies:
  rod: {shape: rod, mass: m, length: l, at: G, angle: theta}
"""


CART = "\n" + CART_PENDULUM


def solve(text: str):
    return solve_problem(build_model(load_text(text, "scene.yaml")))


def test_transcendental_equilibria_are_refused_with_the_reason() -> None:
    scene = ROD + "springs:\n  s: {stiffness: c, angle: theta}\nquestions: [equilibria]\n"
    result = solve(scene).solutions[0]
    assert not result.solved
    assert "transcendental" in result.error and "theta" in result.error


def test_modes_about_the_upside_down_rod_grow() -> None:
    # About θ = π: M = m l²/3, K = −m g l/2, so λ = −3g/(2l): growth at √(3g/(2l)).
    result = solve(ROD + "questions:\n  - modes: {about: {theta: pi}}\n").solutions[0]
    g, l = sp.symbols("g l", positive=True)
    assert result.answers.motions[0].value == "growth"
    assert sp.simplify(result.answers.eigenvalues[0] + 3 * g / (2 * l)) == 0
    assert result.answers.frequencies == (None,)


def test_about_a_point_that_is_not_an_equilibrium_fails_only_that_question() -> None:
    report = solve(ROD + "questions:\n  - eom\n  - modes: {about: {theta: pi/2}}\n")
    eom, modes = report.solutions
    assert eom.solved and not modes.solved
    assert "not an equilibrium: ∂V/∂theta = g*l*m/2 there" in modes.error
    assert "questions[1].modes.about.theta" in modes.error


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


def test_modes_with_a_neutral_direction() -> None:
    answers = solve(CART + "questions:\n  - modes: {about: {x: 0, theta: 0}}\n").solutions[0].answers
    m, M, l, g = sp.symbols("m M l g", positive=True)
    # By hand: det(K − λM) = λ (λ M m l² − (M + m) m g l) → λ = 0, (M + m) g/(M l).
    assert answers.eigenvalues[0] == 0
    assert sp.simplify(answers.eigenvalues[1] - (M + m) * g / (M * l)) == 0
    assert [x.value for x in answers.motions] == ["neutral", "oscillation"]
    # Neutral mode: the whole system drifts, a = (1, 0); the oscillation keeps the centre
    # of mass still: (M + m) x + m l θ = 0, so a = (1, −(M + m)/(m l)).
    assert answers.shapes[0] == (1, 0)
    assert sp.simplify(answers.shapes[1][1] + (M + m) / (m * l)) == 0


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


def test_four_rod_chain_against_a_hand_derivation() -> None:
    """n equal uniform rods hanging in a chain, about the hanging position. By hand
    (1-based i, j; rods below a joint carry its motion): M_ij = m l² (n − max(i, j) + ½)
    for i ≠ j, M_ii = m l² (n − i + ⅓), K = m g l diag(n − i + ½). Eigenvalues from
    scipy's generalized symmetric solver; mode shapes must satisfy K a = λ M a."""
    import numpy as np
    from scipy.linalg import eigh

    n = 4
    points = ["  P0: [0, 0]"] + [f"  P{i}: P{i - 1} + l*[sin(q{i}), -cos(q{i})]" for i in range(1, n + 1)]
    bodies = [f"  r{i}: {{shape: rod, mass: m, length: l, at: (P{i - 1} + P{i})/2, angle: q{i}}}"
              for i in range(1, n + 1)]
    about = ", ".join(f"q{i}: 0" for i in range(1, n + 1))
    text = "\n".join(["parameters: {m: mass, l: length, g: gravity}",
                      f"coordinates: [{', '.join(f'q{i}' for i in range(1, n + 1))}]",
                      "gravity: [0, -g]", "points:", *points, "bodies:", *bodies,
                      "values: {m: 1, l: 1, g: 1}", "questions:", f"  - modes: {{about: {{{about}}}}}"])
    result = solve(text).solutions[0]
    assert result.solved, result.error
    M = np.array([[(n - max(i, j) + 0.5) if i != j else (n - i + 1 / 3) for j in range(1, n + 1)]
                  for i in range(1, n + 1)])
    K = np.diag([n - i + 0.5 for i in range(1, n + 1)])
    expected = eigh(K, M, eigvals_only=True)
    assert np.allclose(result.values["eigenvalues"], expected, rtol=1e-12)
    for lam, shape in zip(result.values["eigenvalues"], result.values["shapes"]):
        a = np.array(shape, dtype=float)
        assert np.abs(K @ a - lam * M @ a).max() < 1e-9 * np.abs(a).max()
