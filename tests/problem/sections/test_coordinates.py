"""The ``coordinates:`` options: kind, periodic, range; each mistake located."""

from __future__ import annotations

import pytest
from click.testing import CliRunner

from conftest import PROBLEMS
from rbdsolve.cli import main
from rbdsolve.errors import InputError
from rbdsolve.problem import load_text
from rbdsolve.problem.schema import CoordinateKind

SCENE = """\
parameters: {{m: mass, l: length, g: gravity}}
coordinates:
  x: {spec}
gravity: [0, -g]
points:
  P: [x, 0]
bodies:
  bead: {{shape: particle, mass: m, at: P}}
questions: [equilibria]
"""


def test_a_declared_range_and_periodic_are_read() -> None:
    problem = load_text(SCENE.format(spec="{kind: angle, periodic: false, range: [-2*pi, 2*pi]}"), "c.yaml")
    (c,) = problem.coordinates
    assert c.kind is CoordinateKind.ANGLE and c.periodic is False
    assert [end.text for end in c.range] == ["-2*pi", "2*pi"]


@pytest.mark.parametrize("spec, words", [
    ("{kind: angle, range: [0, 1]}", "c.yaml:3:27: coordinates.x.range: a periodic angle is searched over one turn"),
    ("{kind: length, periodic: false}", "c.yaml:3:31: coordinates.x.periodic: 'periodic' is for an angle"),
    ("{kind: length, range: [2, 1]}", "coordinates.x.range: the range of 'x' is empty: its low end 2 is not below"),
    ("{kind: length, range: [0]}", "coordinates.x.range: a range is [low, high], two constants"),
    ("{kind: length, range: [0, x]}", "'x' cannot appear here: the range of 'x' must be constant"),
    ("{kind: lenght}", "coordinates.x.kind: unknown coordinate kind 'lenght' (expected angle, length or auto) (did you mean"),
    ("{kind: length, rang: [0, 1]}", "coordinates.x.rang: unknown key 'rang' in coordinate 'x' (did you mean 'range'?)"),
    ("{kind: angle, periodic: maybe}", "coordinates.x.periodic: expected true or false, found 'maybe'"),
])
def test_bad_coordinate_options(spec: str, words: str) -> None:
    with pytest.raises(InputError) as caught:
        load_text(SCENE.format(spec=spec), "c.yaml")
    assert words in str(caught.value)


def test_an_angle_a_spring_winds_up_is_refused_located(tmp_path) -> None:
    """Declared a (periodic) angle, but a torsional spring holds θ bare: V does not repeat
    after a turn. Found when the model is built (solve), exit 2, at the declaration."""
    text = (PROBLEMS / "edges" / "inverted-rod-stiff-spring.yaml").read_text(encoding="utf-8")
    path = tmp_path / "rod.yaml"
    path.write_text(text.replace("  theta: {kind: angle, periodic: false}", "  theta: angle"))
    result = CliRunner().invoke(main, ["solve", str(path)])
    assert result.exit_code == 2, result.output
    assert (f"{path}:15:3: coordinates.theta: 'theta' is declared an angle, which repeats after a turn, but "
            "spring 'pivot' holds it outside sin and cos") in result.output
    assert "declare 'theta: {kind: angle, periodic: false}', with a 'range' for the search" in result.output


def test_auto_is_a_kind_as_the_manual_says() -> None:
    """docs/format.md: "Without a kind (or with `auto`) rbdsolve decides" — `auto` was
    refused as an unknown kind (a new user's `coordinates: {s: auto}`)."""
    text = ("parameters: {m: mass, g: gravity}\ncoordinates: {s: auto}\ngravity: [0, -g]\n"
            "bodies:\n  b: {shape: particle, mass: m, at: [s, 0]}\nquestions: [eom]\n")
    (c,) = load_text(text, "c.yaml").coordinates
    assert c.kind is CoordinateKind.AUTO
