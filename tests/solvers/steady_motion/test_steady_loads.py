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
