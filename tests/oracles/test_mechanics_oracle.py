"""Independent oracle: derive T, V, M and K with sympy.physics.mechanics and compare
them exactly with what rbdsolve computes from the YAML scenes.

The mechanics derivation shares no code with rbdsolve: the bodies are built from
ReferenceFrame / Point / RigidBody / Particle, Lagrange's equations come from
LagrangesMethod, and the linearization at the equilibrium q = 0 is

    M = mass_matrix |_(q=0),    K = -d(forcing)/dq |_(q=0, q'=0).

rbdsolve writes its coordinates as real-valued Function(name)(t) and its parameters
as positive Symbols, whereas dynamicsymbols / symbols() here carry no assumptions, so
both sides are first rewritten in fresh plain Symbols matched by name (q' -> q_d1,
then q(t) -> q, then every symbol -> Symbol(name)) before subtracting.
"""

from __future__ import annotations

import dataclasses
import functools
from pathlib import Path

import pytest
import sympy as sp
from sympy.core.function import AppliedUndef
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
from rbdsolve.model.energies.energy import (
    kinetic_energy,
    mass_matrix,
    potential_energy,
    stiffness_matrix,
)
from rbdsolve.problem import load_file
from rbdsolve.problem.schema import QuestionKind
from rbdsolve.solvers import solve_problem

ROOT = Path(__file__).resolve().parents[2]

P1 = ROOT / "problems" / "sg2150-2015-10-29" / "p1-two-rods.yaml"
DOUBLE_PENDULUM = ROOT / "problems" / "examples" / "double-pendulum.yaml"


# --------------------------------------------------------------------------- helpers


def canon(expr) -> sp.Expr | sp.Matrix:
    """Rewrite ``expr`` in assumption-free Symbols matched by name: d^k q/dt^k ->
    Symbol('q_dk'), q(t) -> Symbol('q'), any other symbol s -> Symbol(s.name)."""
    if isinstance(expr, sp.MatrixBase):
        return sp.Matrix(expr).applyfunc(canon)
    expr = sp.sympify(expr)
    derivatives = {}
    for d in expr.atoms(sp.Derivative):
        f = d.expr
        assert isinstance(f, AppliedUndef), f"unexpected derivative {d}"
        derivatives[d] = sp.Symbol(f"{f.func.__name__}_d{d.derivative_count}")
    expr = expr.xreplace(derivatives)
    functions = {f: sp.Symbol(f.func.__name__) for f in expr.atoms(AppliedUndef)}
    expr = expr.xreplace(functions)
    return expr.xreplace({s: sp.Symbol(s.name) for s in expr.free_symbols})


def names(expr) -> set[str]:
    return {s.name for s in canon(expr).free_symbols}


def assert_same(ours, theirs, what: str) -> None:
    a, b = canon(ours), canon(theirs)
    if isinstance(a, sp.MatrixBase):
        assert a.shape == b.shape, f"{what}: shape {b.shape}, expected {a.shape}"
        bad = [(i, j) for i in range(a.rows) for j in range(a.cols)
               if sp.simplify(a[i, j] - b[i, j]) != 0]
        assert not bad, f"{what} differs at {bad}:\nrbdsolve  {b}\nmechanics {a}"
    else:
        assert sp.simplify(a - b) == 0, f"{what}:\nrbdsolve  {b}\nmechanics {a}"


def linearize(lagrangian, q, frame_bodies) -> tuple[sp.Matrix, sp.Matrix]:
    """M and K of Lagrange's equations at q = 0 (which must be an equilibrium)."""
    lm = LagrangesMethod(lagrangian, q, frame=frame_bodies[0], bodies=frame_bodies[1:])
    lm.form_lagranges_equations()
    qd = [qi.diff() for qi in q]
    rest = {v: 0 for v in qd}
    zero = {qi: 0 for qi in q}
    M = lm.mass_matrix.xreplace(rest).xreplace(zero)
    static = lm.forcing.xreplace(rest)  # q and q' are independent: set q' = 0 first
    assert sp.simplify(static.xreplace(zero)) == sp.zeros(len(q), 1), \
        "q = 0 is not an equilibrium of the mechanics model"
    K = -static.jacobian(q).xreplace(zero)
    return M.applyfunc(sp.simplify), K.applyfunc(sp.simplify)


def modes_only(problem):
    """The scene with only its modes question (the one under test; the others are
    slower and irrelevant here)."""
    questions = tuple(q for q in problem.questions if q.kind is QuestionKind.MODES)
    if not questions:
        pytest.fail(f"{problem.file} has no modes question")
    return dataclasses.replace(problem, questions=questions)


def modes_answers(report, about_names):
    modes = next(s for s in report.solutions if s.question == "modes")
    assert modes.error is None, modes.error
    about = {k: sp.sympify(v) for k, v in dict(modes.answers.about).items()}
    assert about == {n: 0 for n in about_names}, f"modes expanded about {about}"
    return modes.answers


# ------------------------------------------------------- problem 1 (SG2150 2015-10-29)


@functools.cache  # each derivation takes about a second: do it once
def mechanics_two_rods():
    theta, phi = dynamicsymbols("theta phi")
    m, r, g = sp.symbols("m r g")
    N = ReferenceFrame("N")
    A = N.orientnew("A", "Axis", (theta, N.z))  # long rod: angle theta, along A.x
    B = N.orientnew("B", "Axis", (phi, N.z))  # short rod: angle phi, along B.y
    O = Point("O")
    O.set_vel(N, 0)
    G1 = O.locatenew("G1", r / 2 * (sp.sin(theta) * N.x - sp.cos(theta) * N.y))
    G2 = G1.locatenew("G2", r / 2 * (sp.sin(phi) * N.x - sp.cos(phi) * N.y))
    G1.set_vel(N, G1.pos_from(O).dt(N))
    G2.set_vel(N, G2.pos_from(O).dt(N))

    m1, L1 = 3 * m, sp.sqrt(3) * r  # long rod
    m2, L2 = m, r  # short rod
    I1 = m1 * L1**2 / 12
    I2 = m2 * L2**2 / 12
    long_rod = RigidBody("long_rod", G1, A, m1, (inertia(A, 0, I1, I1), G1))
    short_rod = RigidBody("short_rod", G2, B, m2, (inertia(B, I2, 0, I2), G2))

    # gravity -g N.y; potential zero at the level of O
    V = m1 * g * G1.pos_from(O).dot(N.y) + m2 * g * G2.pos_from(O).dot(N.y)
    T = long_rod.kinetic_energy(N) + short_rod.kinetic_energy(N)
    q = [theta, phi]
    M, K = linearize(T - V, q, [N, long_rod, short_rod])
    return {"q": q, "T": T, "V": V, "M": M, "K": K, "m": m, "r": r, "g": g}


@pytest.fixture(scope="module")
def two_rods_report():
    return solve_problem(build_model(modes_only(load_file(str(P1)))))


def test_mechanics_derivation_matches_exam():
    """Sanity check of the oracle itself against the exam's published M and K."""
    mech = mechanics_two_rods()
    m, r, g = mech["m"], mech["r"], mech["g"]
    assert_same(m * r**2 * sp.Matrix([[sp.Rational(7, 4), sp.Rational(1, 4)],
                                      [sp.Rational(1, 4), sp.Rational(1, 3)]]),
                mech["M"], "exam M vs mechanics M")
    assert_same(m * g * r * sp.Matrix([[2, 0], [0, sp.Rational(1, 2)]]),
                mech["K"], "exam K vs mechanics K")


def test_two_rods_energies_match_mechanics(two_rods_report):
    mech = mechanics_two_rods()
    model = two_rods_report.model  # the report's summary: coordinates, T, V
    assert [str(canon(q)) for q in model.coordinates] == ["theta", "phi"]
    assert names(model.T) <= {"m", "r", "theta", "phi", "theta_d1", "phi_d1"}
    assert names(model.V) <= {"m", "r", "g", "theta", "phi"}
    assert_same(mech["T"], model.T, "kinetic energy T")
    assert_same(mech["V"], model.V, "potential energy V")


def test_two_rods_M_K_match_mechanics(two_rods_report):
    mech = mechanics_two_rods()
    answers = modes_answers(two_rods_report, ["theta", "phi"])
    assert_same(mech["M"], answers.M, "mass matrix M")
    assert_same(mech["K"], answers.K, "stiffness matrix K")


# ------------------------------------------------------------------- double pendulum


@functools.cache
def mechanics_double_pendulum():
    theta1, theta2 = dynamicsymbols("theta1 theta2")
    m1, m2, l1, l2, g = sp.symbols("m1 m2 l1 l2 g")
    N = ReferenceFrame("N")
    O = Point("O")
    O.set_vel(N, 0)
    P1 = O.locatenew("P1", l1 * (sp.sin(theta1) * N.x - sp.cos(theta1) * N.y))
    P2 = P1.locatenew("P2", l2 * (sp.sin(theta2) * N.x - sp.cos(theta2) * N.y))
    P1.set_vel(N, P1.pos_from(O).dt(N))
    P2.set_vel(N, P2.pos_from(O).dt(N))
    b1, b2 = Particle("b1", P1, m1), Particle("b2", P2, m2)
    V = m1 * g * P1.pos_from(O).dot(N.y) + m2 * g * P2.pos_from(O).dot(N.y)
    T = b1.kinetic_energy(N) + b2.kinetic_energy(N)
    q = [theta1, theta2]
    M, K = linearize(T - V, q, [N, b1, b2])
    return {"q": q, "T": T, "V": V, "M": M, "K": K,
            "symbols": (m1, m2, l1, l2, g)}


def _textbook_check(mech):
    m1, m2, l1, l2, g = mech["symbols"]
    assert_same(sp.Matrix([[(m1 + m2) * l1**2, m2 * l1 * l2], [m2 * l1 * l2, m2 * l2**2]]),
                mech["M"], "textbook M vs mechanics M")
    assert_same(sp.diag((m1 + m2) * g * l1, m2 * g * l2), mech["K"],
                "textbook K vs mechanics K")


@pytest.fixture(scope="module")
def double_pendulum():
    if not DOUBLE_PENDULUM.exists():
        pytest.skip(f"{DOUBLE_PENDULUM.relative_to(ROOT)} not written yet")
    model = build_model(modes_only(load_file(str(DOUBLE_PENDULUM))))
    assert model.coordinate_names() == ["theta1", "theta2"]
    return model, mechanics_double_pendulum()


def test_double_pendulum_energies_match_mechanics(double_pendulum):
    model, mech = double_pendulum
    _textbook_check(mech)
    T = model.to_time(kinetic_energy(model).total)  # the public form: theta1(t), ...
    V = model.to_time(potential_energy(model).total)
    assert names(T) <= {"m1", "m2", "l1", "l2", "theta1", "theta2", "theta1_d1", "theta2_d1"}
    assert names(V) <= {"m1", "m2", "l1", "l2", "g", "theta1", "theta2"}
    assert_same(mech["T"], T, "kinetic energy T")
    assert_same(mech["V"], V, "potential energy V")  # both with the datum at O


def test_double_pendulum_M_K_match_mechanics(double_pendulum):
    """rbdsolve's M and K at theta1 = theta2 = 0, from the functions its modes solver
    reports (so this holds even when the modes question cannot finish)."""
    model, mech = double_pendulum
    at = {q: 0 for q in model.q}
    M = mass_matrix(model, at)
    K = stiffness_matrix(potential_energy(model).total, model.q, at)
    assert_same(mech["M"], M, "mass matrix M")
    assert_same(mech["K"], K, "stiffness matrix K")


def test_double_pendulum_modes_answers_match_mechanics(double_pendulum):
    """The modes question of the scene itself, end to end."""
    model, mech = double_pendulum
    report = solve_problem(model)
    answers = modes_answers(report, ["theta1", "theta2"])
    assert_same(mech["M"], answers.M, "mass matrix M")
    assert_same(mech["K"], answers.K, "stiffness matrix K")
