"""Equilibria where the loads do not change as the body moves (∂V/∂q holds no
coordinate): the spool rests only where cos α = r/R. The printed condition is sampled
on both sides of it, and at it, with values (R = 2, r = 1: α = π/3)."""

from __future__ import annotations

import json

import pytest
import sympy as sp

from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.render.json import report_object
from rbdsolve.solvers import solve_problem

from conftest import PROBLEMS

SPOOL = (PROBLEMS / "forces" / "spool-pulled-at-angle.yaml").read_text(encoding="utf-8")


def _equilibria(values: str | None = None) -> dict:
    text = SPOOL.replace("  - eom\n  - reactions: {forces: [C]}\n", "")
    if values:
        text = text.replace("questions:", f"values: {{{values}}}\nquestions:")
    (result,) = json.loads(json.dumps(report_object(solve_problem(build_model(load_text(text, "s.yaml"))))))["results"]
    return result


def test_the_condition_is_the_spool_s() -> None:
    result = _equilibria()
    (eq,) = result["answers"]["equilibria"]
    assert eq["stability"] == "neutral"
    alpha, r, R = (sp.Symbol(n, positive=True) for n in ("alpha", "r", "R"))
    condition = sp.sympify(eq["exists_when"], locals={"alpha": alpha, "r": r, "R": R})
    assert isinstance(condition, sp.Eq) and sp.simplify(condition.lhs - condition.rhs - (sp.cos(alpha) - r / R)) == 0


@pytest.mark.parametrize("alpha, exists", [("pi/4", False), ("pi/3", True), ("2*pi/5", False)])
def test_sampled_on_both_sides_of_cos_alpha_r_over_R(alpha: str, exists: bool) -> None:
    """With R = 2, r = 1 the spool rests only at α = π/3; the force on it along x,
    F (cos α − r/R), is by hand > 0 below and < 0 above."""
    result = _equilibria(f"R: 2, r: 1, alpha: {alpha}")
    assert result["ok"] is exists, result
    if exists:
        assert result["answers"]["equilibria"][0]["at"] == {"x": "0"}


DISK = (PROBLEMS / "forces" / "disk-pulled-up-incline.yaml").read_text(encoding="utf-8")


def _disk_condition(option: str) -> sp.Basic:
    text = DISK.replace("  - eom\n  - reactions: {forces: [C]}\n", "").replace("  - equilibria: {for: F}", option)
    (result,) = json.loads(json.dumps(report_object(solve_problem(build_model(load_text(text, "d.yaml"))))))["results"]
    (eq,) = result["answers"]["equilibria"]
    names = {n: sp.Symbol(n, positive=True) for n in ("F", "g", "m", "alpha")}
    return sp.sympify(eq["exists_when"], locals=names), names


@pytest.mark.parametrize("option, solved_for", [("  - equilibria: {for: F}", "F"), ("  - equilibria: {for: m}", "m"),
                                                ("  - equilibria", "m")])
def test_the_condition_is_solved_for_the_parameter_asked(option: str, solved_for: str) -> None:
    """The disk pulled up the incline by a string from its top rests where 2F = m g sin α
    (by hand: Newton along the slope and moments about G): written in the parameter
    'for:' names, else in the first without a value (α has one, 30°)."""
    condition, s = _disk_condition(option)
    assert isinstance(condition, sp.Eq) and condition.lhs == s[solved_for]
    F, g, m, alpha = s["F"], s["g"], s["m"], s["alpha"]
    assert not condition.rhs.has(condition.lhs)
    residual = (2 * F - m * g * sp.sin(alpha)).subs(condition.lhs, condition.rhs)
    assert sp.simplify(residual) == 0
