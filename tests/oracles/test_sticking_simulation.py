"""Independent numerical oracle for sticking impacts: the particle is joined to the point
it strikes by a very strong damper, F = −c (v_particle − v_point) on the particle and −F
on the body, which brings their relative velocity to zero in a time of order m/c; the
motion is integrated (scipy Radau) and compared with rbdsolve's answers just after.

Nothing of rbdsolve's model is used: the equations of each scene are written here by
hand (a rod about a fixed pivot; a free rod), and the support's impulse is the change of
the whole system's momentum (the damper is internal). The damper acts for 40 time
constants m/c = 10 ns, while the body turns by about 1e-6 rad: the simulated state
differs from the impulsive one by about that (a 1 µs constant gave 1.6e-3 in the pivot's
impulse, through the rod's turn); TOL = 1e-4 relative, |sim − exact| ≤ TOL·max(1, |exact|).
Energies before and after count the particle, as the answers must.
"""

from __future__ import annotations

import numpy as np
from scipy.integrate import solve_ivp

from conftest import PROBLEMS
from rbdsolve.model.build import build_model
from rbdsolve.problem import load_file, load_text
from rbdsolve.solvers import solve_problem

TOL = 1e-4


def _close(sim: float, exact: float) -> bool:
    return abs(sim - exact) <= TOL * max(1.0, abs(exact))


def _answers(problem):
    (solution,) = solve_problem(build_model(problem)).solutions
    assert solution.error is None, solution.error
    return solution.values


def _settle(rhs, y0, c_over_m: float):
    """Integrate until the damper has acted for 40 of its time constants m/c."""
    run = solve_ivp(rhs, (0.0, 40.0 / c_over_m), y0, method="Radau", rtol=1e-10, atol=1e-13)
    assert run.success, run.message
    return run.y[:, -1]


def test_bullet_lodging_in_a_hanging_rod() -> None:
    """problems/impact/bullet-embeds-in-hanging-rod.yaml: rod M = 4 kg, l = 1.2 m about
    O; bullet m = 0.02 kg at (300, −40) m/s into the lower end A at θ = 0."""
    M, l, m, u = 4.0, 1.2, 0.02, np.array([300.0, -40.0])
    c = m / 1e-8  # the damper's time constant m/c = 10 ns: θ moves ~1e-6 while it acts
    I_O = M * l**2 / 3

    def rhs(_, y):
        theta, w, xp, yp, vx, vy = y
        vA = l * w * np.array([np.cos(theta), np.sin(theta)])
        rA = l * np.array([np.sin(theta), -np.cos(theta)])
        F = -c * (np.array([vx, vy]) - vA)  # on the bullet; −F on the rod at A
        torque = rA[0] * (-F[1]) - rA[1] * (-F[0])
        return [w, torque / I_O, vx, vy, F[0] / m, F[1] / m]

    theta, w, *_, vx, vy = _settle(rhs, [0.0, 0.0, 0.0, -l, *u], c / m)
    momentum_after = M * (l / 2) * w * np.array([np.cos(theta), np.sin(theta)]) + m * np.array([vx, vy])
    support = momentum_after - m * u
    energy_lost = m * u @ u / 2 - (I_O * w**2 / 2 + m * (vx**2 + vy**2) / 2)
    got = _answers(load_file(PROBLEMS / "impact" / "bullet-embeds-in-hanging-rod.yaml"))
    assert _close(w, got["velocities"]["theta"])
    assert all(_close(s, e) for s, e in zip(support, got["support_impulse"][:2]))
    assert _close(energy_lost, got["energy_lost"])
    assert all(_close(s, e) for s, e in zip((vx, vy), got["particles"]["A"][:2]))


FREE_ROD = """\
parameters: {M: mass, l: length, m: clay mass, u: clay speed to the left, v: clay speed up}
values: {M: 3, l: 2, m: 1/2, u: 1, v: 2}
coordinates: [x, y, theta]
points:
  G: [x, y]
  A: G + l/2 * [cos(theta), sin(theta)]
bodies:
  rod: {shape: rod, mass: M, length: l, at: G, angle: theta}
questions:
  - impact:
      at: {theta: pi/6}
      collisions:
        A: {particle: {mass: m, velocity: [-u, v]}, sticks: true}
"""


def test_clay_sticking_obliquely_to_a_free_rod() -> None:
    """A free rod (M = 3, l = 2) at rest at θ = π/6 on a smooth table; clay (m = 1/2) at
    (−1, 2), oblique to the rod, sticks to its end A. Nothing supports the rod: the
    system's momentum is kept, and the support impulse is 0."""
    M, l, m, u = 3.0, 2.0, 0.5, np.array([-1.0, 2.0])
    c = 1e8 * m
    I_G = M * l**2 / 12

    def rhs(_, y):
        x, yy, theta, vxg, vyg, w, xp, yp, vx, vy = y
        e = np.array([np.cos(theta), np.sin(theta)])
        vA = np.array([vxg, vyg]) + l / 2 * w * np.array([-e[1], e[0]])
        F = -c * (np.array([vx, vy]) - vA)
        arm = l / 2 * e
        torque = arm[0] * (-F[1]) - arm[1] * (-F[0])
        return [vxg, vyg, w, -F[0] / M, -F[1] / M, torque / I_G, vx, vy, F[0] / m, F[1] / m]

    start = [0.0, 0.0, np.pi / 6, 0.0, 0.0, 0.0, l / 2 * np.cos(np.pi / 6), l / 2 * np.sin(np.pi / 6), *u]
    *_, vxg, vyg, w, _, _, vx, vy = _settle(rhs, start, c / m)
    got = _answers(load_text(FREE_ROD, "free.yaml"))
    assert all(_close(s, got["velocities"][k]) for s, k in zip((vxg, vyg, w), ("x", "y", "theta")))
    lost = m * u @ u / 2 - (M * (vxg**2 + vyg**2) / 2 + I_G * w**2 / 2 + m * (vx**2 + vy**2) / 2)
    assert _close(lost, got["energy_lost"]) and lost > 0.1  # not a vacuous check
    assert all(_close(s, 0.0) for s in got["support_impulse"])
    impulse_on_rod = M * np.array([vxg, vyg])  # all the rod's momentum came from the clay
    assert all(_close(s, e) for s, e in zip(impulse_on_rod, got["sticking_impulses"]["A"][:2]))
