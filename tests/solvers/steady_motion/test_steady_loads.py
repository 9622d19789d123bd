"""A steady motion with an applied couple: a symmetric top precessing at Ω with a
couple Q0 about the line of nodes e1 besides gravity; the spin it needs against Euler's
law about O written here (dL/dt = Ω_T × L in the precessing triad)."""

from __future__ import annotations

import json

import sympy as sp

from rbdsolve.model.build import build_model
from rbdsolve.problem import load_file, load_text
from rbdsolve.render.json import report_object
from rbdsolve.solvers import solve_problem

from conftest import PROBLEMS, positive_names


def _turn(axis: int, angle) -> sp.Matrix:
    """The active turn by ``angle`` about a coordinate axis (columns: the turned axes)."""
    c, s = sp.cos(angle), sp.sin(angle)
    i, j = [k for k in range(3) if k != axis]
    R = sp.eye(3)
    R[i, i], R[i, j], R[j, i], R[j, j] = c, -s, s, c
    return R


def test_a_top_with_a_couple_about_the_line_of_nodes() -> None:
    m, h, J1, J3, g, theta, Omega, Q0, t = sp.symbols("m h J1 J3 g theta Omega Q0 t", positive=True)
    spin = sp.Symbol("spin", real=True)
    T = _turn(2, Omega * t) * _turn(0, theta)  # [[z, Omega*t], [x, theta]]
    z = T.T * sp.Matrix([0, 0, 1])  # the vertical in the triad's components
    omega = Omega * z + spin * sp.Matrix([0, 0, 1])
    L = sp.diag(J1 + m * h**2, J1 + m * h**2, J3) * omega  # about O, the triad's axes principal there
    weight = T.T * sp.Matrix([0, 0, -m * g])
    M = (h * sp.Matrix([0, 0, 1])).cross(weight) + sp.Matrix([Q0, 0, 0])
    (expected,) = sp.solve(sp.simplify(((Omega * z).cross(L) - M)[0]), spin)

    text = (PROBLEMS / "steady" / "heavy-top.yaml").read_text(encoding="utf-8")
    text = text.replace("  Omega: rate of precession", "  Omega: rate of precession\n  Q0: couple")
    text = text.replace("questions:", "couples:\n  turn: {on: top, moment: Q0*e1}\nquestions:")
    (result,) = json.loads(json.dumps(report_object(solve_problem(build_model(load_text(text, "top.yaml"))))))[
        "results"]
    assert result["ok"], result["error"]
    got = result["answers"]["solved"]["spin"]
    names = positive_names(got)
    assert sp.simplify(sp.sympify(got, locals=names) - expected.subs({s: names.get(s.name, s)
                                                                       for s in expected.free_symbols})) == 0
    assert load_file(PROBLEMS / "steady" / "heavy-top.yaml").couples == ()


def test_moments_about_a_point_moving_across_G_s_path() -> None:
    """The top with its pivot's force R = R1 e1 + R2 e2 + R3 e3 unknown, moments taken
    about P = a e1, a point of the precessing triad beside O on the line of nodes: P
    moves at v_P = Ω_T × a e1 = Ω a (cos θ e2 − sin θ e3), across G's v_G = Ω h sin θ e1,
    so the balance about P needs its transport term v_P × m v_G (dL_P/dt + v_P × m v_G
    = M_P). Expected here from Newton's law for G and Euler's law about G instead, where
    no such term enters: m Ω_T × v_G = m g + R and Ω_T × J_G ω = h(−e3) × R."""
    m, h, J1, J3, g, theta, Omega, a, t = sp.symbols("m h J1 J3 g theta Omega a t", positive=True)
    spin, R1, R2, R3 = sp.symbols("spin R1 R2 R3", real=True)
    T = _turn(2, Omega * t) * _turn(0, theta)
    Omega_T = Omega * (T.T * sp.Matrix([0, 0, 1]))
    e3 = sp.Matrix([0, 0, 1])
    R = sp.Matrix([R1, R2, R3])
    v_G = Omega_T.cross(h * e3)
    newton = m * Omega_T.cross(v_G) - (T.T * sp.Matrix([0, 0, -m * g]) + R)
    L_G = sp.diag(J1, J1, J3) * (Omega_T + spin * e3)
    euler = Omega_T.cross(L_G) - (-h * e3).cross(R)
    (expected,) = sp.solve(list(newton) + list(euler), [spin, R1, R2, R3], dict=True)

    text = (PROBLEMS / "steady" / "heavy-top.yaml").read_text(encoding="utf-8")
    text = text.replace("  Omega: rate of precession", "  Omega: rate of precession\n  a: distance from O to P")
    text = text.replace("unknowns: [spin]", "unknowns: [spin, R1, R2, R3]")
    text = text.replace("  G: h*e3", "  G: h*e3\n  P: a*e1")
    text = text.replace("{about: O, solve_for: spin}",
                        "{about: P, reactions: [{at: O, force: R1*e1 + R2*e2 + R3*e3}], solve_for: [spin, R1, R2, R3]}")
    (result,) = json.loads(json.dumps(report_object(solve_problem(build_model(load_text(text, "top.yaml"))))))[
        "results"]
    assert result["ok"], result["error"]
    solved = result["answers"]["solved"]
    assert set(solved) == {"spin", "R1", "R2", "R3"}
    for name, value in expected.items():
        got = sp.sympify(solved[name.name], locals=positive_names(solved[name.name]))
        names = {s.name: s for s in (m, h, J1, J3, g, theta, Omega, a)}
        assert sp.simplify(got.subs({s: names[s.name] for s in got.free_symbols}) - value) == 0, (name, got, value)
