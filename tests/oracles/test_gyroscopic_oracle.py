"""Independent oracle for small oscillations with gyroscopic terms: the sleeping top
(a free spin, its angle cyclic) and a gyroscope in gimbals (a rotor driven at s).

The expected side is built with ``sympy.physics.mechanics`` from scratch in the
inertial frame N: the body's orientation by ``orientnew`` (body-fixed turns, the spin
angle a coordinate or the prescribed s t), its angular velocity from the frames, the
Lagrangian and ``LagrangesMethod`` for the full nonlinear equations. These are solved
for the accelerations at the parameter values, and the Jacobian of the first-order
system (q, q̇)' = f(q, q̇) is taken at the steady state numerically (central
differences on exact evaluations at 30 digits); its eigenvalues s are the oracle's
(s = iω for an oscillation, Re s > 0 a growth; the free spin's cyclic angle and its
momentum add zeros, left out). No rbdsolve model code is used there.

Compared: rbdsolve's stability (the case whose condition holds at the sample, on both
sides of the critical value, at random parameter values) against the sign of the
oracle's largest Re s, and the frequencies against the oracle's Im s; for the gimbals,
M, G and K against the linearization of the oracle's equations, exactly.
"""

from __future__ import annotations

import random

import mpmath
import pytest
import sympy as sp
from sympy.physics.mechanics import LagrangesMethod, Lagrangian, Point, ReferenceFrame, RigidBody, dynamicsymbols, \
    inertia

from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.solvers import solve_problem

m, h, A, C, g, s, r, k = sp.symbols("m h A C g s r k", positive=True)

TOP = """
parameters: {m: mass, h: length, A: inertia about O, C: axial inertia, g: gravity, s: spin rate}
assumptions: [A > m*h**2]
coordinates: [a, b, phi]
gravity: [0, 0, -g]
triads:
  T: {turns: [[x, a], [y, b], [z, phi]], vectors: [e1, e2, e3]}
points:
  G: h*e3
bodies:
  top: {mass: m, inertia: [A - m*h**2, A - m*h**2, C], at: G, orientation: [T]}
questions:
  - modes: {about: {a: 0, b: 0, dot(phi): s}}
"""


def _top_oracle():
    """The top's nonlinear equations, solved for the accelerations (a function of the
    parameters and the state)."""
    a, b, phi = dynamicsymbols("a b phi")
    N = ReferenceFrame("N")
    B = N.orientnew("B", "Body", [a, b, phi], "XYZ")
    O = Point("O")
    O.set_vel(N, 0)
    G = O.locatenew("G", h * B.z)
    G.v2pt_theory(O, N, B)
    top = RigidBody("top", G, B, m, (inertia(B, A - m * h**2, A - m * h**2, C), G))
    top.potential_energy = m * g * h * (B.z.dot(N.z))
    method = LagrangesMethod(Lagrangian(N, top), [a, b, phi])
    method.form_lagranges_equations()
    return method, (a, b, phi)


def _jacobian_roots(method, q, values: dict, state0: list) -> list[complex]:
    """Eigenvalues of the first-order system's Jacobian at state0 (q, q̇), at 30 digits."""
    qd = [x.diff() for x in q]
    plain = sp.symbols(f"x0:{2 * len(q)}")
    rhs = method.rhs().xreplace(values)
    rhs = rhs.xreplace({**dict(zip(qd, plain[len(q):])), **dict(zip(q, plain[:len(q)]))})
    f = sp.lambdify(plain, rhs, "mpmath")
    with mpmath.workdps(30):
        step = mpmath.mpf(10) ** -10
        columns = []
        for j in range(2 * len(q)):
            up, down = list(map(mpmath.mpf, state0)), list(map(mpmath.mpf, state0))
            up[j] += step
            down[j] -= step
            columns.append([(x - y) / (2 * step) for x, y in zip(f(*up), f(*down))])
        J = mpmath.matrix(2 * len(q), 2 * len(q))
        for j, col in enumerate(columns):
            for i, x in enumerate(col):
                J[i, j] = x
        return [complex(v) for v in mpmath.eig(J, left=False, right=False)]


def _case_at(answers, point: dict) -> str:
    held = [c.stability.value for c in answers.stability_cases if bool(c.when.xreplace(point))]
    assert len(held) == 1, (answers.stability_cases, point)
    return held[0]


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_sleeping_top_against_a_simulation_of_its_linearized_mechanics(seed) -> None:
    (modes,) = solve_problem(build_model(load_text(TOP, "top.yaml"))).solutions
    assert modes.error is None, modes.error
    answers = modes.answers
    (critical,) = answers.critical
    assert critical.parameter == "s"
    assert sp.simplify(critical.value - 2 * sp.sqrt(A * m * g * h) / C) == 0
    method, q = _top_oracle()
    rng = random.Random(seed)
    values = {m: sp.Rational(rng.randint(2, 20), 10), h: sp.Rational(rng.randint(2, 10), 100),
              C: sp.Rational(rng.randint(5, 30), 10000), g: sp.Rational(981, 100)}
    values[A] = values[m] * values[h] ** 2 + sp.Rational(rng.randint(5, 30), 10000)
    s_c = critical.value.xreplace(values)
    for factor in (sp.Rational(1, 2), sp.Rational(97, 100), sp.Rational(103, 100), 3):
        point = {**values, s: s_c * factor}
        roots = [z for z in _jacobian_roots(method, q, point, [0, 0, 0, 0, 0, sp.N(s_c * factor, 30)])
                 if abs(z) > 1e-8]
        growth = max(z.real for z in roots)
        assert _case_at(answers, point) == ("unstable" if growth > 1e-6 else "stable"), (factor, roots)
        if growth <= 1e-6:
            expected = sorted({round(abs(z.imag), 9) for z in roots})
            got = sorted(float(w.xreplace(point)) for w in answers.frequencies)
            assert got == pytest.approx(expected, rel=1e-8)
        else:
            rate = next(c.growth_rate for c in answers.stability_cases if c.stability.value == "unstable")
            assert float(rate.xreplace(point)) == pytest.approx(growth, rel=1e-7)


GIMBAL = """
parameters: {m: mass, r: radius, k: stiffness, s: spin rate}
coordinates: [psi, theta]
triads:
  ring: {turns: [[z, psi], [x, theta]], vectors: [e1, e2, e3]}
points:
  O: [0, 0, 0]
bodies:
  rotor: {shape: disk, mass: m, radius: r, at: O, axis: y, orientation: [ring, [y, s*t]]}
springs:
  one: {stiffness: k, angle: psi}
  two: {stiffness: 2*k, angle: theta}
questions:
  - modes: {about: {psi: 0, theta: 0}}
"""


def test_gimbals_with_a_driven_rotor_against_the_oracles_linearization() -> None:
    """Unequal springs k and 2k: M, G and K from the oracle's equations linearized by
    hand (∂/∂ε at q = ε u), exactly; the frequencies at values against its roots."""
    (modes,) = solve_problem(build_model(load_text(GIMBAL, "gimbal.yaml"))).solutions
    assert modes.error is None, modes.error
    a = modes.answers
    psi, theta = dynamicsymbols("psi theta")
    t = dynamicsymbols._t
    N = ReferenceFrame("N")
    ring = N.orientnew("ring", "Body", [psi, theta, 0], "ZXY")
    rotor = ring.orientnew("rotor", "Axis", [s * t, ring.y])
    O = Point("O")
    O.set_vel(N, 0)
    body = RigidBody("rotor", O, rotor, m, (inertia(rotor, m * r**2 / 4, m * r**2 / 2, m * r**2 / 4), O))
    body.potential_energy = k * psi**2 / 2 + k * theta**2
    method = LagrangesMethod(Lagrangian(N, body), [psi, theta])
    equations = method.form_lagranges_equations()
    eps = sp.Symbol("eps")
    u = dynamicsymbols("u1 u2")
    linear = sp.Matrix([sp.diff(e.subs({psi: eps * u[0], theta: eps * u[1]}).doit(), eps).subs(eps, 0)
                        for e in equations]).applyfunc(sp.simplify)
    M = linear.jacobian([x.diff(t, 2) for x in u])
    Gm = linear.jacobian([x.diff(t) for x in u])
    K = linear.jacobian(u)
    for got, want in ((a.M, M), (a.G, Gm), (a.K, K)):
        assert (sp.Matrix(got) - want).applyfunc(sp.simplify) == sp.zeros(2), (got, want)
    assert a.stability.value == "stable"
    point = {m: 2, r: sp.Rational(1, 10), k: sp.Rational(1, 2), s: 100}
    lam = sp.Symbol("lam")
    roots = sp.Poly((K + lam * Gm + lam**2 * M).det().xreplace(point), lam).nroots(n=30)
    expected = sorted({round(abs(complex(z).imag), 9) for z in roots})
    assert sorted(float(w.xreplace(point)) for w in a.frequencies) == pytest.approx(expected, rel=1e-9)
