"""Independent oracle for ``problems/steady/rolling-cone.yaml``: a solid cone rolling on
its side, its tip O at rest, its line of contact turning at Omega about the vertical.

A cone on its side touches the table along a line, so the table's push is spread along
it: rbdsolve finds its resultant N and the distance x_N from the tip where it acts,
and the friction (F1 along the line, F2 across it), from Newton's law for G and the
angular momentum balance about O, with the contact forces stated as reactions.

The oracle derives the same from scratch with ``sympy.physics.mechanics``:

- the cone with its tip fixed at O, oriented by heading psi about the vertical, tilt
  theta about the new horizontal y axis (so its axis rises at theta from the line of
  contact) and spin phi about its axis; textbook moments of a solid cone about its
  centre of mass, 3/4 h from the tip: 3 m a²/10 axial, 3 m a²/20 + 3 m h²/80 across;
- the steady motion: psi' = Omega, theta = alpha (the half-angle: then the cone lies
  on the table), theta' = 0, and the spin that keeps the rim's contact point at rest
  (found here from that point's velocity, v = 0);
- Kane's equations fr + fr* = 0 with gravity at G and the normal force N N.z at the
  cone's point x_N along the line of contact (friction at the tip, where the velocity
  is zero, contributes nothing), at the steady state (all accelerations u' = 0): the
  tilt equation fixes N x_N, the other two must hold identically;
- N and the friction from G's acceleration: m a_G = m g + N + F.

Exact comparisons: ``simplify(a - b) == 0``.
"""

from __future__ import annotations

import json

import pytest
import sympy as sp
import sympy.physics.mechanics as me

from rbdsolve.model.build import build_model
from rbdsolve.problem import load_file
from rbdsolve.render.json import report_object
from rbdsolve.solvers import solve_problem

from conftest import PROBLEMS

m, h, alpha, g, Omega = sp.symbols("m h alpha g Omega", positive=True)
N_, x_N = sp.symbols("N x_N", real=True)


def _oracle():
    psi, theta, phi = me.dynamicsymbols("psi theta phi")
    u1, u2, u3 = me.dynamicsymbols("u1 u2 u3")
    spin = sp.Symbol("spin", real=True)
    N = me.ReferenceFrame("N")
    A = N.orientnew("A", "Axis", [psi, N.z])  # turns with the line of contact
    B = A.orientnew("B", "Axis", [-theta, A.y])  # B.x is the cone's axis from the tip
    C = B.orientnew("C", "Axis", [phi, B.x])  # the cone
    O = me.Point("O")
    O.set_vel(N, 0)
    a = h * sp.tan(alpha)
    G = O.locatenew("G", 3 * h / 4 * B.x)
    G.v2pt_theory(O, N, C)
    I_G = me.inertia(C, 3 * m * a**2 / 10, 3 * m * a**2 / 20 + 3 * m * h**2 / 80,
                     3 * m * a**2 / 20 + 3 * m * h**2 / 80)
    cone = me.RigidBody("cone", G, C, m, (I_G, G))
    Q = O.locatenew("Q", x_N * A.x)  # the cone's point where N acts, on the line of contact
    Q.v2pt_theory(O, N, C)
    rim = O.locatenew("rim", h / sp.cos(alpha) * A.x)
    rim.v2pt_theory(O, N, C)
    kane = me.KanesMethod(N, q_ind=[psi, theta, phi], u_ind=[u1, u2, u3],
                          kd_eqs=[psi.diff() - u1, theta.diff() - u2, phi.diff() - u3])
    fr, frstar = kane.kanes_equations([cone], [(G, -m * g * N.z), (Q, N_ * N.z)])
    steady = {u1.diff(): 0, u2.diff(): 0, u3.diff(): 0}
    state = {u1: Omega, u2: 0, u3: spin, theta: alpha, psi: 0, phi: 0}

    def at_steady(x):
        return sp.simplify(x.subs(steady).subs(kane.kindiffdict()).subs(state))

    v_rim = [at_steady(rim.vel(N).dot(e)) for e in (A.x, A.y, A.z)]
    (found,) = sp.solve([v for v in v_rim if v != 0], [spin], dict=True)
    spin_value = found[spin]
    equations = [sp.simplify(e.subs(spin, spin_value)) for e in (fr + frstar).subs(steady).subs(state)]
    a_G = [at_steady(G.acc(N).dot(e)).subs(spin, spin_value) for e in (A.x, A.y, A.z)]
    normal = sp.solve(m * a_G[2] + m * g - N_, N_)[0]  # vertical: m a_Gz = N − m g
    omega = [sp.simplify(at_steady(C.ang_vel_in(N).dot(e)).subs(spin, spin_value)) for e in (A.x, A.y, A.z)]
    return {"spin": spin_value, "equations": equations, "N": normal,
            "F1": sp.simplify(m * a_G[0]), "F2": sp.simplify(m * a_G[1]), "omega": omega}


@pytest.fixture(scope="module")
def oracle():
    return _oracle()


@pytest.fixture(scope="module")
def answers():
    report = solve_problem(build_model(load_file(PROBLEMS / "steady" / "rolling-cone.yaml")))
    (result,) = json.loads(json.dumps(report_object(report)))["results"]
    assert result["ok"], result["error"]
    return result["answers"]


def same(a, b) -> bool:
    names = {"m": m, "h": h, "alpha": alpha, "g": g, "Omega": Omega, "N": N_, "x_N": x_N}
    return sp.simplify(sp.sympify(a, locals=names) - b) == 0


def test_rolling_fixes_the_spin_and_the_angular_velocity(oracle, answers) -> None:
    assert same(answers["rates"]["spin"], oracle["spin"])
    for got, want in zip(answers["angular_velocity"], oracle["omega"]):
        assert same(got, want)
    assert oracle["omega"][1] == 0 and oracle["omega"][2] == 0  # along the line of contact


def test_normal_force_and_friction(oracle, answers) -> None:
    solved = answers["solved"]
    assert same(solved["N"], oracle["N"]) and same(solved["N"], m * g)
    assert same(solved["F1"], oracle["F1"]) and same(solved["F2"], oracle["F2"])


def test_where_the_normal_force_acts(oracle, answers) -> None:
    """Kane's tilt equation at the steady state, with N from the vertical balance,
    fixes x_N; the heading and spin equations hold identically."""
    equations = [sp.simplify(e.subs(N_, oracle["N"])) for e in oracle["equations"]]
    holding = [e for e in equations if e.has(x_N)]
    assert len(holding) == 1 and all(e == 0 for e in equations if not e.has(x_N))
    (want,) = sp.solve(holding[0], x_N)
    assert same(answers["solved"]["x_N"], want)
