"""An angle given as a bare number past a full turn is read in radians, as every bare
angle is, and that is said: an exam's `alpha: 30` (an incline of 30°) was taken as 30 rad
without a word (a new user's trial). Where the number is an angle is decided from the
scene: a term of a sine's or cosine's argument (an incline's line, `angle: -alpha`), an
angle coordinate's value in a state (`from_rest: {theta: theta0}`), or such a state's
own number. Not an angle: Ω in sin(Ω t), a stiffness, a mass; nor a value with its unit.
"""

from __future__ import annotations

import pytest

from conftest import DISK_IN_TRACK, PROBLEMS
from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.solvers import solve_problem

RELEASED = DISK_IN_TRACK.replace("[m, r, R, g]", "[m, r, R, g, theta0]") + """\
values: {m: 1, r: 0.08, R: 0.5, g: 9.81, theta0: VALUE}
questions:
  - reactions: {forces: [C], from_rest: {theta: START}}
"""


def _warnings(text: str) -> list[str]:
    report = solve_problem(build_model(load_text(text, "scene.yaml")))
    return [w for solution in report.solutions for w in solution.warnings if "radians" in w]


def test_a_release_angle_given_as_a_bare_40_is_said() -> None:
    (said,) = _warnings(RELEASED.replace("VALUE", "40").replace("START", "theta0"))
    assert said == ("parameter 'theta0', an angle, is given as 40, read in radians (40 rad is 2292°); "
                    "for degrees write '40 deg'")


def test_a_state_s_own_bare_number_is_said_at_its_place() -> None:
    (said,) = _warnings(RELEASED.replace("VALUE", "1").replace("START", "100"))
    assert said.startswith("scene.yaml:") and "questions[0].reactions.from_rest.theta: the angle is given as 100" in said


@pytest.mark.parametrize("value, start", [("40 deg", "theta0"), ("pi/3", "theta0"), ("1", "2 rad"), ("1", "60 deg"),
                                          ("6", "theta0")])
def test_an_angle_with_its_unit_or_within_a_turn_is_not(value: str, start: str) -> None:
    assert _warnings(RELEASED.replace("VALUE", value).replace("START", start)) == []


def test_an_incline_s_angle_in_its_line_is_one() -> None:
    text = (PROBLEMS / "forces" / "incline-30-deg.yaml").read_text(encoding="utf-8").replace("alpha: 30 deg", "alpha: 30")
    (said,) = _warnings(text)
    assert said.startswith("parameter 'alpha', an angle, is given as 30") and "1719°" in said


def test_a_rate_inside_a_sine_times_t_a_stiffness_and_a_mass_are_not() -> None:
    hoop = (PROBLEMS / "frames" / "rotating-hoop-fast.yaml").read_text(encoding="utf-8")
    assert _warnings(hoop.replace("Omega: 5 rad/s", "Omega: 10").replace("m: 1 kg", "m: 12")) == []
