"""Torque-free precession of an axisymmetric body, checked against a simulation of
Euler's equations and of the body's rotation (scipy), not against rbdsolve's formulas."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from rbdsolve.errors import InputError
from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.solvers import solve_problem
from rbdsolve.solvers.routes.options import Options, RouteChoice

SCENE = """\
parameters: {{m: mass, r: radius, Omega: spin, w: rate across}}
values: {{m: 2, r: 1/2, Omega: 3, w: 2}}
bodies:
  b: {{shape: cylinder, mass: m, radius: r, height: {height}, at: [0, 0, 0]}}
questions:
  - steady_spin: {{precession: {precession}}}
"""


def _simulate(A: float, C: float, w3: float, wt: float, T: float = 3.0):
    """ω in the body and R (body -> space) over time, from Euler's equations and Ṙ = R [ω]×."""
    J = np.array([A, A, C])

    def rhs(_, y):
        w, R = y[:3], y[3:].reshape(3, 3)
        dw = np.cross(J * w, w) / J  # J ω̇ = (J ω) × ω
        wx = np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])
        return np.concatenate([dw, (R @ wx).ravel()])

    y0 = np.concatenate([[wt, 0.0, w3], np.eye(3).ravel()])
    t = np.linspace(0, T, 3001)
    sol = solve_ivp(rhs, (0, T), y0, t_eval=t, rtol=1e-11, atol=1e-12)
    return t, sol.y[:3].T, sol.y[3:].T.reshape(-1, 3, 3), J


def _measured(A: float, C: float, w3: float, wt: float):
    t, w, R, J = _simulate(A, C, w3, wt)
    body_rate = np.polyfit(t, np.unwrap(np.arctan2(w[:, 1], w[:, 0])), 1)[0]
    L = R[0] @ (J * w[0])
    L_hat = L / np.linalg.norm(L)
    axis = R[:, :, 2]  # the symmetry axis in space
    u = np.cross(L_hat, [1.0, 0, 0]) if abs(L_hat[0]) < 0.9 else np.cross(L_hat, [0, 1.0, 0])
    u /= np.linalg.norm(u)
    v = np.cross(L_hat, u)
    space_rate = np.polyfit(t, np.unwrap(np.arctan2(axis @ v, axis @ u)), 1)[0]
    nu = np.arccos(axis[-1] @ L_hat)
    omega_space = np.einsum("nij,nj->ni", R, w)[-1]
    gamma = np.arccos(omega_space @ L_hat / np.linalg.norm(omega_space))
    return body_rate, space_rate, nu, gamma


@pytest.mark.parametrize("height", ["r/2", "3*r"])  # oblate (C > A) and prolate (C < A)
@pytest.mark.parametrize("route", [RouteChoice.EXACT, RouteChoice.NUMERIC])
def test_rates_and_angles_match_a_simulation(height: str, route: RouteChoice) -> None:
    model = build_model(load_text(SCENE.format(height=height, precession="{spin: Omega, transverse: w}"), "c.yaml"))
    result = solve_problem(model, Options(route=route)).solutions[0]
    assert result.solved, result.error
    values = result.values["precession"] if route is RouteChoice.EXACT else vars(result.answers.precession)
    m, r, h = 2.0, 0.5, {"r/2": 0.25, "3*r": 1.5}[height]
    A, C = m * (3 * r**2 + h**2) / 12, m * r**2 / 2
    body_rate, space_rate, nu, gamma = _measured(A, C, 3.0, 2.0)
    assert values["body_rate"] == pytest.approx(body_rate, rel=1e-6)
    assert values["space_rate"] == pytest.approx(space_rate, rel=1e-6)
    assert values["nu"] == pytest.approx(nu, rel=1e-6)
    assert values["gamma"] == pytest.approx(gamma, rel=1e-5)


@pytest.mark.parametrize("precession, words", [
    ("{spin: Omega}", "'precession' needs ω across the symmetry axis: 'transverse: RATE'"),
    ("{spin: Omega, transverse: w, angle: pi/6}", "one of them"),
    ("{transverse: w}", "missing required key 'spin'"),
    ("{spin: Omega, tilt: 1}", "unknown key 'tilt' in precession"),
    ("{spin: t, angle: 1}", "the spin along the symmetry axis must be constant"),
])
def test_bad_precession(precession: str, words: str) -> None:
    with pytest.raises(InputError) as caught:
        load_text(SCENE.format(height="r", precession=precession), "c.yaml")
    assert "c.yaml:6:" in str(caught.value) and words in str(caught.value)


def test_a_body_that_is_not_axisymmetric() -> None:
    text = SCENE.format(height="r", precession="{spin: Omega, transverse: w}").replace(
        "{shape: cylinder, mass: m, radius: r, height: r,", "{shape: box, mass: m, width: r, depth: 2*r, height: 3*r,")
    result = solve_problem(build_model(load_text(text, "c.yaml")), Options(route=RouteChoice.EXACT)).solutions[0]
    assert not result.solved and "needs an axisymmetric body" in result.error
