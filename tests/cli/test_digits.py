"""``solve --digits``: significant digits in text, full precision in JSON; the numeric
route's accuracy (conditioning, bounds) in its own block under the answers."""

from __future__ import annotations

import json
import math

import pytest
from click.testing import CliRunner

from rbdsolve.cli import main

from conftest import SIMPLE_PENDULUM

# ω² = g/l = 9.81/0.7 for a simple pendulum
SCENE = "title: Pendulum\n" + SIMPLE_PENDULUM + "values: {m: 1, l: 0.7, g: 9.81}\nquestions:\n  - modes: {about: {theta: 0}}\n"
LAMBDA = 9.81 / 0.7


@pytest.fixture(scope="module")
def scene(tmp_path_factory):
    path = tmp_path_factory.mktemp("digits") / "pendulum.yaml"
    path.write_text(SCENE, encoding="utf-8")
    return str(path)


def solve(*args):
    result = CliRunner().invoke(main, ["solve", *args, "--route", "numeric"])
    assert result.exit_code == 0, result.output
    return result.stdout


def test_six_digits_by_default_and_as_asked(scene) -> None:
    assert f"λ₁ = {LAMBDA:.6g}" in solve(scene)
    assert f"λ₁ = {LAMBDA:.3g}" in solve(scene, "--digits", "3")
    assert f"λ₁ = {LAMBDA:.10g} 1/s²" in solve(scene, "--digits", "10")


def test_json_keeps_full_precision(scene) -> None:
    line = json.loads(solve(scene, "-f", "json", "--digits", "2"))
    assert math.isclose(line["results"][0]["answers"]["eigenvalues"][0], LAMBDA, rel_tol=1e-14)


def test_digits_out_of_range_is_a_usage_error(scene) -> None:
    result = CliRunner().invoke(main, ["solve", scene, "--digits", "0"])
    assert result.exit_code == 2 and "--digits" in result.output


def test_accuracy_is_a_block_under_the_answers(scene) -> None:
    out = solve(scene)
    answers, _, accuracy = out.partition("Accuracy:")
    assert "Numeric values:" in answers and "λ₁ =" in answers
    assert "Conditioning:" not in answers and "relative_errors" not in answers
    assert "Conditioning about θ = 0: κ₂(M) = 1" in accuracy and "relative_errors = [" in accuracy


def test_json_marks_the_accuracy_steps(scene) -> None:
    steps = json.loads(solve(scene, "-f", "json"))["results"][0]["steps"]
    marked = [s for s in steps if s.get("accuracy")]
    assert len(marked) == 1 and marked[0]["text"].startswith("Conditioning about θ = 0:")


def test_every_number_in_the_steps_holds_the_digits_asked(scene) -> None:
    """Numbers are kept to 15 digits in the steps, so 12 digits asked are 12 true ones:
    λ = g/l = 14.0142857142857…"""
    assert f"λ₁ = {LAMBDA:.12g}" in solve(scene, "--digits", "12")


@pytest.mark.parametrize("digits", [3, 10])
def test_the_period_beside_a_frequency_holds_the_digits_asked(scene, digits: int) -> None:
    """The period 2π/ω, ω = √(g/l), is printed as the frequency is (it kept 6 digits)."""
    omega = math.sqrt(LAMBDA)
    assert f"ω₁ = {omega:.{digits}g} rad/s (period {2 * math.pi / omega:.{digits}g} s)" in solve(
        scene, "--digits", str(digits))
