"""The forces where the motion released from rest gets to (``reactions: {…, to: …}``):
a rod hinged at one end, from rest at φ₀, asked at φ. By hand (I_O = m l²/3): φ̇² =
3 g (cos φ − cos φ₀)/l, and R_Oy = (m g/4)(1 + 9 cos² φ) − (3/2) m g cos φ₀ cos φ …
at the vertical from the horizontal, 5 m g/2; a motion released at 30° never gets to
60° (φ̇² < 0 there), so no force is given there."""

from __future__ import annotations

import json

import pytest
from click.testing import CliRunner

from rbdsolve.cli import main

ROD = """\
parameters: {m: mass, l: length, g: gravity}
coordinates: [phi]
gravity: [0, -g]
points:
  O: [0, 0]
  G: l/2 * [sin(phi), -cos(phi)]
bodies:
  rod: {shape: rod, mass: m, length: l, at: G, angle: phi, axis: y}
questions:
  - reactions: {forces: [O], %s}
"""


def _result(tmp_path, question: str) -> dict:
    path = tmp_path / "rod.yaml"
    path.write_text(ROD % question, encoding="utf-8")
    result = CliRunner().invoke(main, ["solve", str(path), "--format", "json"])
    body = json.loads(result.stdout) if result.stdout.startswith("{") else {}
    return result, (body.get("results") or [None])[0]


def test_from_the_horizontal_the_hinge_carries_five_halves_of_the_weight_at_the_vertical(tmp_path) -> None:
    _, found = _result(tmp_path, "from_rest: {phi: pi/2}, to: {phi: 0}")
    assert found["answers"]["there"]["O"]["components"] == {"R_Ox": "0", "R_Oy": "5*g*m/2"}
    assert found["answers"]["there_reached"] is True


def test_the_rate_where_it_gets_to_has_its_number_and_unit(tmp_path) -> None:
    """φ̇² = 3 g (cos φ − cos φ₀)/l = 3 g/l at the vertical from the horizontal: with
    g = 9.81 m/s² and l = 0.6 m, 49.05 rad²/s² (a new user's trial: the number was
    missing, the expression alone printed)."""
    ROD_VALUES = ROD.replace("questions:", "values: {m: 2 kg, l: 60 cm, g: 9.81 m/s^2}\nquestions:")
    path = tmp_path / "rod.yaml"
    path.write_text(ROD_VALUES % "from_rest: {phi: pi/2}, to: {phi: 0}", encoding="utf-8")
    result = CliRunner().invoke(main, ["solve", str(path), "--format", "json"])
    found = json.loads(result.stdout)["results"][0]
    assert found["answers"]["there_rate_squared"] == {"phi": "3*g/l"}
    assert found["values"]["there_rate_squared"]["phi"] == pytest.approx(3 * 9.81 / 0.6, rel=1e-12)
    assert found["units"]["there_rate_squared"]["phi"] == "rad²/s²"


def test_a_configuration_the_motion_does_not_get_to_has_no_forces(tmp_path) -> None:
    # from rest at 30°: φ̇² = 3 g (cos φ − cos φ₀)/l < 0 at 60°
    _, found = _result(tmp_path, "from_rest: {phi: pi/6}, to: {phi: pi/3}")
    assert found["ok"] and found["answers"]["there"] is None and found["answers"]["there_reached"] is False
    assert any("does not get there" in s["text"] for s in found["steps"])


@pytest.mark.parametrize("question", ["to: {phi: 0}", "at: {phi: 0, dot(phi): 1}, to: {phi: 0}"])
def test_to_without_a_release_from_rest_is_bad_input(tmp_path, question) -> None:
    result, _ = _result(tmp_path, question)
    assert result.exit_code == 2 and "give 'from_rest: {q: VALUE}' with it" in result.output, result.output


def test_a_barrier_on_the_way_is_not_crossed(tmp_path) -> None:
    """An inverted rod on a torsion spring c = 4 N·m/rad (m = 1 kg, l = 1 m), released at
    θ = 1.4 rad: V(θ) = ½ m g l cos θ + ½ c θ², V(0) = 4.905 J > V(1.4) = 4.754 J, so it
    never crosses the top to θ = −1, though q̇² > 0 there (by hand)."""
    path = tmp_path / "barrier.yaml"
    path.write_text("""\
parameters: {m: mass, l: length, g: gravity, c: torsional stiffness}
values: {m: 1 kg, l: 1 m, g: 9.81 m/s^2, c: 4 N*m/rad}
coordinates:
  theta: {kind: angle, periodic: false}
gravity: [0, -g]
points:
  O: [0, 0]
  G: l/2 * [-sin(theta), cos(theta)]
bodies:
  rod: {shape: rod, mass: m, length: l, at: G, angle: theta, axis: y}
springs:
  pivot: {stiffness: c, angle: theta}
questions:
  - reactions: {forces: [O], from_rest: {theta: 1.4}, to: {theta: -1}}
""", encoding="utf-8")
    result = CliRunner().invoke(main, ["solve", str(path), "--format", "json"])
    answers = json.loads(result.stdout)["results"][0]["answers"]
    assert answers["there_reached"] is False and answers["there"] is None


def test_an_angle_a_whole_turn_on_is_the_same_place(tmp_path) -> None:
    # from the horizontal, φ = 2π is the bottom met the first time round (φ = 0): 5 m g/2
    _, found = _result(tmp_path, "from_rest: {phi: pi/2}, to: {phi: 2*pi}")
    assert found["answers"]["there_reached"] is True
    assert found["answers"]["there"]["O"]["components"] == {"R_Ox": "0", "R_Oy": "5*g*m/2"}


def test_released_at_an_equilibrium_it_stays_and_says_so(tmp_path) -> None:
    """Upright at φ = π the rod is at an equilibrium (φ̈ = −3 g sin φ/(2 l) = 0 there):
    released at rest it stays, though φ̇² = 3 g (cos φ + 1)/l = 3 g/l > 0 at φ = π/2 (a
    start displaced ever so slightly). Neither 'q̇² < 0 there' nor a turning back is why."""
    _, found = _result(tmp_path, "from_rest: {phi: pi}, to: {phi: pi/2}")
    assert found["answers"]["there_reached"] is False and found["answers"]["there"] is None
    notes = [s["text"] for s in found["steps"] if "no force is given" in s["text"]]
    assert len(notes) == 1 and notes[0].startswith("Released at rest at an equilibrium"), notes
