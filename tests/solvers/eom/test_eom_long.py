"""A chain of five links: Lagrange's equations are given, but the general q̈ (Cramer's
rule: numerators of about 10⁴ operations) is too long to write out, and is refused at
once rather than cancelled for minutes (solvers/lagrange/accelerations.py, NUMERATOR_OPS)."""

from __future__ import annotations


from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.solvers import solve_problem

from conftest import chain  # the n-link chain of the numeric tests, shared


def test_five_links_give_their_equations_without_the_general_accelerations() -> None:
    report = solve_problem(build_model(load_text(chain(5, rods=False).replace("questions: [modes]", "questions: [eom]"), "chain.yaml")))
    eom = report.solutions[0]
    assert eom.error is None and eom.answers.accelerations is None
    assert len(eom.answers.equations) == 5
    assert any("too long to be useful" in s.text for s in eom.steps)
