"""The reactions question beyond the goldens: a joint between two bodies (seed problem 1's
rods) checked against Newton's law for the whole system written by hand, and the bad
input of item 6 (a point that holds nothing, a body not in a contact, a support left out)."""

from __future__ import annotations

import json

import pytest
import sympy as sp
from click.testing import CliRunner

from rbdsolve.cli import main
from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.render.json import report_object
from rbdsolve.solvers import solve_problem

from conftest import PROBLEMS, SEED


def _p1(question: str) -> str:
    head = (SEED / "p1-two-rods.yaml").read_text(encoding="utf-8").split("questions:")[0]
    return head + f"questions:\n  - {question}\n"


def _result(text: str) -> dict:
    report = solve_problem(build_model(load_text(text, "p.yaml")))
    return json.loads(json.dumps(report_object(report)))["results"][0]


def test_two_rods_pivot_and_joint_just_after_release() -> None:
    """From rest at θ = π/2, φ = π/2 (hand: θ̈ = −26 g/(25 r), φ̈ = −18 g/(25 r), see
    tests/solvers/eom). At rest a_G1 = (r/2) θ̈ (cos θ, sin θ) = (0, r θ̈/2) and
    a_G2 = a_G1 + (r/2) φ̈ (0, 1). The joint's force on the short rod is
    m a_G2 + m g ŷ; the circle's force on the long rod (its midpoint O's reaction) is the
    whole system's: 3m a_G1 + m a_G2 + 4 m g ŷ."""
    m, r, g = sp.symbols("m r g", positive=True)
    tdd, pdd = -sp.Rational(26, 25) * g / r, -sp.Rational(18, 25) * g / r
    a1 = r / 2 * tdd
    a2 = a1 + r / 2 * pdd
    result = _result(_p1("reactions: {forces: [{at: O, on: long_rod}, {at: G1, on: short_rod, by: long_rod}], "
                         "from_rest: {theta: pi/2, phi: pi/2}}"))
    assert result["ok"], result["error"]
    at = result["answers"]["at"]
    names = {"m": m, "r": r, "g": g}
    joint = at["G1"]["components"]
    assert sp.sympify(joint["R_G1x"], locals=names) == 0
    assert sp.simplify(sp.sympify(joint["R_G1y"], locals=names) - (m * a2 + m * g)) == 0
    pivot = at["O"]["components"]
    assert sp.simplify(sp.sympify(pivot["R_Oy"], locals=names) - (3 * m * a1 + m * a2 + 4 * m * g)) == 0


def _invoke(tmp_path, text: str, *more: str):
    path = tmp_path / "p.yaml"
    path.write_text(text, encoding="utf-8")
    return CliRunner().invoke(main, ["solve", str(path), *more])


@pytest.mark.parametrize("route", ["exact", "numeric"])
def test_a_support_left_out_is_bad_input(tmp_path, route) -> None:
    """The joint at G1 left out: the short rod's balances cannot hold (exit 2, at the
    force asked for on it), on both routes."""
    text = _p1("reactions: {forces: [{at: O, on: long_rod}], from_rest: {theta: 1, phi: 0}}")
    text = text.replace("values:\n  m: {range: [1, 5], step: 0.5}\n  r: {range: [0.2, 2], step: 0.1}\n  "
                        "g: {choices: [9.81, 10]}", "values: {m: 2, r: 1/2, g: 10}")
    out = _invoke(tmp_path, text, "--route", route)
    assert out.exit_code == 2, out.output
    assert "cannot keep body 'long_rod' in its motion" in out.output and "a support on it is missing" in out.output
    assert "p.yaml:" in out.output and "questions[0].reactions.forces[0]" in out.output


def test_a_point_that_holds_nothing_is_bad_input(tmp_path) -> None:
    """G2 moves freely in the plane (two coordinates): nothing can hold it there."""
    out = _invoke(tmp_path, _p1("reactions: {forces: [{at: G2, on: short_rod}]}"))
    assert out.exit_code == 2 and "'G2' is not a support of body 'short_rod'" in out.output
    assert "p.yaml:" in out.output and "questions[0].reactions.forces[0]" in out.output


def test_a_point_on_a_path_that_holds_nothing_is_bad_input(tmp_path) -> None:
    """With one coordinate every point moves along a path, so the kinematics cannot tell a
    guide from nothing; the balances do: the rod's moment about G is left (exit 2)."""
    text = (PROBLEMS / "forces" / "rod-pivot-released.yaml").read_text(encoding="utf-8")
    out = _invoke(tmp_path, text.replace("forces: [O]", "forces: [G]"))
    assert out.exit_code == 2, out.output
    assert "a point listed does not hold it" in out.output and "questions[0].reactions.forces[0]" in out.output


def test_a_body_not_in_the_contact_is_bad_input(tmp_path) -> None:
    text = (PROBLEMS / "forces" / "yo-yo.yaml").read_text(encoding="utf-8")
    out = _invoke(tmp_path, text.replace("forces: [S]", "forces: [{at: S, on: wheel}]"))
    assert out.exit_code == 2 and "is not in contact at 'S'" in out.output


def test_an_unknown_point_is_bad_input(tmp_path) -> None:
    text = (PROBLEMS / "forces" / "rod-pivot-released.yaml").read_text(encoding="utf-8")
    out = _invoke(tmp_path, text.replace("forces: [O]", "forces: [Q]"))
    assert out.exit_code == 2 and "no point or contact 'Q'" in out.output
