"""The one reader of a state (``context.Reading.state``): ``eom``'s and ``reactions``'
``at:`` (every coordinate and rate), ``from_rest:`` (every coordinate) and
``kinematics``' ``at:`` (any of q, dot(q), ddot(q)) follow the same rules, and their
bad input exits 2 at file:line:column with the key path, naming what is missing."""

from __future__ import annotations

import pytest
from click.testing import CliRunner

from rbdsolve.cli import main

from conftest import PROBLEMS, SEED


def _p1(question: str) -> str:
    head = (SEED / "p1-two-rods.yaml").read_text(encoding="utf-8").split("questions:")[0]
    return head + f"questions:\n  - {question}\n"


def _rod(options: str) -> str:
    text = (PROBLEMS / "forces" / "rod-pivot-released.yaml").read_text(encoding="utf-8")
    return text.replace("{forces: [O], from_rest: {theta: 0}}", "{forces: [O], " + options + "}")


def _check(tmp_path, text: str):
    path = tmp_path / "p.yaml"
    path.write_text(text, encoding="utf-8")
    return CliRunner().invoke(main, ["check", str(path)])


@pytest.mark.parametrize("text, path, message", [
    (_p1("eom: {at: {theta: 0, phi: 0, dot(theta): 0}}"), "questions[0].eom.at", "missing dot(phi)"),
    (_p1("eom: {at: {theta: 0, dot(theta): 0, dot(phi): 1}}"), "questions[0].eom.at", "missing phi"),
    (_rod("at: {theta: 0}"), "questions[0].reactions.at", "missing dot(theta) (or give 'from_rest:'"),
    (_rod("at: {dot(theta): 0}"), "questions[0].reactions.at", "missing theta"),
    (_rod("from_rest: {}"), "questions[0].reactions.from_rest", "missing theta"),
    (_rod("at: {theta: 0, dot(thta): 0}"), "questions[0].reactions.at.dot(thta)",
     "'dot(thta)' is not a coordinate, nor dot() of one (did you mean 'dot(theta)'?)"),
    (_rod("at: {theta: 0, dot(theta): 0, ddot(theta): 0}"), "questions[0].reactions.at.ddot(theta)",
     "'ddot(theta)' is not a coordinate, nor dot() of one"),
    (_rod("from_rest: {dot(theta): 0}"), "questions[0].reactions.from_rest.dot(theta)",
     "'dot(theta)' is not a coordinate"),
])
def test_a_bad_state_is_located_and_named(tmp_path, text, path, message) -> None:
    out = _check(tmp_path, text)
    assert out.exit_code == 2, out.output
    assert "p.yaml:" in out.output and path in out.output and message in out.output


def test_kinematics_takes_part_of_a_state(tmp_path) -> None:
    """kinematics leaves out what it is not given (symbolic), and takes ddot(q) too."""
    out = _check(tmp_path, _p1("kinematics: {points: [G2], at: {theta: 0, ddot(phi): 1}}"))
    assert out.exit_code == 0, out.output
    out = _check(tmp_path, _p1("kinematics: {points: [G2], at: {thta: 0}}"))
    assert out.exit_code == 2 and "'thta' is not a coordinate, nor dot() or ddot() of one" in out.output
