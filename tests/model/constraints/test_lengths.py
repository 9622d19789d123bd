"""Impossible geometry (issue 39, item 3; model/constraints/lengths.py): a circle a body rolls on,
a string's winding radius, a hanging string's length and a body's dimensions must be
positive. Each case is refused with exit code 2 and one line located at the length,
naming it — decided by the parameters' signs, by the file's values, or by its
assumptions; a length nothing decides is assumed positive, so that values given later
which break it are refused too."""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner

from rbdsolve.cli import main
from rbdsolve.errors import InputError
from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text

from conftest import PROBLEMS

RING_ON_DRUM = (PROBLEMS / "contacts" / "ring-on-drum.yaml").read_text(encoding="utf-8")
YOYO = (PROBLEMS / "contacts" / "yo-yo.yaml").read_text(encoding="utf-8")
HANGING = (PROBLEMS / "contacts" / "cylinder-pulley-block.yaml").read_text(encoding="utf-8")
CIRCLE = "rolls_on: {circle: {centre: [0, 0], radius: R, side: outside}}"

# (the scene, its text changed, where the length starts (line, column), the message's end)
CASES = {
    "drum radius -R": (RING_ON_DRUM, (CIRCLE, CIRCLE.replace("R,", "-R,")), (18, 63),
                       "contact 'C': the radius of the circle it rolls on must be positive, found -R, zero or "
                       "negative for any values of the parameters"),
    "drum radius 0": (RING_ON_DRUM, (CIRCLE, CIRCLE.replace("R,", "0,")), (18, 63),
                      "contact 'C': the radius of the circle it rolls on must be positive, found 0"),
    "drum radius -1": (RING_ON_DRUM, (CIRCLE, CIRCLE.replace("R,", "-1,")), (18, 63),
                       "contact 'C': the radius of the circle it rolls on must be positive, found -1"),
    "inside, radius -R": (RING_ON_DRUM, (CIRCLE, CIRCLE.replace("R,", "-R,").replace("outside", "inside")),
                          (18, 63), "contact 'C': the radius of the circle it rolls on must be positive, found -R"),
    "string at radius -r": (YOYO, ("direction: [0, -1]}", "direction: [0, -1], radius: -r}"), (20, 69),
                            "contact 'S': the radius the string is wound at must be positive, found -r"),
    "hanging length 0": (HANGING, ("over: P}", "over: P, length: 0}"), (27, 85),
                         "contact 'S': the hanging length of the string must be positive, found 0"),
    "hanging length -1": (HANGING, ("over: P}", "over: P, length: -1}"), (27, 85),
                          "contact 'S': the hanging length of the string must be positive, found -1"),
    "hanging length -r": (HANGING, ("over: P}", "over: P, length: -r}"), (27, 85),
                          "contact 'S': the hanging length of the string must be positive, found -r"),
    "hanging length -1e300": (HANGING, ("over: P}", "over: P, length: -1e300}"), (27, 85),
                              "contact 'S': the hanging length of the string must be positive, found -1e300"),
    "hanging radius -r": (HANGING, ("over: P}", "over: P, radius: -r}"), (27, 85),
                          "contact 'S': the radius the string is wound at must be positive, found -r"),
}


def solved(tmp_path: Path, text: str, *options: str):
    path = tmp_path / "scene.yaml"
    path.write_text(text, encoding="utf-8")
    return path, CliRunner().invoke(main, ["solve", str(path), *options])


@pytest.mark.parametrize("case", list(CASES))
def test_a_length_that_cannot_be_is_refused_where_it_is_written(tmp_path, case: str) -> None:
    scene, (old, new), (line, column), message = CASES[case]
    assert old in scene
    path, result = solved(tmp_path, scene.replace(old, new))
    assert result.exit_code == 2, result.output
    assert result.stderr.startswith(f"{path}:{line}:{column}: ")
    assert message in result.stderr and len(result.stderr.splitlines()) == 1
    found = message.rsplit("found ", 1)[1].split(",")[0]
    assert scene.replace(old, new).splitlines()[line - 1][column - 1:].startswith(found)  # located at the length


def test_a_drum_body_of_negative_radius_under_a_rolling_ring_is_refused(tmp_path) -> None:
    scene = RING_ON_DRUM.replace("bodies:\n", "bodies:\n  drum: {shape: disk, mass: m, radius: -R, at: [0, 0]}\n")
    scene = scene.replace(CIRCLE, "rolls_on: {body: drum, side: outside}")
    path, result = solved(tmp_path, scene)
    assert result.exit_code == 2
    assert result.stderr == f"{path}:16:40: bodies.drum.radius: a radius must not be zero or negative, found -R\n"


def test_the_values_decide() -> None:
    scene = RING_ON_DRUM.replace(CIRCLE, CIRCLE.replace("R,", "R - 2,")) + "values: {R: 1}\n"
    with pytest.raises(InputError, match=r"must be positive, found R - 2, which is -1 at the values given \(R = 1\)"):
        build_model(load_text(scene, "s.yaml"))


def test_the_assumptions_decide() -> None:
    scene = RING_ON_DRUM.replace(CIRCLE, CIRCLE.replace("R,", "R - r,")) + "assumptions: [R < r]\n"
    with pytest.raises(InputError, match=r"^s.yaml:18:63: .*found R - r, zero or negative under the file's assumptions"):
        build_model(load_text(scene, "s.yaml"))
    body = RING_ON_DRUM.replace("radius: r}", "radius: R - r}") + "assumptions: [R < r]\n"
    with pytest.raises(InputError, match=r"^s.yaml:16:40: bodies.ring.radius: body 'ring': its radius must be "
                                         r"positive, found R - r, zero or negative under the file's assumptions"):
        build_model(load_text(body, "s.yaml"))


def test_a_length_nothing_decides_is_assumed_and_values_that_break_it_are_refused(tmp_path) -> None:
    """R − r outside (R, r positive, nothing said): solved, as if R > r were written;
    --set values with R < r are refused, as the same values in the file are (the model is
    built from them: the error names the circle's radius in the file)."""
    scene = RING_ON_DRUM.replace(CIRCLE, CIRCLE.replace("R,", "R - r,"))
    model = build_model(load_text(scene, "s.yaml"))
    assert [a.named for a in model.assumptions] == [
        "'R − r > 0' (implied by contact 'C': the radius of the circle it rolls on is positive)"]
    path, result = solved(tmp_path, scene, "--set", "R=1", "--set", "r=2", "--set", "m=1", "--set", "g=9.81")
    assert result.exit_code == 2
    assert ":18:63: contacts.C.rolls_on.circle.radius: " in result.stderr
    assert "must be positive, found R - r, which is -1 at the values given (R = 1, r = 2)" in result.stderr


def test_a_body_dimension_at_values_given_later_is_refused(tmp_path) -> None:
    scene = RING_ON_DRUM.replace("  r: radius of the ring\n", "  r: {description: radius of the ring, positive: false}\n")
    path, result = solved(tmp_path, scene, "--set", "r=-1")
    assert result.exit_code == 2
    assert "a radius must not be zero or negative, found r at the values given (r = -1)" in result.stderr
