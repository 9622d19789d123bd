"""The reactions question against an independent oracle: sympy.physics.mechanics'
KanesMethod with auxiliary speeds, which gives a constraint force from the generalized
speed that the constraint forbids (no rbdsolve code in the oracle). Two of issue 21's
cases: the rod pivoted at one end (the pivot's R_x, R_y at any state) and the particle
on a smooth sphere (N at any state), each compared exactly with rbdsolve's reaction as a
function of the state (θ, θ̇)."""

from __future__ import annotations

import json

import pytest
import sympy as sp
from sympy.physics.mechanics import KanesMethod, Particle, Point, ReferenceFrame, RigidBody, dynamicsymbols, inertia

from rbdsolve.model.build import build_model
from rbdsolve.problem import load_file
from rbdsolve.render.json import report_object
from rbdsolve.solvers import solve_problem

from conftest import PROBLEMS

m, l, g, R = sp.symbols("m l g R", positive=True)
TH, THD = sp.symbols("theta thetadot")


def _kane_forces(bodies, loads, N, th, w, aux, forces):
    """The constraint forces from Kane's auxiliary equations, q̈ from the ordinary ones."""
    kane = KanesMethod(N, q_ind=[th], u_ind=[w], kd_eqs=[th.diff() - w], u_auxiliary=aux)
    fr, frstar = kane.kanes_equations(bodies, loads)
    (wdot,) = sp.solve((fr + frstar)[0], w.diff())
    found = sp.solve([e.subs(w.diff(), wdot) for e in kane.auxiliary_eqs], forces, dict=True)[0]
    return {k: sp.simplify(v.subs(w, THD).subs(th, TH)) for k, v in found.items()}


def rod_pivot_kane():
    """The rod of problems/forces/rod-pivot-released.yaml: G = (l/2)(cos θ, −sin θ)."""
    th, w = dynamicsymbols("theta w")
    ux, uy = dynamicsymbols("u_x u_y")
    Rx, Ry = sp.symbols("R_x R_y")
    N = ReferenceFrame("N")
    A = N.orientnew("A", "Axis", (-th, N.z))
    A.set_ang_vel(N, -w * N.z)
    O = Point("O")
    O.set_vel(N, ux * N.x + uy * N.y)
    G = O.locatenew("G", l / 2 * A.x)
    G.v2pt_theory(O, N, A)
    rod = RigidBody("rod", G, A, m, (inertia(A, 0, 0, m * l**2 / 12), G))
    loads = [(G, -m * g * N.y), (O, Rx * N.x + Ry * N.y)]
    return _kane_forces([rod], loads, N, th, w, [ux, uy], [Rx, Ry]), (Rx, Ry)


def sphere_kane():
    """The particle of problems/forces/particle-on-sphere.yaml: P = R (sin θ, cos θ), the
    push N along the outward normal, the speed it forbids along it too."""
    th, w = dynamicsymbols("theta w")
    un = dynamicsymbols("u_n")
    Nn = sp.Symbol("N")
    N = ReferenceFrame("N")
    A = N.orientnew("A", "Axis", (-th, N.z))  # A.y is the outward normal (sin θ, cos θ)
    A.set_ang_vel(N, -w * N.z)
    O = Point("O")
    O.set_vel(N, 0)
    P = O.locatenew("P", R * A.y)
    P.v2pt_theory(O, N, A)
    P.set_vel(N, P.vel(N) + un * A.y)
    loads = [(P, -m * g * N.y + Nn * A.y)]
    return _kane_forces([Particle("p", P, m)], loads, N, th, w, [un], [Nn]), (Nn,)


def _reaction(name: str, point: str) -> dict[str, sp.Expr]:
    report = solve_problem(build_model(load_file(PROBLEMS / "forces" / f"{name}.yaml")))
    result = json.loads(json.dumps(report_object(report)))["results"][0]
    f, t = sp.Function("theta"), sp.Symbol("t")
    names = {"m": m, "l": l, "g": g, "R": R, "t": t, "theta": f}
    out = {}
    for key, text in result["answers"]["reactions"][point]["components"].items():
        expr = sp.sympify(text, locals=names).subs(sp.Derivative(f(t), t), THD)
        out[key] = expr.subs(f(t), TH)
    return out


@pytest.mark.parametrize("name, point, oracle, keys", [
    ("rod-pivot-released", "O", rod_pivot_kane, ("R_Ox", "R_Oy")),
    ("particle-on-sphere", "P", sphere_kane, ("N_P",)),
])
def test_reaction_as_a_function_of_the_state(name, point, oracle, keys) -> None:
    expected, symbols = oracle()
    got = _reaction(name, point)
    for key, symbol in zip(keys, symbols):
        assert sp.simplify(got[key] - expected[symbol]) == 0, (key, got[key], expected[symbol])
