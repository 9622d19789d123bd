"""Small oscillations on small scenes whose answers are known by hand: growth about
an unstable equilibrium, a neutral direction, a point that is not an equilibrium, a
chain of rods."""

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
    assert "not an equilibrium: ∂V/∂θ = 1/2 g l m there" in modes.error
    assert "questions[1].modes.about.theta" in modes.error


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


def test_modes_about_each_with_no_equilibrium_say_so() -> None:
    """Issue 43: a scene with no equilibrium (a falling particle, ∂V/∂y = m g ≠ 0 by hand)
    refused 'modes: {about: each}' with an empty reason ("… could be answered: "), on
    both routes. Now the reason is named on each."""
    scene = """
parameters: {m: mass, g: gravity}
coordinates: [y]
gravity: [0, -g]
points: {P: "[0, y]"}
bodies: {b: {shape: particle, mass: m, at: P}}
questions: [{modes: {about: each}}]
"""
    for text in (scene, scene + "values: {m: 1, g: 9.81}\n"):
        (solution,) = solve_problem(build_model(load_text(text, "falling.yaml"))).solutions
        assert solution.error is not None
        assert "no equilibrium was found among the roots of ∂V/∂q = 0" in solution.error
        assert not solution.error.rstrip(" )").endswith(":")
    assert "in the numeric search's box" in solution.error  # with values, the numeric route too
