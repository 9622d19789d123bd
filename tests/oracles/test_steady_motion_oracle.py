"""Independent numerical oracle for the ``steady_motion`` question: start a full 3D
rigid-body simulation on the steady motion rbdsolve predicts and check that it stays
steady.

What is compared. rbdsolve answers, for each scene, the relation a steady motion needs
(``answers.solved``), the rates the rolling condition fixes (``answers.rates``) and the
angular velocity in the problem's triad (``answers.angular_velocity``). With numbers
substituted for the parameters, the oracle integrates the equations of motion from the
state of that steady motion and checks, over three precession periods, that

- the tilt theta stays at its initial value (relative drift <= TOL),
- the precession (heading) rate stays at its initial value (relative drift <= TOL),
- for the rolling bodies, the centre G stays on the horizontal circle of radius R
  about the vertical axis through the circle's centre (relative drift <= TOL),
- the simulated angular velocity, in the components of the triad (the frame after the
  precession and tilt turns), equals ``answers.angular_velocity`` at every sample
  (<= TOL relative to the largest component).

A steady motion is a relative equilibrium of the equations of motion: if rbdsolve's
relation were wrong, the start would not be one, and the tilt would oscillate
(nutate) with an amplitude proportional to the error. ``test_*_perturbed`` start
instead with the precession rate (top: the spin) off by 5 % or by 0.1 % and require
the tilt (and, rolling, the radius of G's path) to move by more than 100 * TOL, so
that these tests can fail: measured, a 0.1 % error moves the tilt by 3e-3 (top) to
3.7e-3 (coin, ring) relative and the rolling bodies' radius by 7e-3; a 5 % error moves
the tilt by 0.13 to 0.17 and the radius by 0.4.

Scenes and conventions (checked against the YAML files and
``rbdsolve/solvers/steady_motion/exact.py``):

- ``problems/steady/heavy-top.yaml``: T = Rz(Omega t) Rx(theta), body = T Rz(spin t),
  i.e. z-x-z Euler angles about the fixed point O with psi = Omega t, theta constant,
  phi = spin t. The oracle's coordinates are exactly these Euler angles, started at
  psi' = Omega, theta' = 0, phi' = spin (the total axial rate is spin + Omega cos theta).
- ``problems/steady/rolling-coin.yaml`` (thin disk: I3 = m r^2/2, I1 = m r^2/4 about G)
  and ``problems/sg2150-2015-10-29/p3-rolling-ring.yaml`` (thin ring: I3 = m r^2,
  I1 = m r^2/2): T = Rz(omega0 t) Ry(-theta), body = T Rx(spin t). So e1 = T x is the
  symmetry axis, theta above the horizontal, pointing outwards; e3 = T z runs from the
  contact point C to G, leaning inwards (the plane of the disk is tilted theta from the
  vertical, towards the centre of the circle); e2 is horizontal, along the motion. The
  oracle uses the same angles as coordinates (heading psi, tilt theta, spin phi: the
  body frame is N Rz(psi) Ry(-theta) Rx(phi)) plus the contact point's (x, y), and
  starts with psi = 0, G at (R, 0, 0), C = G - r e3, psi' = omega0 from
  ``solved["omega0**2"]``, theta' = 0, phi' = ``rates["spin"]``.

Independence. The equations of motion are derived here from scratch with
``sympy.physics.mechanics`` (ReferenceFrame with body-fixed angles, Point, RigidBody,
KanesMethod; for the rolling bodies the rolling without slipping is a pair of
nonholonomic velocity constraints, v_G + omega x (C - G) = 0 horizontally, with the
contact point's horizontal velocity as dependent speeds, so the contact force does no
work and never appears), then lambdified and integrated with
``scipy.integrate.solve_ivp`` (DOP853, rtol = 1e-10, atol = 1e-12). Nothing of
rbdsolve's model, kinematics or solvers is used, only ``solve_problem`` for the answers
under test; the moments of inertia of the disk and ring are the textbook values.

Tolerance. On the steady motion the drift is integration error only: measured, 3e-12
for the top's tilt and precession rate, 1e-13 for the rolling bodies' tilt and heading
rate, 4e-10 for the radius of G's path (the contact point's position is integrated
from its velocity). TOL = 1e-7 leaves a margin of 250 and is still 3 * 10^4 times
smaller than what a 0.1 % error in the answer produces. The whole file runs in a few
seconds.
"""

from __future__ import annotations

import dataclasses
import functools
from pathlib import Path

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp
from sympy.physics.mechanics import (
    KanesMethod,
    Point,
    ReferenceFrame,
    RigidBody,
    dynamicsymbols,
    inertia,
)

from rbdsolve.model.build import build_model
from rbdsolve.problem import load_file
from rbdsolve.solvers import solve_problem

ROOT = Path(__file__).resolve().parents[2]
TOL = 1e-7  # relative drift allowed on the steady motion (see the docstring)
PERIODS = 3  # simulated precession periods
SAMPLES = 3000


def _answers(relative: str):
    return solve_problem(build_model(load_file(ROOT / relative))).solutions[0].answers


def _num(expr, values: dict) -> float:
    """A sympy expression of rbdsolve's symbols at the numbers in ``values`` (by name)."""
    expr = sp.sympify(expr)
    missing = {s.name for s in expr.free_symbols} - values.keys()
    assert not missing, f"no value for {missing}"
    return float(expr.xreplace({s: values[s.name] for s in expr.free_symbols}))


@dataclasses.dataclass(frozen=True)
class Numeric:
    """An oracle's equations of motion, M(x, p) x' = F(x, p), and the body's angular
    velocity in the triad's components, as numpy functions of the state x."""

    mass: object
    forcing: object
    omega_triad: object

    def rhs(self, p):
        def f(_t, x):
            return np.linalg.solve(self.mass(x, p), self.forcing(x, p)).ravel()

        return f


def _simulate(num: Numeric, p, x0, t_end: float):
    sol = solve_ivp(num.rhs(p), (0.0, t_end), x0, method="DOP853", rtol=1e-10, atol=1e-12,
                    dense_output=True)
    assert sol.success, sol.message
    times = np.linspace(0.0, t_end, SAMPLES)
    return times, sol.sol(times)


def _relative_drift(series, value: float) -> float:
    return float(np.max(np.abs(series - value)) / abs(value))


# ----------------------------------------------------------------- heavy top


@functools.cache
def top_oracle() -> Numeric:
    """A symmetric top on a fixed point O, z-x-z Euler angles (psi, theta, phi), centre
    of mass G at h along the body's z axis, moments J1, J1, J3 about G, gravity -g z."""
    psi, theta, phi = dynamicsymbols("psi theta phi")
    u = dynamicsymbols("u1:4")
    m, h, J1, J3, g = sp.symbols("m h J1 J3 g", positive=True)
    N = ReferenceFrame("N")
    T = ReferenceFrame("T")  # the precessing triad
    T.orient_body_fixed(N, (psi, theta, 0), "zxz")
    B = ReferenceFrame("B")
    B.orient_body_fixed(N, (psi, theta, phi), "zxz")
    O = Point("O")
    O.set_vel(N, 0)
    G = O.locatenew("G", h * B.z)
    G.v2pt_theory(O, N, B)
    top = RigidBody("top", G, B, m, (inertia(B, J1, J1, J3), G))
    q = [psi, theta, phi]
    kd = [qi.diff() - ui for qi, ui in zip(q, u)]
    kane = KanesMethod(N, q, list(u), kd_eqs=kd)
    kane.kanes_equations([top], [(G, -m * g * N.z)])
    state, params = q + list(u), [m, h, J1, J3, g]
    to_u = dict(zip([qi.diff() for qi in q], u))
    w = B.ang_vel_in(N).subs(to_u)
    w_T = sp.Matrix([w.dot(T.x), w.dot(T.y), w.dot(T.z)])
    return Numeric(sp.lambdify((state, params), kane.mass_matrix_full, cse=True),
                   sp.lambdify((state, params), kane.forcing_full, cse=True),
                   sp.lambdify((state, params), w_T, cse=True))


TOP = {"m": 1.5, "h": 0.6, "J1": 0.3, "J3": 0.8, "g": 9.81, "theta": 0.6, "Omega": 2.5}


@functools.cache
def top_answers():
    return _answers("problems/steady/heavy-top.yaml")


def top_run(spin_factor: float = 1.0):
    ans = top_answers()
    values = dict(TOP)
    values["spin"] = spin_factor * _num(ans.solved["spin"], values)
    num = top_oracle()
    p = [TOP[k] for k in ("m", "h", "J1", "J3", "g")]
    x0 = [0.0, TOP["theta"], 0.0, TOP["Omega"], 0.0, values["spin"]]
    times, xs = _simulate(num, p, x0, PERIODS * 2 * np.pi / TOP["Omega"])
    return ans, values, num, p, times, xs


def test_top_stays_steady():
    ans, values, num, p, _times, xs = top_run()
    assert set(ans.solved) == {"spin"}
    assert _relative_drift(xs[1], TOP["theta"]) <= TOL
    assert _relative_drift(xs[3], TOP["Omega"]) <= TOL
    expected = np.array([_num(c, values) for c in ans.angular_velocity])
    scale = np.max(np.abs(expected))
    for x in xs.T[:: SAMPLES // 30]:
        w = np.asarray(num.omega_triad(x, p), dtype=float).ravel()
        assert np.max(np.abs(w - expected)) <= TOL * scale


@pytest.mark.parametrize("factor", [1.05, 1.001])
def test_top_perturbed_spin_nutates(factor):
    xs = top_run(factor)[-1]
    assert _relative_drift(xs[1], TOP["theta"]) > 100 * TOL


# ----------------------------------------------------------------- rolling disk / ring


@functools.cache
def rolling_oracle() -> Numeric:
    """A body of revolution (axial moment I3, transverse I1 about its centre G, radius
    r) rolling without slipping on the horizontal plane z = 0. Orientation: heading
    psi about z, then -theta about the new y axis (the triad A: A.x the symmetry axis,
    A.z from the contact point C to G), then spin phi about A.x. Coordinates
    (psi, theta, phi, x, y), (x, y) the contact point; speeds u1..u3 = the angle rates
    (independent), u4, u5 = x', y' (dependent, by the rolling constraints)."""
    psi, theta, phi, x, y = dynamicsymbols("psi theta phi x y")
    u = dynamicsymbols("u1:6")
    m, r, I1, I3, g = sp.symbols("m r I1 I3 g", positive=True)
    N = ReferenceFrame("N")
    A = ReferenceFrame("A")
    A.orient_body_fixed(N, (psi, -theta, 0), "zyx")
    B = ReferenceFrame("B")
    B.orient_axis(A, A.x, phi)
    O = Point("O")
    O.set_vel(N, 0)
    C = O.locatenew("C", x * N.x + y * N.y)  # the geometric contact point
    G = C.locatenew("G", r * A.z)
    q = [psi, theta, phi, x, y]
    to_u = dict(zip([qi.diff() for qi in q], u))
    G.set_vel(N, G.pos_from(O).dt(N).subs(to_u))
    B.set_ang_vel(N, B.ang_vel_in(N).subs(to_u))
    w = B.ang_vel_in(N)
    v_contact = G.vel(N) + w.cross(-r * A.z)  # velocity of the body's material point at C
    assert sp.simplify(v_contact.dot(N.z)) == 0
    constraints = [v_contact.dot(N.x), v_contact.dot(N.y)]
    kd = [qi.diff() - ui for qi, ui in zip(q, u)]
    kane = KanesMethod(N, q, list(u[:3]), kd_eqs=kd, u_dependent=list(u[3:]),
                       velocity_constraints=constraints)
    body = RigidBody("body", G, B, m, (inertia(A, I3, I1, I1), G))
    kane.kanes_equations([body], [(G, -m * g * N.z)])
    state, params = q + list(u), [m, r, I1, I3, g]
    w_A = sp.Matrix([w.dot(A.x), w.dot(A.y), w.dot(A.z)])
    numeric = Numeric(sp.lambdify((state, params), kane.mass_matrix_full, cse=True),
                      sp.lambdify((state, params), kane.forcing_full, cse=True),
                      sp.lambdify((state, params), w_A, cse=True))
    dependent = sp.solve(constraints, u[3:], dict=True)[0]
    contact_speed = sp.lambdify((state[:8], params), [dependent[u[3]], dependent[u[4]]], cse=True)
    return numeric, contact_speed


ROLLING = {
    # name: (file, moments (I1, I3) about G over m r^2), common numbers below
    "coin": ("problems/steady/rolling-coin.yaml", (sp.Rational(1, 4), sp.Rational(1, 2))),
    "ring": ("problems/sg2150-2015-10-29/p3-rolling-ring.yaml", (sp.Rational(1, 2), 1)),
}
NUMBERS = {"m": 2.0, "r": 0.3, "R": 0.7, "g": 9.81, "theta": 0.35}


@functools.cache
def rolling_answers(name: str):
    return _answers(ROLLING[name][0])


def rolling_run(name: str, omega_factor: float = 1.0):
    ans = rolling_answers(name)
    values = dict(NUMBERS)
    omega0_sq = _num(ans.solved["omega0**2"], values)
    assert omega0_sq > 0
    omega0 = np.sqrt(omega0_sq)
    values["omega0"] = omega_factor * omega0
    values["spin"] = _num(ans.rates["spin"], values)  # rolling holds also when perturbed
    (numeric, contact_speed), (i1, i3) = rolling_oracle(), ROLLING[name][1]
    m, r, R, g, theta = (NUMBERS[k] for k in ("m", "r", "R", "g", "theta"))
    p = [m, r, float(i1) * m * r**2, float(i3) * m * r**2, g]
    # G at (R, 0, 0); A.z = (-sin theta, 0, cos theta) at psi = 0, C = G - r A.z
    head = [0.0, theta, 0.0, R + r * np.sin(theta), 0.0, values["omega0"], 0.0, values["spin"]]
    x0 = head + list(np.asarray(contact_speed(head, p), dtype=float).ravel())
    times, xs = _simulate(numeric, p, x0, PERIODS * 2 * np.pi / omega0)
    return ans, values, numeric, p, times, xs


def centre_radius(xs, r: float):
    """Horizontal distance of G from the z axis: G = C + r A.z, A.z's horizontal part
    is -sin(theta) (cos psi, sin psi)."""
    psi, theta, x, y = xs[0], xs[1], xs[3], xs[4]
    return np.hypot(x - r * np.sin(theta) * np.cos(psi), y - r * np.sin(theta) * np.sin(psi))


@pytest.mark.parametrize("name", sorted(ROLLING))
def test_rolling_stays_steady(name):
    ans, values, numeric, p, _times, xs = rolling_run(name)
    assert set(ans.solved) == {"omega0**2"}
    assert _relative_drift(xs[1], NUMBERS["theta"]) <= TOL
    assert _relative_drift(xs[5], values["omega0"]) <= TOL
    assert _relative_drift(centre_radius(xs, NUMBERS["r"]), NUMBERS["R"]) <= TOL
    expected = np.array([_num(c, values) for c in ans.angular_velocity])
    scale = np.max(np.abs(expected))
    for x in xs.T[:: SAMPLES // 30]:
        w = np.asarray(numeric.omega_triad(x, p), dtype=float).ravel()
        assert np.max(np.abs(w - expected)) <= TOL * scale


@pytest.mark.parametrize("factor", [1.05, 1.001])
@pytest.mark.parametrize("name", sorted(ROLLING))
def test_rolling_perturbed_omega0_drifts(name, factor):
    xs = rolling_run(name, factor)[-1]
    assert _relative_drift(xs[1], NUMBERS["theta"]) > 100 * TOL
    assert _relative_drift(centre_radius(xs, NUMBERS["r"]), NUMBERS["R"]) > 100 * TOL
