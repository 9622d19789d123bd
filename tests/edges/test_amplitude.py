"""Issue 8, case 7: the modes' check at finite amplitude (``check_amplitudes``).

Independent references: a simple pendulum of length l released from rest at θ₀ has the
period T = 4 K(k²) √(l/g), k = sin(θ₀/2) (K the complete elliptic integral of the
first kind; scipy.special.ellipk takes m = k²), so ω/ω_lin = π / (2 K(sin²(θ₀/2))).
The seed's two rods (problems/sg2150-2015-10-29/p1-two-rods.yaml) have λ₁ = 24 g/(25 r)
and λ₂ = 2 g/r (the exam's worked solution, in its .expected.yaml).
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest
from scipy.special import ellipk

from rbdsolve.errors import InputError
from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.render.json import render_report
from rbdsolve.solvers import Options, RouteChoice, solve_file, solve_problem

from conftest import SIMPLE_PENDULUM

ROOT = Path(__file__).resolve().parents[2]
PENDULUM = SIMPLE_PENDULUM + """\
values: {m: 1, l: 1/2, g: 9.81}
questions:
  - modes: {about: {theta: 0}, check_amplitudes: [0.01, 0.5, 2.0, 3.2]}
"""
TOLERANCE = 1e-8  # relative, measured ω against the elliptic-integral one (rtol 1e-11 integration)


def _modes(text: str, route: RouteChoice = RouteChoice.EXACT):
    report = solve_file(load_text(text, "scene.yaml"), Options(route=route, budget=30))
    return report, report.solutions[0]


@pytest.mark.parametrize("route", [RouteChoice.EXACT, RouteChoice.NUMERIC])
def test_the_pendulum_matches_the_elliptic_integral(route: RouteChoice) -> None:
    report, modes = _modes(PENDULUM, route)
    runs = modes.answers.amplitude_check.runs
    omega_lin = math.sqrt(9.81 / 0.5)
    for run, theta0 in zip(runs, (0.01, 0.5, 2.0)):
        expected = omega_lin * math.pi / (2 * ellipk(math.sin(theta0 / 2) ** 2))
        assert run.amplitude == theta0 and run.coordinate == "theta"
        assert abs(run.linear_frequency - omega_lin) <= 1e-12 * omega_lin
        assert abs(run.measured_frequency - expected) <= TOLERANCE * expected
        assert abs(run.drift - (expected / omega_lin - 1)) <= TOLERANCE
        assert run.spread < 1e-6 and run.energy_error < 1e-8
    # drifts: −6.25e-6 at 0.01 (1 − θ₀²/16), −1.56 % at 0.5, −24.75 % at 2.0: a warning past 1 %
    assert [w for w in modes.warnings if "0.01 of theta" in w] == []
    assert any("amplitude 0.5 of theta" in w and "-1.56%" in w for w in modes.warnings)
    assert any("amplitude 2 of theta" in w and "-24.75%" in w for w in modes.warnings)
    # past π the pendulum goes over the top: no oscillation about θ = 0, said, with nulls
    over = runs[3]
    assert over.measured_frequency is None and over.drift is None
    assert any("amplitude 3.2 of theta does not oscillate" in w for w in modes.warnings)
    line = json.loads(render_report(report), parse_constant=lambda c: pytest.fail(f"non-strict JSON: {c}"))
    assert line["results"][0]["answers"]["amplitude_check"]["runs"][3]["drift"] is None


def test_the_two_rods_at_small_amplitude_match_the_linear_modes() -> None:
    text = (ROOT / "problems/sg2150-2015-10-29/p1-two-rods.yaml").read_text().replace(
        "  - modes: {about: {theta: 0, phi: 0}}", "  - modes: {about: {theta: 0, phi: 0}, check_amplitudes: [0.01]}")
    assert "check_amplitudes" in text
    from fractions import Fraction

    model = build_model(load_text(text, "p1.yaml")).with_values({"m": Fraction(1), "r": Fraction(1, 2),
                                                                 "g": Fraction(981, 100)})
    report = solve_problem(model, Options(budget=30))
    modes = next(s for s in report.solutions if s.question == "modes")
    g, r = 9.81, 0.5
    linear = [math.sqrt(24 * g / (25 * r)), math.sqrt(2 * g / r)]
    runs = modes.answers.amplitude_check.runs
    assert [x.mode for x in runs] == [1, 2]
    for run, omega in zip(runs, linear):
        assert abs(run.linear_frequency - omega) <= 1e-12 * omega
        assert abs(run.measured_frequency / omega - 1) <= 1e-4


def test_without_every_value_the_check_is_refused_with_a_warning() -> None:
    text = PENDULUM.replace("values: {m: 1, l: 1/2, g: 9.81}\n", "")
    _, modes = _modes(text)
    assert modes.solved and modes.answers.amplitude_check is None
    assert any("check_amplitudes: not run" in w and "give m, l, g" in w for w in modes.warnings)


@pytest.mark.parametrize("option, token, message", [
    ("check_amplitudes: [0.1, -1]", "-1", "questions[0].modes.check_amplitudes[1]: an amplitude must be positive, "
                                          "found -1"),
    ("check_amplitudes: []", "[]", "questions[0].modes.check_amplitudes: expected a list of amplitudes"),
    ("check_amplitudes: 0.5", "0.5", "questions[0].modes.check_amplitudes: expected a list of amplitudes"),
    ("check_amplitudes: [a]", "a]", "questions[0].modes.check_amplitudes[0]: expected a number, found 'a'"),
    ("check_amplitudes: [1, 2, 3, 4, 5, 6, 7, 8, 9]", "[1,", "questions[0].modes.check_amplitudes: 9 amplitudes; "
                                                              "the limit is 8"),
    ("check_amplitude: [1]", "check_amplitude:", "questions[0].modes.check_amplitude: unknown key 'check_amplitude' "
                                                 "in question 'modes' (did you mean 'check_amplitudes'?)"),
])
def test_the_option_is_checked_at_load_time(option: str, token: str, message: str) -> None:
    text = "title: p\n" + PENDULUM.replace("check_amplitudes: [0.01, 0.5, 2.0, 3.2]", option)
    line = text.splitlines()[10]
    assert option in line
    with pytest.raises(InputError) as caught:
        load_text(text, "p.yaml")
    assert str(caught.value).startswith(f"p.yaml:11:{line.index(token) + 1}: {message}")


def test_the_option_is_refused_with_a_frame() -> None:
    text = PENDULUM.replace("questions:", "frames:\n  hoop: {axis: y, rate: 1}\nquestions:").replace(
        "{about: {theta: 0}, check", "{about: {theta: 0}, frame: hoop, check")
    with pytest.raises(InputError, match="'check_amplitudes' simulates the scene's own equations; it is not "
                                         "available with 'frame'"):
        load_text(text, "p.yaml")
