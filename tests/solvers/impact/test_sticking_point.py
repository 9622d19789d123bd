"""A body's point that sticks (issue 40, item 7): it becomes a pivot at the instant.
Expected values from an independent impulse–momentum computation in each test (the
Newton–Euler impulse equations of the free rod, solved here by sympy), or by hand."""

from __future__ import annotations

import random

import pytest
import sympy as sp

from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.solvers import Options, solve_problem

ROD = """
parameters: {m: mass, L: length, v0: speed, u: speed, beta: angle}
coordinates: [x, y, theta]
points:
  G: [x, y]
  A: G - L/2*[cos(theta), sin(theta)]
bodies:
  rod: {shape: rod, mass: m, length: L, at: G, angle: theta}
questions:
  - impact:
      at: {theta: AT}
      before: BEFORE
      collisions:
        A: {sticks: true}
"""


def _solve(text: str):
    model = build_model(load_text(text, "scene.yaml"))
    solution = solve_problem(model, Options()).solutions[0]
    assert solution.error is None, solution.error
    return model, solution.answers


def _newton_euler(beta, u, v0, w0, m, L):
    """The rod's impulse equations, unknowns v_G after, ω after and the ledge's impulse
    P at A: m Δv_G = P, (m L²/12) Δω = ((r_A − r_G) × P)_z, and A at rest after,
    v_G + ω e_z × (r_A − r_G) = 0."""
    vx, vy, w, Px, Py = sp.symbols("vx vy w Px Py")
    d = -L / 2 * sp.Matrix([sp.cos(beta), sp.sin(beta)])  # r_A − r_G
    equations = [m * (vx - u) - Px, m * (vy + v0) - Py,
                 m * L**2 / 12 * (w - w0) - (d[0] * Py - d[1] * Px),
                 vx - w * d[1], vy + w * d[0]]
    return sp.solve(equations, [vx, vy, w, Px, Py], dict=True)[0], (vx, vy, w, Px, Py)


def test_a_rod_falling_flat_catches_a_ledge_with_one_end() -> None:
    """By hand: angular momentum about A is kept, m v₀ L/2 = (m L²/3) ω, so ω = 3v₀/(2L)
    (clockwise: the free end goes on down); v_G = −3v₀/4, the ledge's impulse m v₀/4 up."""
    model, answers = _solve(ROD.replace("AT", "0").replace("BEFORE", "{y: -v0}"))
    p = model.symbols.parameters
    m, L, v0 = p["m"], p["L"], p["v0"]
    assert sp.simplify(answers.velocities["theta"] + 3 * v0 / (2 * L)) == 0
    assert sp.simplify(answers.velocities["y"] + 3 * v0 / 4) == 0 and answers.velocities["x"] == 0
    assert sp.simplify(sp.Matrix(answers.sticking_impulses["A"]) - sp.Matrix([0, m * v0 / 4, 0])) == sp.zeros(3, 1)
    assert sp.simplify(answers.energy_lost - m * v0**2 / 8) == 0
    assert all(x == 0 for x in answers.support_impulse)  # a free rod: the ledge is the only support


@pytest.mark.parametrize("at", ["beta", "pi/6", "-pi/3"])
def test_a_tilted_rod_moving_sideways_catches_the_ledge_as_newton_euler_says(at: str) -> None:
    """A rod at angle β, moving at (u, −v₀) and turning at ω₀ = v₀/L before: both
    components of the ledge's impulse, and the motion after, as the Newton–Euler impulse
    equations give them."""
    text = ROD.replace("AT", at).replace("BEFORE", "{x: u, y: -v0, theta: v0/L}")
    model, answers = _solve(text)
    p = model.symbols.parameters
    m, L, v0, u = p["m"], p["L"], p["v0"], p["u"]
    beta = p["beta"] if at == "beta" else sp.sympify(at)
    expected, (vx, vy, w, Px, Py) = _newton_euler(beta, u, v0, v0 / L, m, L)
    rng = random.Random(7)
    for _ in range(5):
        at_values = {s: sp.Rational(rng.randint(1, 40), 7) for s in (m, L, v0, u)}
        at_values[p["beta"]] = sp.Rational(rng.randint(-30, 30), 17)
        got = [answers.velocities["x"], answers.velocities["y"], answers.velocities["theta"],
               *answers.sticking_impulses["A"][:2]]
        for g, e in zip(got, (expected[vx], expected[vy], expected[w], expected[Px], expected[Py])):
            assert abs(sp.N((g - e).xreplace(at_values), 30)) < 1e-20


def test_a_ball_sticks_to_the_rim_of_a_turntable() -> None:
    """A ball moving at v₀ along the rim's tangent sticks to it: angular momentum about the
    axle, m R v₀ = (M R²/2 + m R²) ω, so ω = 2 m v₀/((M + 2m) R); the axle's impulse is
    the ball's change of momentum, −M m v₀/(M + 2m) along the tangent."""
    model, answers = _solve("""
parameters: {M: mass, m: mass, R: length, v0: speed}
coordinates: [phi, x, y]
points:
  P: [x, y]
  Q: R*[cos(phi), sin(phi)]
bodies:
  table: {shape: disk, mass: M, radius: R, at: [0, 0], angle: phi}
  ball: {shape: particle, mass: m, at: P}
questions:
  - impact:
      at: {phi: 0, x: R, y: 0}
      before: {y: v0}
      collisions:
        P: {sticks: true, to: Q}
""")
    p = model.symbols.parameters
    M, m, R, v0 = p["M"], p["m"], p["R"], p["v0"]
    assert sp.simplify(answers.velocities["phi"] - 2 * m * v0 / ((M + 2 * m) * R)) == 0
    assert sp.simplify(answers.support_impulse[1] + M * m * v0 / (M + 2 * m)) == 0
    assert sp.simplify(answers.energy_after - m**2 * v0**2 / (M + 2 * m)) == 0


def test_a_fixed_point_cannot_stick() -> None:
    """A point that does not move at the instant: sticking would change nothing, and the
    file probably names the ledge instead of the rod's end."""
    text = ROD.replace("AT", "0").replace("BEFORE", "{y: -v0}").replace("A: {sticks", "O: {sticks")
    text = text.replace("  A: G", "  O: [0, 0]\n  A: G")
    model = build_model(load_text(text, "scene.yaml"))
    solution = solve_problem(model, Options()).solutions[0]
    assert "the point O cannot move at the instant" in solution.error
