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


# --- a state's values with units (as exams write them) ----------------------------------

TRIANGLE = """title: an equilateral triangle hung by a vertex
parameters: {m: mass, a: side, g: gravity}
values: {m: 2 kg, a: 30 cm, g: 9.81 m/s^2}
coordinates: [theta]
gravity: [0, -g]
points:
  O: [0, 0]
bodies:
  plate: {shape: triangle, mass: m, base: a, height: sqrt(3)*a/2, apex: a/2, at: O, angle: theta - 2*pi/3}
questions:
  - energy: {from_rest: {theta: START}, to: {theta: 0}}
"""


def _solved(tmp_path, text: str) -> dict:
    import json

    path = tmp_path / "p.yaml"
    path.write_text(text, encoding="utf-8")
    out = CliRunner().invoke(main, ["solve", str(path), "--format", "json"])
    assert out.exit_code == 0, out.output
    return json.loads(out.stdout)["results"][0]


def test_a_release_angle_in_degrees_is_read_in_radians(tmp_path) -> None:
    """By hand: the centroid lies a/√3 below the vertex, J_O = m a²/12 + m a²/3 = 5 m a²/12,
    so ½ J_O θ̇² = m g (a/√3)(cos θ − cos θ₀) and at the bottom θ̇² = 8 √3 g (1 − cos θ₀)/(5 a):
    from 10° with a = 0.3 m, 1.37673 rad²/s². The same answer as θ₀ written π/18."""
    import math

    degrees = _solved(tmp_path, TRIANGLE.replace("START", "10 deg"))
    radians = _solved(tmp_path, TRIANGLE.replace("START", "pi/18"))
    hand = 8 * math.sqrt(3) * 9.81 * (1 - math.cos(math.pi / 18)) / (5 * 0.3)
    assert degrees["values"]["there"]["rate_squared"]["theta"] == pytest.approx(hand, rel=1e-12)
    assert degrees["answers"] == radians["answers"]


def test_a_rate_and_a_length_with_units_are_read_in_si(tmp_path) -> None:
    """A bead on a smooth horizontal rod turning freely about a vertical axis, r from the
    axis, the rod's angle φ: at r = 20 cm, ṙ = 0, φ̇ = 120 rev/min (4π rad/s), Lagrange's
    r̈ = r φ̇² = 0.2 (4π)² = 31.5827 m/s² by hand (no force along the rod)."""
    import math

    text = """title: a bead on a freely turning rod
parameters: {m: mass}
values: {m: 100 g}
coordinates: [r, phi]
points:
  P: r * [cos(phi), sin(phi), 0]
bodies:
  bead: {shape: particle, mass: m, at: P}
questions:
  - eom: {at: {r: 20 cm, phi: 0, dot(r): 0, dot(phi): 120 rev/min}}
"""
    result = _solved(tmp_path, text)
    assert result["values"]["at"]["r"] == pytest.approx(0.2 * (4 * math.pi) ** 2, rel=1e-12)


@pytest.mark.parametrize("state, message", [
    ("from_rest: {theta: 2 kg}", "'2 kg' is a quantity in kg, not a coordinate's value"),
    ("at: {theta: 0, dot(theta): 3 m}", "'3 m' is a quantity in m, not a rate"),
])
def test_a_unit_of_another_kind_in_a_state_is_refused(tmp_path, state, message) -> None:
    result = _check(tmp_path, _rod(state))
    assert result.exit_code == 2 and message in result.output, result.output
