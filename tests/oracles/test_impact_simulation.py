"""Independent numerical oracle for the ``impact`` question: simulate a short, strong
force pulse and compare the motion just after it with rbdsolve's exact answers.

What is compared. For each scene (written below as YAML with numbers in place of the
parameters, so rbdsolve's answers are numbers) rbdsolve answers an ``impact`` question
with a known impulse P applied at one point. The oracle applies instead the constant
force P/tau at that point during 0 <= t <= tau, starting from the configuration ``at``
and the velocities ``before``, with no gravity or other force, and integrates the
equations of motion with ``scipy.integrate.solve_ivp`` (DOP853, rtol = 1e-10,
atol = 1e-12). At t = tau it compares with rbdsolve:

- the generalized velocities (``answers.velocities``),
- the velocities of the named points (``answers.points``), from the oracle's own
  kinematics evaluated at the simulated state,
- the impulse the supports gave (``answers.support_impulse``): in the simulation, the
  change of momentum of the system, sum m_i (v_Gi(tau) - v_Gi(0)), less the applied
  impulse P = (P/tau) * tau. For the pendulum this is the pivot's reaction integrated
  over the pulse; for the cart it is the table's normal impulse on the cart; for the
  free rod it is zero.

Independence. The equations of motion are derived here from scratch with
``sympy.physics.mechanics`` (ReferenceFrame, Point, RigidBody, Particle,
LagrangesMethod with the pulse as an applied force); nothing of rbdsolve's model,
kinematics, energy or solver code is used, only its public ``solve_problem`` to get the
answers under test. The oracle never uses Lagrange's *impact* equations: the
post-impact state is the end state of an ordinary (finite-force) simulation.

Tolerance. As tau -> 0 the simulated state tends to the impulsive answer with an error
O(tau): during the pulse the configuration moves by O(|q'| tau) and finite
(velocity-dependent, e.g. centripetal) forces act for a time tau. All quantities are
O(1) in these dimensionless units, and tau = 1e-6, so the expected discrepancy is of
order |q'|^2 tau: measured, 2e-6 to 2e-5 (largest: v_A.x of the free rod, which turns
at 5 rad/s by the end of the pulse); the integration error, ~1e-10, is negligible.
Each quantity must agree to TOL = 1e-4 relative, with the same absolute floor for
quantities near zero: |sim - exact| <= TOL * max(1, |exact|).
``test_pulse_error_is_first_order`` checks the O(tau) premise on one scene (the error
shrinks ~10x when tau does).
"""

from __future__ import annotations

import dataclasses
import functools

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp
from sympy.physics.mechanics import (
    LagrangesMethod,
    Particle,
    Point,
    ReferenceFrame,
    RigidBody,
    dynamicsymbols,
    inertia,
)

from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.solvers import solve_problem

TAU = 1e-6  # duration of the pulse (dimensionless units)
TOL = 1e-4  # relative tolerance, with the same absolute floor (see the docstring)

R = sp.Rational


# ----------------------------------------------------------------- mechanics oracle


@dataclasses.dataclass(frozen=True)
class Mechanics:
    """A planar system built with sympy.physics.mechanics, with a force F = (Fx, Fy)
    at ``struck``; ``points`` are the points whose velocities are compared and
    ``centres`` the (mass, centre of mass) pairs that make up the momentum."""

    N: ReferenceFrame
    q: list
    bodies: list
    struck: Point
    points: dict
    centres: list


def _place(origin: Point, name: str, vector, N: ReferenceFrame) -> Point:
    p = origin.locatenew(name, vector)
    p.set_vel(N, origin.vel(N) + p.pos_from(origin).dt(N))  # absolute velocity
    return p


def rod(name: str, G: Point, N: ReferenceFrame, angle, m, length) -> RigidBody:
    """A uniform thin rod of mass m, turning with ``angle`` about N.z (only its moment
    of inertia about z, m L^2/12, matters in plane motion)."""
    frame = N.orientnew(f"{name}_frame", "Axis", (angle, N.z))
    J = m * length**2 / 12
    return RigidBody(name, G, frame, m, (inertia(frame, 0, J, J), G))


def free_rod_mechanics(m, l) -> Mechanics:
    x, y, theta = dynamicsymbols("x y theta")
    N = ReferenceFrame("N")
    O = Point("O")
    O.set_vel(N, 0)
    G = _place(O, "G", x * N.x + y * N.y, N)
    A = _place(G, "A", l / 2 * (sp.cos(theta) * N.x + sp.sin(theta) * N.y), N)
    body = rod("rod", G, N, theta, m, l)
    return Mechanics(N, [x, y, theta], [body], A, {"A": A, "G": G}, [(m, G)])


def pendulum_mechanics(m, l, d) -> Mechanics:
    theta = dynamicsymbols("theta")
    N = ReferenceFrame("N")
    O = Point("O")
    O.set_vel(N, 0)
    down = sp.sin(theta) * N.x - sp.cos(theta) * N.y
    G = _place(O, "G", l / 2 * down, N)
    Q = _place(O, "Q", d * down, N)
    body = rod("rod", G, N, theta, m, l)
    return Mechanics(N, [theta], [body], Q, {"Q": Q, "G": G}, [(m, G)])


def cart_rod_mechanics(M, m, l) -> Mechanics:
    x, theta = dynamicsymbols("x theta")
    N = ReferenceFrame("N")
    O = Point("O")
    O.set_vel(N, 0)
    down = sp.sin(theta) * N.x - sp.cos(theta) * N.y
    C = _place(O, "C", x * N.x, N)
    G = _place(C, "G", l / 2 * down, N)
    B = _place(C, "B", l * down, N)
    cart = Particle("cart", C, M)
    body = rod("rod", G, N, theta, m, l)
    return Mechanics(N, [x, theta], [cart, body], B, {"B": B, "C": C, "G": G},
                     [(M, C), (m, G)])


@dataclasses.dataclass(frozen=True)
class Numeric:
    """The oracle's equations of motion and kinematics as numpy functions of the
    state (q, u), u = q'."""

    eom: object  # (q, u, Fx, Fy) -> (M, f) with M u' = f
    point_velocity: dict  # name -> (q, u) -> (vx, vy)
    momentum: object  # (q, u) -> (px, py)


def numeric(mech: Mechanics) -> Numeric:
    t = dynamicsymbols._t
    Fx, Fy = sp.symbols("F_x F_y")
    N = mech.N
    T = sum((b.kinetic_energy(N) for b in mech.bodies), sp.S.Zero)  # no gravity: L = T
    lm = LagrangesMethod(T, mech.q, forcelist=[(mech.struck, Fx * N.x + Fy * N.y)],
                         frame=N)
    lm.form_lagranges_equations()

    qs = sp.symbols(f"q0:{len(mech.q)}")
    us = sp.symbols(f"u0:{len(mech.q)}")
    rates = {qi.diff(t): ui for qi, ui in zip(mech.q, us)}
    coordinates = dict(zip(mech.q, qs))

    def to_plain(expr):  # derivatives first, then the coordinates themselves
        return sp.sympify(expr).xreplace(rates).xreplace(coordinates)

    def planar(vector):
        return [to_plain(vector.dot(N.x)), to_plain(vector.dot(N.y))]

    M = lm.mass_matrix.applyfunc(to_plain)
    f = lm.forcing.applyfunc(to_plain)
    assert not (M.free_symbols | f.free_symbols) - set(qs) - set(us) - {Fx, Fy}
    eom = sp.lambdify((qs, us, Fx, Fy), (M, f), "numpy")
    velocities = {name: sp.lambdify((qs, us), planar(p.vel(N)), "numpy")
                  for name, p in mech.points.items()}
    p = sum((mass * G.vel(N) for mass, G in mech.centres), sp.S.Zero * N.x)
    momentum = sp.lambdify((qs, us), planar(p), "numpy")
    return Numeric(eom, velocities, momentum)


@dataclasses.dataclass(frozen=True)
class Simulated:
    u: np.ndarray  # generalized velocities at t = tau
    points: dict  # name -> (vx, vy) at t = tau
    support_impulse: np.ndarray  # Δ(momentum) - applied impulse


def simulate(num: Numeric, q0, u0, impulse, tau: float = TAU) -> Simulated:
    """Apply the constant force impulse/tau for a time tau from (q0, u0)."""
    n = len(q0)
    Fx, Fy = (float(c) / tau for c in impulse)

    def rhs(_t, s):
        q, u = s[:n], s[n:]
        M, f = num.eom(q, u, Fx, Fy)
        return np.concatenate([u, np.linalg.solve(np.array(M, float),
                                                  np.array(f, float).ravel())])

    s0 = np.array([*map(float, q0), *map(float, u0)])
    sol = solve_ivp(rhs, (0.0, tau), s0, method="DOP853", rtol=1e-10, atol=1e-12)
    assert sol.success, sol.message
    s1 = sol.y[:, -1]
    q1, u1 = s1[:n], s1[n:]
    points = {name: np.array(v(q1, u1), float) for name, v in num.point_velocity.items()}
    dp = np.array(num.momentum(q1, u1), float) - np.array(num.momentum(s0[:n], s0[n:]), float)
    return Simulated(u1, points, dp - np.array(impulse, float))


# ----------------------------------------------------------------------- rbdsolve


def rbdsolve_impact(yaml_text: str):
    report = solve_problem(build_model(load_text(yaml_text, "scene.yaml")))
    (solution,) = report.solutions
    assert solution.error is None, solution.error
    return solution.answers


def num(expr) -> float:
    value = complex(sp.N(sp.sympify(expr), 30))
    assert abs(value.imag) < 1e-12, expr
    return value.real


def assert_close(sim: float, exact: float, what: str) -> None:
    err = abs(sim - exact)
    assert err <= TOL * max(1.0, abs(exact)), \
        f"{what}: rbdsolve {exact!r}, simulation {sim!r} (|difference| {err:.3g})"


def compare(answers, sim: Simulated, coordinates, points) -> None:
    assert set(answers.velocities) == set(coordinates)
    for i, name in enumerate(coordinates):
        assert_close(sim.u[i], num(answers.velocities[name]), f"velocity of {name}")
    assert set(answers.points) == set(points)
    for name in points:
        v = answers.points[name]
        assert num(v[2]) == 0, f"point {name}: out-of-plane velocity {v[2]}"
        for k, axis in enumerate("xy"):
            assert_close(sim.points[name][k], num(v[k]), f"v_{name}.{axis}")
    S = answers.support_impulse
    assert num(S[2]) == 0, f"out-of-plane support impulse {S[2]}"
    for k, axis in enumerate("xy"):
        assert_close(sim.support_impulse[k], num(S[k]), f"support impulse .{axis}")


# ------------------------------------------------------------ scene 1: free rod

FREE_ROD = """\
title: A free rod struck at one end (numbers)
coordinates: [x, y, theta]
points:
  G: [x, y]
  A: G + 3/2 * [cos(theta), sin(theta)]
bodies:
  rod: {{shape: rod, mass: 2, length: 3, at: G, angle: theta}}
questions:
  - impact:
      at: {{theta: {theta}}}
      before: {before}
      impulses: {{A: {impulse}}}
      points: [A, G]
"""

FREE_ROD_CASES = {
    # id: (theta as YAML, theta, before as YAML, before (x, y, theta), impulse)
    "at-rest-theta0": ("0", 0, "{}", (0, 0, 0), "[0, 5]", (0, 5)),
    "moving-theta-pi/6": ("pi/6", sp.pi / 6, "{x: 1/2, y: 0, theta: 1/3}",
                          (R(1, 2), 0, R(1, 3)), "[1, 2]", (1, 2)),
}


@functools.cache
def free_rod_numeric() -> Numeric:
    return numeric(free_rod_mechanics(2, 3))


def test_oracle_free_rod_matches_hand_result():
    """The oracle itself against the hand result of problems/impact/free-rod-struck:
    v_G = P/m e_y, omega = 6P/(m l), v_A = 4P/m e_y (m = 2, l = 3, P = 5)."""
    sim = simulate(free_rod_numeric(), (0, 0, 0), (0, 0, 0), (0, 5))
    for got, want, what in [(sim.u[0], 0, "x'"), (sim.u[1], 5 / 2, "y'"),
                            (sim.u[2], 6 * 5 / (2 * 3), "theta'"),
                            (sim.points["A"][0], 0, "v_A.x"), (sim.points["A"][1], 10, "v_A.y")]:
        assert_close(got, want, what)


@pytest.mark.parametrize("case", list(FREE_ROD_CASES), ids=list(FREE_ROD_CASES))
def test_free_rod_struck(case):
    theta_yaml, theta, before_yaml, before, impulse_yaml, impulse = FREE_ROD_CASES[case]
    answers = rbdsolve_impact(FREE_ROD.format(theta=theta_yaml, before=before_yaml,
                                              impulse=impulse_yaml))
    sim = simulate(free_rod_numeric(), (0, 0, theta), before, impulse)
    compare(answers, sim, ["x", "y", "theta"], ["A", "G"])


# ------------------------------------------------------- scene 2: struck pendulum

PENDULUM = """\
title: A hanging rod struck below its pivot (numbers)
coordinates: [theta]
points:
  G: 3/2 * [sin(theta), -cos(theta)]
  Q: {d} * [sin(theta), -cos(theta)]
bodies:
  rod: {{shape: rod, mass: 2, length: 3, at: G, angle: theta, axis: y}}
questions:
  - impact:
      at: {{theta: 0}}
      before: {before}
      impulses: {{Q: [4, 0]}}
      points: [Q, G]
"""

PENDULUM_CASES = {
    # id: (d as YAML, d, before as YAML, theta' before); m = 2, l = 3, P = 4
    "d=1": ("1", 1, "{}", 0),
    "centre-of-percussion-d=2": ("2", 2, "{}", 0),  # 2l/3: the pivot feels nothing
    "d=5/2": ("5/2", R(5, 2), "{}", 0),
    "d=3-swinging": ("3", 3, "{theta: -1/2}", R(-1, 2)),
}


@functools.cache
def pendulum_numeric(d) -> Numeric:
    return numeric(pendulum_mechanics(2, 3, d))


@pytest.mark.parametrize("case", list(PENDULUM_CASES), ids=list(PENDULUM_CASES))
def test_pendulum_struck(case):
    d_yaml, d, before_yaml, before = PENDULUM_CASES[case]
    answers = rbdsolve_impact(PENDULUM.format(d=d_yaml, before=before_yaml))
    sim = simulate(pendulum_numeric(d), (0,), (before,), (4, 0))
    compare(answers, sim, ["theta"], ["Q", "G"])
    if d == 2:  # the oracle agrees that the centre of percussion is at 2l/3
        assert abs(sim.support_impulse[0]) <= TOL


# ------------------------------------------------- scene 3: cart with hanging rod

CART_ROD = """\
title: A cart carrying a hanging rod, struck at the rod's lower end (numbers)
coordinates: [x, theta]
points:
  C: [x, 0]
  G: C + 1 * [sin(theta), -cos(theta)]
  B: C + 2 * [sin(theta), -cos(theta)]
bodies:
  cart: {shape: particle, mass: 3, at: C}
  rod: {shape: rod, mass: 2, length: 2, at: G, angle: theta, axis: y}
questions:
  - impact:
      at: {theta: pi/4}
      before: {x: 1, theta: -1/2}
      impulses: {B: [3, 1]}
      points: [B, C, G]
"""


def test_cart_with_rod_struck():
    """Cart mass 3 on a smooth track, rod mass 2 and length 2 hanging from it, the
    impulse [3, 1] at the rod's lower end B at theta = pi/4, moving before. The
    track's impulse on the cart is vertical; its horizontal part must be 0."""
    answers = rbdsolve_impact(CART_ROD)
    sim = simulate(numeric(cart_rod_mechanics(3, 2, 2)), (0, sp.pi / 4),
                   (1, R(-1, 2)), (3, 1))
    compare(answers, sim, ["x", "theta"], ["B", "C", "G"])
    assert abs(sim.support_impulse[0]) <= TOL  # the track is smooth
    assert abs(sim.support_impulse[1]) > 0.1  # and it does push (not a vacuous check)


# ------------------------------------------------------------ the oracle's premise


def test_pulse_error_is_first_order():
    """The discrepancy shrinks in proportion to tau (so TAU = 1e-6 puts it near 1e-6,
    well inside TOL): swinging pendulum, where centripetal forces make it nonzero."""
    d_yaml, d, before_yaml, before = PENDULUM_CASES["d=3-swinging"]
    answers = rbdsolve_impact(PENDULUM.format(d=d_yaml, before=before_yaml))
    exact = num(answers.support_impulse[1])
    errors = [abs(simulate(pendulum_numeric(d), (0,), (before,), (4, 0), tau)
                  .support_impulse[1] - exact) for tau in (1e-3, 1e-4)]
    assert 5 < errors[0] / errors[1] < 20, errors
    assert errors[1] < 1e-3, errors
