"""``rbdsolve solve`` on many files: folders, globs, standard input, --jobs, the summary
table on standard error, the worst exit code."""

from __future__ import annotations

import json

from click.testing import CliRunner

from rbdsolve.cli import main

from conftest import PROBLEMS, SEED

PENDULUM = PROBLEMS / "examples" / "pendulum.yaml"
BAD = PROBLEMS.parent / "tests" / "problem" / "bad" / "001-yaml-unclosed-flow-mapping.yaml"


def run(*args: str, input: str | None = None):
    return CliRunner().invoke(main, [str(a) for a in args], input=input)


def _without_seconds(line: str) -> dict:
    body = json.loads(line)
    for result in body.get("results", []):
        result.pop("seconds")
    return body


def test_jobs_give_the_same_lines_in_file_order() -> None:
    one = run("solve", SEED, "-f", "json", "--quiet")
    two = run("solve", SEED, "-f", "json", "--quiet", "--jobs", "2")
    assert one.exit_code == two.exit_code == 0, two.output
    assert [_without_seconds(x) for x in two.stdout.splitlines()] == \
        [_without_seconds(x) for x in one.stdout.splitlines()]
    assert [json.loads(x)["file"].rsplit("/", 1)[1][:2] for x in two.stdout.splitlines()] == \
        ["p1", "p2", "p3", "p4", "p5", "p6"]


def test_a_quoted_glob_is_expanded_in_path_order() -> None:
    result = run("check", f"{SEED}/p[21]-*.yaml")
    assert result.exit_code == 0, result.output
    assert [line.split("/")[-1].split(":")[0] for line in result.stdout.splitlines()] == \
        ["p1-two-rods.yaml", "p2-rod-impact.yaml"]
    nothing = run("check", f"{SEED}/q*.yaml")
    assert nothing.exit_code == 2 and "no problem files match this pattern" in nothing.output


def test_a_problem_on_standard_input() -> None:
    result = run("solve", "-", "-f", "json", input=PENDULUM.read_text(encoding="utf-8"))
    assert result.exit_code == 0, result.output
    assert json.loads(result.stdout)["file"] == "<stdin>"
    broken = run("solve", "-", input="title: x\nparameters: {m: mass\n")
    assert broken.exit_code == 2 and broken.output.startswith("<stdin>:")


def test_json_lines_stay_clean_and_the_summary_goes_to_stderr() -> None:
    result = run("solve", PENDULUM, BAD, "-f", "json")
    assert result.exit_code == 2  # the worst of 0 and 2
    lines = [json.loads(x) for x in result.stdout.splitlines()]
    assert [x["file"].rsplit("/", 1)[1] for x in lines] == [PENDULUM.name, BAD.name]
    assert lines[1]["ok"] is False and lines[1]["error"]["line"] == 9
    assert "Summary" in result.stderr and "bad input" in result.stderr and "solved" in result.stderr
    assert "Summary" not in result.stdout


def test_quiet_has_no_summary_but_still_says_errors() -> None:
    result = run("solve", PENDULUM, BAD, "--quiet")
    assert result.exit_code == 2
    assert "Summary" not in result.stderr and "YAML syntax error" in result.stderr


def test_the_exit_code_is_the_worst_file(tmp_path) -> None:
    unanswerable = tmp_path / "no-equilibrium.yaml"  # ∂V/∂y = m g (tanh y + 2) > 0, which no route
    unanswerable.write_text(  # proves rootless (tanh y is transcendental; a search covers a box): exit code 1
        "title: falling\nparameters: {m: mass, g: gravity}\ncoordinates: [y]\ngravity: [0, -g]\n"
        "bodies:\n  b: {shape: particle, mass: m, at: [0, log(cosh(y)) + 2*y]}\nquestions: [equilibria]\n",
        encoding="utf-8")
    assert run("solve", PENDULUM, unanswerable, "--quiet").exit_code == 1
    assert run("solve", PENDULUM, unanswerable, BAD, "--quiet", "--jobs", "2").exit_code == 2


def test_standard_input_is_read_once() -> None:
    result = run("solve", "-", "-", input="")
    assert result.exit_code == 2 and "given more than once" in result.output
