"""Issue 28, findings 3 and 11: values that make a configuration complex, and values
that overflow floating point. Each is a clear refusal or a warning, never exit code 3
nor a silent null, and the message names the cause this scene can have."""

from __future__ import annotations

import json

import pytest
from click.testing import CliRunner

from rbdsolve.cli import main

from conftest import SIMPLE_PENDULUM


def solve(tmp_path, text: str, *args: str):
    path = tmp_path / "p.yaml"
    path.write_text(text, encoding="utf-8")
    result = CliRunner().invoke(main, ["solve", str(path), "-f", "json", *args])
    assert "internal error" not in result.output and "Traceback" not in result.output, result.output
    return result, json.loads(result.stdout)


@pytest.mark.parametrize("route", ["auto", "numeric"])
def test_an_about_point_that_is_complex_at_the_values_is_refused(tmp_path, route: str) -> None:
    # acos(g/l) with g/l = 10 has no real value: the point does not exist at these values.
    text = SIMPLE_PENDULUM + "values: {m: 1, l: 1, g: 10}\nquestions:\n  - modes: {about: {theta: acos(g/l)}}\n"
    result, line = solve(tmp_path, text, "--route", route)
    assert result.exit_code == 1
    error = line["results"][0]["error"]
    assert "is not a real number at the parameter values" in error or "not an equilibrium" in error
    if route == "numeric":
        assert ":10:28: questions[0].modes.about.theta: theta = acos(g/l) is not a real number" in error


def test_an_answer_that_overflows_gets_a_warning_not_a_silent_null(tmp_path) -> None:
    # M = m³ l² = 1e900 and K = m³ g l: past the largest float (1.8e308); ω² = g/l = 10 is fine.
    text = SIMPLE_PENDULUM.replace("mass: m,", "mass: m**3,") + \
        "values: {m: 1e300, l: 1, g: 10}\nquestions:\n  - modes: {about: {theta: 0}}\n"
    result, line = solve(tmp_path, text)
    modes = line["results"][0]
    assert result.exit_code == 0 and modes["values"]["M"] == [[None]] and modes["values"]["eigenvalues"] == [10.0]
    assert any("no numeric value for M[1][1], K[1][1]" in w and "overflow" in w for w in modes["warnings"])


@pytest.mark.parametrize("values", ["{m: 1e300, l: 1, g: 10}", "{m: 1, l: 1e300, g: 10}"])
def test_the_numeric_route_blames_the_overflow_not_a_spring(tmp_path, values: str) -> None:
    mass = "m**3" if values.startswith("{m: 1e300") else "m"
    text = SIMPLE_PENDULUM.replace("mass: m,", f"mass: {mass},") + \
        f"values: {values}\nquestions:\n  - modes: {{about: {{theta: 0}}}}\n"
    result, line = solve(tmp_path, text, "--route", "numeric")
    error = line["results"][0]["error"]
    assert result.exit_code == 1 and "overflow" in error and "1e+300" in error
    assert "spring" not in error  # the scene has none
