"""``rbdsolve grade``: its messages and exit codes, on small scenes.

A simple pendulum has λ = g/l, ω = √(g/l) (by hand: m l² θ̈ + m g l θ = 0). A solid
cylinder rolling inside a hollow one of radius R > r has ω² = 2g/(3(R − r)) (by hand:
T = ¾ m (R − r)² θ̇², V = −m g (R − r) cos θ): √(2g/3)/√(R − r) is that answer only
where R > r, which the file's assumption says — so the check must sample there.
"""

from __future__ import annotations

import re

import pytest
from click.testing import CliRunner

from rbdsolve.cli import main

from conftest import PROBLEMS, SIMPLE_PENDULUM

PENDULUM = "title: Pendulum\n" + SIMPLE_PENDULUM + "questions:\n  - modes: {about: {theta: 0}}\n"

ROLLING = """\
title: A cylinder rolling inside a hollow cylinder
parameters: {m: mass, r: radius of the cylinder, R: radius of the hollow, g: gravity}
assumptions: [R > r]
coordinates: [theta]
gravity: [0, -g]
bodies:
  cylinder: {shape: cylinder, mass: m, radius: r, height: 1}
contacts:
  C: {body: cylinder, rolls_on: {circle: {centre: [0, 0], radius: R, side: inside}}, along: theta}
questions:
  - modes: {about: {theta: 0}}
"""


@pytest.fixture(scope="module")
def pendulum(tmp_path_factory):
    path = tmp_path_factory.mktemp("grade") / "pendulum.yaml"
    path.write_text(PENDULUM, encoding="utf-8")
    return path


def grade(*args: str):
    return CliRunner().invoke(main, ["grade", *map(str, args)])


def test_every_answer_right_is_exit_0(pendulum) -> None:
    result = grade(pendulum, "-a", "omega1 = sqrt(g/l)", "-a", "lambda1 = g/l", "-a", "modes.motions[1] = oscillation")
    assert result.exit_code == 0, result.output
    assert result.stdout.splitlines() == ["modes.frequencies[1] = sqrt(g/l): right",
                                          "modes.eigenvalues[1] = g/l: right",
                                          "modes.motions[1] = oscillation: right"]


def test_an_answers_file_with_a_malformed_line(pendulum, tmp_path) -> None:
    answers = tmp_path / "mine.txt"
    answers.write_text("# my answers\nomega1 = sqrt(g/l)\nlambda1 g/l\n\nlambda1 = g*l\nomega1 = sqrt(g/L)\n"
                       "lambda1 = g + l\n", encoding="utf-8")
    result = grade(pendulum, answers)
    assert result.exit_code == 2
    right, equal_for, different = result.stdout.splitlines()
    assert right == "modes.frequencies[1] = sqrt(g/l): right"
    assert equal_for == "modes.eigenvalues[1] = g*l: wrong: equal only when l = 1"  # g l = g/l there
    found = re.fullmatch(r"modes.eigenvalues\[1\] = g \+ l: wrong: different at g = (\d+), l = (\d+) "
                         r"\(yours is ([\d.]+)\)", different)
    g, l, yours = (float(x) for x in found.groups())
    assert yours == g + l and g + l != g / l
    assert result.stderr.splitlines() == [
        f"{answers}:3:1: expected 'ANSWER = EXPRESSION', e.g. 'modes.frequencies[1] = sqrt(24*g/(25*r))'",
        f"{answers}:6:17: unknown symbol 'L' (did you mean 'l'?)"]


@pytest.mark.parametrize(("answer", "message"), [
    ("modes.frequencies[0] = 1", "indices count from 1, as in the printed solution"),
    ("omega = 1", "no answer is called 'omega'"),
    ("modes.shapes[1] = [1, 0]", "give one number or expression, not a vector: check a vector's entries one by one"),
    ("modes.growth_rates[1] = 0", "'modes.growth_rates[1]' has no value here"),
    ("omega1 = sqrt(g/x)", "unknown symbol 'x' (this problem's symbols are g, l, m, theta, and t)"),
    ("omega1 = __import__('os')", "is not allowed"),
    ("modes.motions[1] = wobbly", "'wobbly' is not one of: oscillation, growth, neutral"),
    (f"modes.frequencies[{'9' * 5000}] = 1", "an index of more than 6 digits; no answer has so many entries"),
    (f"omega{'9' * 5000} = 1", f"no answer is called 'omega{'9' * 55}… (5,005 characters)'"),
    (f"modes.frequencies[{'0' * 9}] = 1", "indices count from 1"),
])
def test_a_malformed_answer(pendulum, answer: str, message: str) -> None:
    result = grade(pendulum, "-a", answer)
    assert result.exit_code == 2
    assert message in result.stderr
    assert "Traceback" not in result.output


@pytest.mark.parametrize(("args", "message"), [
    ((), "give the answers to check"),
    (("-a", "omega1 = 1", "--answer", "x"), "expected 'ANSWER = EXPRESSION'"),
])
def test_usage(pendulum, args, message: str) -> None:
    result = grade(pendulum, *args)
    assert result.exit_code == 2 and message in result.stderr


def test_more_answers_than_the_limit_is_refused_where_the_first_past_it_is(pendulum, tmp_path) -> None:
    answers = tmp_path / "many.txt"
    answers.write_text("# six hundred\n\n" + "omega1 = 1\n" * 600, encoding="utf-8")
    result = grade(pendulum, answers)
    assert result.exit_code == 2
    assert result.stderr == f"{answers}:503:9: 600 answers to check; the limit is 500: check them in parts " \
                            "(answer 501 is here)\n"


def test_a_variants_table_takes_a_csv_not_expressions(tmp_path) -> None:
    table = tmp_path / "v.json"
    table.write_text('{"columns": ["modes.frequencies[1]"], "rows": []}', encoding="utf-8")
    assert "give the class's answers as a CSV" in grade(table, "-a", "omega1 = 1").stderr
    assert "give the class's answers after" in grade(table).stderr
    assert "no such file: nope.csv" in grade(table, "nope.csv").stderr


def test_the_assumptions_decide_where_answers_are_compared(tmp_path) -> None:
    path = tmp_path / "rolling.yaml"
    path.write_text(ROLLING, encoding="utf-8")
    answer = "omega1 = sqrt(2*g/3)/sqrt(R - r)"
    assert grade(path, "-a", answer).exit_code == 0
    path.write_text(ROLLING.replace("assumptions: [R > r]\n", ""), encoding="utf-8")
    assert grade(path, "-a", answer).exit_code == 0  # rolling inside implies R > r
    by_hand = ROLLING.replace("assumptions: [R > r]\n", "").split("contacts:")[0].replace(
        "height: 1}", "height: 1, at: '(R - r)*[sin(theta), -cos(theta)]', angle: -(R - r)*theta/r}")
    path.write_text(by_hand + "questions:\n  - modes: {about: {theta: 0}}\n", encoding="utf-8")
    result = grade(path, "-a", answer)
    assert result.exit_code == 1  # for R < r it is −1 times the answer: not the same expression


def test_help_has_examples() -> None:
    result = CliRunner().invoke(main, ["grade", "--help"])
    assert result.exit_code == 0
    assert "rbdsolve grade variants.json answers.csv" in result.output
    assert "--answer 'modes.frequencies[1] = sqrt(24*g/(25*r))'" in result.output


def test_a_number_for_a_file_with_values(tmp_path) -> None:
    """l = 2, g = 9.81: ω = √4.905 = 2.2147…, f = ω/2π = 0.35248…; a student's rounded
    number is held to --rtol (1 % by default)."""
    path = tmp_path / "pendulum.yaml"
    path.write_text(PENDULUM + "values: {m: 1, l: 2, g: 9.81}\n", encoding="utf-8")
    result = grade(path, "-a", "omega1 = 2.215", "-a", "omega1 = sqrt(g/l)", "-a", "omega1 = 0.3525",
                   "-a", "omega1 = 2.3", "-a", "lambda1 = 4.9")
    assert result.stdout.splitlines() == [
        "modes.frequencies[1] = 2.215: right (at the file's values, within the tolerance)",
        "modes.frequencies[1] = sqrt(g/l): right",
        "modes.frequencies[1] = 0.3525: wrong: off by a factor 2π (ω ↔ f)",
        "modes.frequencies[1] = 2.3: wrong: different at l = 2, g = 9.81 (yours is 2.3)",
        "modes.eigenvalues[1] = 4.9: right (at the file's values, within the tolerance)"]
    assert grade(path, "-a", "omega1 = 2.3", "--rtol", "0.05").exit_code == 0


def test_a_hostile_expression_is_not_a_verdict_nor_a_crash(pendulum, monkeypatch) -> None:
    """sympy's simplify expands sin(10**40*g) without end (cut at its time, here made
    short), and exp(exp(exp(exp(10)))) overflows mpmath: neither reaches the user."""
    from rbdsolve.teaching import compare

    monkeypatch.setattr(compare, "SIMPLIFY_SECONDS", 0.3)
    result = grade(pendulum, "-a", "omega1 = sin(10**40*g)", "-a", "omega1 = exp(exp(exp(exp(10))))",
                   "-a", "omega1 = sqrt(g/l)")
    assert result.exit_code == 1
    first, second, third = result.stdout.splitlines()
    assert first.startswith("modes.frequencies[1] = sin(10**40*g): wrong: different at")
    assert second.endswith("not decided: no admissible parameter values where both have a finite value")
    assert third.endswith("sqrt(g/l): right")


def test_points_where_the_answer_is_real_decide() -> None:
    """A bead on a hoop turning at Ω: ω² = g/R − Ω² about the lowest point (by hand,
    V_eff = −m g R cos θ − ½ m Ω² R² sin² θ). Past Ω² = g/R the frequency is imaginary,
    and there 1/√(R/(g − Ω²R)) is −1 times √(g − Ω²R)/√R: a right form all the same."""
    hoop = PROBLEMS / "frames" / "rotating-hoop-slow.yaml"
    result = grade(hoop, "-a", "omega1 = 1/sqrt(R/(g - Omega**2*R))", "-a", "lambda1 = g/R - Omega**2")
    assert result.exit_code == 0, result.output


@pytest.mark.parametrize(("answer", "message"), [
    ("equilibrium(theta=1).stability = stable", "no equilibrium is at theta=1"),
    ("equilibrium(x=0).stability = stable", "expected equilibrium(COORDINATE=VALUE, ...) with the coordinates theta"),
    ("equilibrium(theta=0).stability == stable", "expected 'ANSWER = EXPRESSION'"),
])
def test_an_equilibrium_named_by_a_place_it_is_not(tmp_path, answer: str, message: str) -> None:
    """A pendulum's equilibria are θ = 0 (stable) and θ = π (by hand: V = −m g l cos θ)."""
    path = tmp_path / "pendulum.yaml"
    path.write_text("title: Pendulum\n" + SIMPLE_PENDULUM + "questions: [equilibria]\n", encoding="utf-8")
    assert grade(path, "-a", "equilibrium(theta=0).stability = stable", "-a",
                 "equilibrium(theta=-pi).stability = unstable").exit_code == 0
    result = grade(path, "-a", answer)
    assert result.exit_code == 2 and message in result.stderr


def test_the_first_of_repeated_questions_may_be_numbered_one(pendulum) -> None:
    """The first question of a kind is 'modes', the second 'modes(2)'; 'modes(1)' is the
    first too, as a student counting would write it."""
    first = grade(pendulum, "-a", "modes(1).eigenvalues[1] = 2*g/l")
    plain = grade(pendulum, "-a", "modes.eigenvalues[1] = 2*g/l")
    assert first.exit_code == plain.exit_code != 2 and first.output == plain.output


@pytest.mark.skipif(not hasattr(__import__("os"), "mkfifo"), reason="no FIFOs here")
def test_a_fifo_of_answers_that_no_one_writes_is_not_waited_for(pendulum, tmp_path, monkeypatch) -> None:
    """Issue 39: 'grade p.yaml ans.fifo' with no writer blocked forever."""
    import os

    from rbdsolve.problem import yamlnodes

    monkeypatch.setattr(yamlnodes, "READ_SECONDS", 0.3)
    fifo = tmp_path / "ans.fifo"
    os.mkfifo(fifo)
    result = grade(pendulum, fifo)
    assert result.exit_code == 2
    assert result.stderr.startswith(f"{fifo}:1:1: no end of file within 0.3 s")
