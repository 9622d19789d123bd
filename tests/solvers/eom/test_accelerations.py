"""eom's accelerations q̈ = −M⁻¹ h, and at a state (``at:``, ``from_rest:``).

The oracle is sympy.physics.mechanics' KanesMethod on seed problem 1 (two rods, the
long one a chord of a circle of radius r, the short one pinned at its midpoint), built
from frames and points with no rbdsolve code; its mass matrix and forcing give
q̈ = M⁻¹ f, compared exactly with rbdsolve's, everywhere and just after release.
"""

from __future__ import annotations

import sympy as sp
from click.testing import CliRunner
from sympy.physics.mechanics import KanesMethod, Point, ReferenceFrame, RigidBody, dynamicsymbols, inertia

from rbdsolve.cli import main
from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.solvers import solve_problem

from conftest import SEED

m, r, g = sp.symbols("m r g", positive=True)


def two_rods_kane():
    """(θ̈, φ̈) of seed problem 1 as functions of θ, φ, θ̇, φ̇, by Kane's method."""
    th, ph = dynamicsymbols("theta phi")
    wt, wp = dynamicsymbols("w_theta w_phi")
    N = ReferenceFrame("N")
    A = N.orientnew("A", "Axis", (th, N.z))
    B = N.orientnew("B", "Axis", (ph, N.z))
    O = Point("O")
    O.set_vel(N, 0)
    G1 = O.locatenew("G1", r / 2 * A.y * -1)
    G2 = G1.locatenew("G2", r / 2 * B.y * -1)
    A.set_ang_vel(N, wt * N.z)
    B.set_ang_vel(N, wp * N.z)
    G1.v2pt_theory(O, N, A)
    G2.v2pt_theory(G1, N, B)
    long_rod = RigidBody("long", G1, A, 3 * m, (inertia(A, 0, 0, 3 * m * 3 * r**2 / 12), G1))
    short_rod = RigidBody("short", G2, B, m, (inertia(B, 0, 0, m * r**2 / 12), G2))
    loads = [(G1, -3 * m * g * N.y), (G2, -m * g * N.y)]
    kane = KanesMethod(N, q_ind=[th, ph], u_ind=[wt, wp], kd_eqs=[th.diff() - wt, ph.diff() - wp])
    kane.kanes_equations([long_rod, short_rod], loads)
    udot = kane.mass_matrix.LUsolve(kane.forcing)
    plain = sp.symbols("theta phi theta_dot phi_dot")
    return [sp.simplify(x.subs({wt: plain[2], wp: plain[3]}).subs({th: plain[0], ph: plain[1]})) for x in udot], plain


def _answers(text: str) -> dict:
    from rbdsolve.render.json import report_object
    import json
    report = solve_problem(build_model(load_text(text, "p1.yaml")))
    return json.loads(json.dumps(report_object(report)))["results"][0]


def _p1(question: str) -> str:
    text = (SEED / "p1-two-rods.yaml").read_text(encoding="utf-8")
    head = text.split("questions:")[0]
    return head + f"questions:\n  - {question}\n"


def _read(text: str, plain) -> sp.Expr:
    th, ph, thd, phd = plain
    t = sp.Symbol("t")
    f = {"theta": sp.Function("theta"), "phi": sp.Function("phi")}
    expr = sp.sympify(text, locals={"m": m, "r": r, "g": g, "t": t, **f})
    expr = expr.subs({sp.Derivative(f["theta"](t), t): thd, sp.Derivative(f["phi"](t), t): phd})
    return expr.subs({f["theta"](t): th, f["phi"](t): ph})


def test_two_rods_accelerations_against_kanes_method() -> None:
    kane, plain = two_rods_kane()
    result = _answers(_p1("eom"))
    got = result["answers"]["accelerations"]
    for name, want in zip(("theta", "phi"), kane):
        assert sp.simplify(_read(got[name], plain) - want) == 0, name


def test_two_rods_just_after_release() -> None:
    """From rest at θ = π/3, φ = −π/4: the exact numbers, Kane's q̈ at that state."""
    kane, plain = two_rods_kane()
    result = _answers(_p1("eom: {from_rest: {theta: pi/3, phi: -pi/4}}"))
    state = dict(zip(plain, (sp.pi / 3, -sp.pi / 4, 0, 0)))
    for name, want in zip(("theta", "phi"), kane):
        assert sp.simplify(_read(result["answers"]["at"][name], plain) - want.subs(state)) == 0, name
    kinds = [s["kind"] for s in result["steps"]]
    assert "given" in kinds and result["steps"][kinds.index("given")]["text"].startswith("Released from rest")


def test_a_state_with_rates() -> None:
    kane, plain = two_rods_kane()
    result = _answers(_p1("eom: {at: {theta: pi/2, phi: 0, dot(theta): 2, dot(phi): -1}}"))
    state = dict(zip(plain, (sp.pi / 2, 0, 2, -1)))
    for name, want in zip(("theta", "phi"), kane):
        assert sp.simplify(_read(result["answers"]["at"][name], plain) - want.subs(state)) == 0, name


def test_values_give_numbers(tmp_path) -> None:
    """With values, the accelerations at the state are numbers: θ̈ = −26 g/(25 r) by hand
    (M = m r² [[7/4, 1/4], [1/4, 1/3]] at θ = φ = π/2, generalized forces −m g r (2, 1/2))."""
    text = _p1("eom: {from_rest: {theta: pi/2, phi: pi/2}}").replace(
        "values:\n  m: {range: [1, 5], step: 0.5}\n  r: {range: [0.2, 2], step: 0.1}\n  g: {choices: [9.81, 10]}",
        "values: {m: 2, r: 1/2, g: 10}")
    result = _answers(text)
    assert result["values"]["at"]["theta"] == -26 * 10 / (25 * 0.5)
    assert abs(result["values"]["at"]["phi"] + 18 * 10 / (25 * 0.5)) < 1e-12


def test_a_state_missing_a_rate_is_named(tmp_path) -> None:
    path = tmp_path / "p.yaml"
    path.write_text(_p1("eom: {at: {theta: 0, phi: 0, dot(theta): 0}}"), encoding="utf-8")
    out = CliRunner().invoke(main, ["check", str(path)])
    assert out.exit_code == 2
    assert "missing dot(phi)" in out.output and "questions[0].eom.at" in out.output


def test_from_rest_missing_a_coordinate_is_named(tmp_path) -> None:
    path = tmp_path / "p.yaml"
    path.write_text(_p1("eom: {from_rest: {theta: 0}}"), encoding="utf-8")
    out = CliRunner().invoke(main, ["check", str(path)])
    assert out.exit_code == 2 and "missing phi" in out.output
