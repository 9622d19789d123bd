"""Steady spins of a free body with symbolic moments, decided by assumptions (issue 19).

By hand (Euler's equations, e.g. Goldstein ch. 5.6): with A > B > C, a spin about the
largest or smallest moment is stable, its perturbation turning at
ν = Ω √((J − J_i)(J − J_j)/(J_i J_j)); about the intermediate one it grows at
γ = Ω √((A − B)(B − C)/(A C)).
"""

from __future__ import annotations

import sympy as sp

from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.solvers import solve_problem

BODY = """\
parameters: {m: mass, A: moment 1, B: moment 2, C: moment 3}
bodies:
  b: {mass: m, inertia: [A, B, C], at: [0, 0, 0]}
questions:
  - steady_spin
"""


def test_an_order_of_the_moments_decides_every_spin() -> None:
    (solution,) = solve_problem(build_model(load_text(BODY + "assumptions: [A > B, B > C]\n", "b.yaml"))).solutions
    assert solution.solved, solution.error
    (case,) = solution.answers.cases
    A, B, C, W = sp.symbols("A B C Omega", positive=True)
    local = {"A": A, "B": B, "C": C, "Omega": W}
    want = [("stable", W * sp.sqrt((A - B) * (A - C) / (B * C))),
            ("unstable", W * sp.sqrt((A - B) * (B - C) / (A * C))),
            ("stable", W * sp.sqrt((A - C) * (B - C) / (A * B)))]
    for spin, (kind, rate) in zip(case.stability, want):
        assert spin.stability.value == kind
        got = sp.parse_expr(str(spin.rate), local_dict=local)
        for values in ({A: 3, B: 2, C: 1, W: 1}, {A: 7, B: sp.Rational(5, 2), C: sp.Rational(1, 3), W: 2}):
            assert abs(float(got.subs(values)) - float(rate.subs(values))) < 1e-12


def test_without_the_assumption_the_condition_is_stated() -> None:
    (solution,) = solve_problem(build_model(load_text(BODY, "b.yaml"))).solutions
    assert any(spin.stability.value == "conditional" for case in solution.answers.cases for spin in case.stability)
