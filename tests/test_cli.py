"""The command line, through click's CliRunner: exit codes, formats and messages."""

from __future__ import annotations

import json

import pytest
from click.testing import CliRunner

from rbdsolve.cli import main

from conftest import PROBLEMS, same

P1 = str(PROBLEMS / "sg2150-2015-10-29" / "p1-two-rods.yaml")
PENDULUM = str(PROBLEMS / "examples" / "pendulum.yaml")


def run(*args: str, input: str | None = None):
    return CliRunner().invoke(main, list(args), input=input)


def test_solve_terminal_reads_like_the_exam() -> None:
    result = run("solve", P1)
    assert result.exit_code == 0, result.output
    out = result.output
    assert "T = T₁ + T₂ = m r² [7/8 θ̇² + 1/4 cos(φ − θ) θ̇ φ̇ + 1/6 φ̇²]" in out
    assert "M = m r² [[7/4, 1/4], [1/4, 1/3]]" in out
    assert "⇒ 25/48 μ² − 37/24 μ + 1 = 0" in out
    assert "λ₁ = 24 g/(25 r)" in out and "λ₂ = 2 g/r" in out


def test_impact_reads_like_the_exam() -> None:
    result = run("solve", str(PROBLEMS / "sg2150-2015-10-29" / "p2-rod-impact.yaml"))
    assert result.exit_code == 0, result.output
    out = result.output
    assert "v_G1 = (ẋ − 1/2 l φ̇) eₓ" in out and "v_AB" not in out  # the rod's centre, by its point
    assert "m [2 ẋ_f − 3/2 l φ̇_f] = m v₀" in out
    assert "ẋ_f = 7/5 v₀" in out and "φ̇_f = 6 v₀/(5 l)" in out
    assert "v_G1 = 4/5 v₀ eₓ" in out and "e_G1 = 4/5" in out


def test_restitution_set_outside_zero_one_exits_2() -> None:
    result = run("solve", str(PROBLEMS / "impact" / "ball-hits-pinned-rod.yaml"), "--set", "e=3/2")
    assert result.exit_code == 2
    assert "ball-hits-pinned-rod.yaml:24:37:" in result.output
    assert "questions[0].impact.collisions.A.restitution: a coefficient of restitution is between 0 and 1" \
        in result.output


def test_solve_json_lines_contract() -> None:
    result = run("solve", P1, PENDULUM, "--format", "json")
    assert result.exit_code == 0
    lines = result.stdout.splitlines()  # the summary table is on standard error
    assert len(lines) == 2 and "Summary" in result.stderr
    first = json.loads(lines[0])
    assert {"file", "title", "model", "results"} <= first.keys()
    assert first["model"]["coordinates"] == ["theta(t)", "phi(t)"]
    modes = first["results"][2]
    assert {"question", "route", "seconds", "answers", "values", "steps"} <= modes.keys()
    assert modes["route"] == "exact"
    assert [same(a, b) for a, b in zip(modes["answers"]["eigenvalues"], ["24*g/(25*r)", "2*g/r"])] == [True, True]


def test_folder_is_solved_in_file_order() -> None:
    result = run("solve", str(PROBLEMS / "examples"), "-f", "json")
    assert result.exit_code == 0
    files = [json.loads(line)["file"].rsplit("/", 1)[1] for line in result.stdout.splitlines()]
    on_disk = sorted(p.name for p in (PROBLEMS / "examples").glob("*.yaml"))
    assert files == [name for name in on_disk if not name.endswith(".expected.yaml")]
    assert "pendulum.yaml" in files and len(files) >= 5


def test_set_gives_numeric_values() -> None:
    result = run("solve", P1, "-f", "json", "--set", "m=1", "--set", "r=0.5", "--set", "g=9.81")
    assert result.exit_code == 0
    modes = json.loads(result.stdout)["results"][2]
    assert modes["values"]["eigenvalues"] == pytest.approx([24 * 9.81 / 12.5, 2 * 9.81 / 0.5], rel=1e-12)
    assert modes["values"]["frequencies"][1] == pytest.approx((2 * 9.81 / 0.5) ** 0.5, rel=1e-12)


@pytest.mark.parametrize(
    "args, words",
    [
        (("--set", "M=1"), "has no parameter 'M' (did you mean 'm'?)"),
        (("--set", "m"), "--set expects NAME=VALUE"),
        (("--set", "m=heavy"), "--set m: expected a number, found 'heavy'"),
        (("--set", "m=-1"), "the parameter is positive"),
        (("--format", "pdf"), "Invalid value"),
    ],
)
def test_bad_options_exit_2(args, words) -> None:
    result = run("solve", P1, *args)
    assert result.exit_code == 2
    assert words in result.output


def test_bad_file_exit_2_with_location(tmp_path) -> None:
    bad = tmp_path / "bad.yaml"
    bad.write_text("parameters: {m: mass}\ncoordinates: [x]\nbodies:\n  b: {shape: particle, mass: M, at: [x, 0]}\nquestions: [eom]\n")
    result = run("solve", str(bad))
    assert result.exit_code == 2
    assert f"{bad}:4:30: bodies.b.mass: unknown symbol 'M' (did you mean 'm'?)" in result.output
    assert "Traceback" not in result.output


def test_json_keeps_one_line_per_file_even_for_bad_input(tmp_path) -> None:
    bad = tmp_path / "bad.yaml"
    bad.write_text("questions: [eom]\n")
    result = CliRunner().invoke(main, ["solve", str(bad), PENDULUM, "-f", "json"])
    assert result.exit_code == 2
    lines = [json.loads(x) for x in result.stdout.splitlines()]
    assert lines[0]["ok"] is False and "coordinates" in lines[0]["error"]["message"]
    assert lines[1]["ok"] is True


def test_unanswerable_question_exits_1(tmp_path) -> None:
    sliding = tmp_path / "slide.yaml"
    sliding.write_text("parameters: {m: mass, g: gravity}\ncoordinates: [x]\ngravity: [0, -g]\n"  # ∂V/∂x > 0,
                       "bodies:\n  b: {shape: particle, mass: m, at: [x, log(cosh(x)) + 2*x]}\n"  # no route
                       "questions: [equilibria]\n")  # proves it: m g (tanh x + 2) is transcendental
    result = run("solve", str(sliding))
    assert result.exit_code == 1
    assert "could not answer" in result.output and "no evident root" in result.output


def test_internal_error_exits_3(monkeypatch) -> None:
    from rbdsolve import solvers
    from rbdsolve.problem.schema import QuestionKind

    def broken(*args):
        raise ZeroDivisionError("boom")

    monkeypatch.setitem(solvers.FAMILIES, QuestionKind.EOM, solvers.Family(broken, broken))
    result = run("solve", PENDULUM)
    assert result.exit_code == 3
    assert "internal error: ZeroDivisionError: boom (run with --debug" in result.output
    assert "Traceback" not in result.output
    assert "Traceback" in run("solve", PENDULUM, "--debug").output


def test_check_validates_without_solving(tmp_path) -> None:
    result = run("check", str(PROBLEMS / "sg2150-2015-10-29"))
    assert result.exit_code == 0
    assert "p1-two-rods.yaml: ok (eom, equilibria, modes)" in result.output
    bad = tmp_path / "bad.yaml"
    bad.write_text("title: [\n")
    assert run("check", str(bad)).exit_code == 2


@pytest.mark.parametrize("fmt, marker", [("markdown", "$$"), ("latex", "\\begin{document}")])
def test_document_formats(fmt, marker, tmp_path) -> None:
    out = tmp_path / f"p1.{fmt}"
    result = run("solve", P1, "-f", fmt, "-o", str(out))
    assert result.exit_code == 0
    text = out.read_text(encoding="utf-8")
    assert marker in text
    assert "\\frac{25}{48}" in text or "frac{25}{48}" in text


def test_help_has_examples() -> None:
    assert "Examples:" in run("solve", "--help").output
    assert run("--help").exit_code == 0


def test_one_internal_error_does_not_lose_the_other_files(monkeypatch) -> None:
    from rbdsolve import solvers

    real = solvers.solve_file

    def flaky(problem, options=solvers.Options()):
        if "pendulum.yaml" in problem.file:
            raise ZeroDivisionError("boom")
        return real(problem, options)

    monkeypatch.setattr(solvers, "solve_file", flaky)
    result = CliRunner().invoke(main, ["solve", P1, PENDULUM, "-f", "json"])
    assert result.exit_code == 3
    lines = [json.loads(x) for x in result.stdout.splitlines()]
    assert lines[0]["ok"] is True and lines[1]["ok"] is False and lines[1]["exit_code"] == 3


CONE = (PROBLEMS / "steady" / "rolling-cone.yaml").read_text(encoding="utf-8")
PUSH = "        - {at: Q, force: N*e3}              # the table's push, spread along OB\n"
FRICTION = "        - {at: O, force: F1*e1 + F2*e2}     # friction\n"


def test_steady_motion_x_N_alone_reads_free_of_N(tmp_path) -> None:
    """N, F1, F2 are solved with x_N and shown first; x_N itself holds no N."""
    cone = tmp_path / "cone.yaml"
    cone.write_text(CONE.replace("solve_for: [N, x_N, F1, F2]", "solve_for: [x_N]"))
    result = run("solve", str(cone))
    assert result.exit_code == 0, result.output
    out = result.output
    assert "Solved, together with the reactions' other unknowns:" in out
    assert "N = g m" in out and "F₂ = 0" in out
    x_N = next(line for line in out.splitlines() if line.strip().startswith("x_N ="))
    assert "N" not in x_N.split("=", 1)[1]


def test_steady_motion_rolling_contact_without_reaction_exits_2(tmp_path) -> None:
    cone = tmp_path / "cone.yaml"
    text = CONE.replace(PUSH, "").replace("{at: O, force: F1*e1 + F2*e2}", "{at: O, force: F1*e1 + F2*e2 + N*e3}")
    cone.write_text(text)
    line = text.splitlines().index("      reactions:") + 2  # the list's first item, 1-based
    result = run("solve", str(cone))
    assert result.exit_code == 2, result.output
    assert (f"{cone}:{line}:9: questions[0].steady_motion.reactions: no reaction at the rolling contact 'B'"
            in result.output)
    assert "Traceback" not in result.output


def test_steady_motion_answer_with_an_unknown_exits_1(tmp_path) -> None:
    cone = tmp_path / "cone.yaml"
    cone.write_text(CONE.replace("unknowns: [spin, N, x_N, F1, F2]", "unknowns: [spin, N, x_N, F1, F2, N2]")
                    .replace(FRICTION, FRICTION + "        - {at: B, force: N2*e3}\n")
                    .replace("solve_for: [N, x_N, F1, F2]", "solve_for: [x_N]"))
    result = run("solve", str(cone))
    assert result.exit_code == 1, result.output
    assert "could not answer: the relations leave N2 unknown" in result.output
    assert "Solved" not in result.output


def _strict(text: str) -> dict:
    def refuse(token: str):
        raise ValueError(f"not strict JSON: {token}")

    return json.loads(text, parse_constant=refuse)


@pytest.mark.parametrize("path, values", [
    ("steady/rolling-cone.yaml", ["m=1", "h=1", "alpha=1/2", "g=9.81", "Omega=2"]),
    ("sg2150-2015-10-29/p3-rolling-ring.yaml", ["m=1", "r=1/5", "R=1", "g=9.81", "theta=1/2"]),  # no omega0
])
def test_steady_motion_numeric_route_prints_strict_json(path, values) -> None:
    """Every number finite or null: the cone's F2 = 0 (no relative error), the ring's
    relations holding omega0 and spin (null values)."""
    sets = [arg for value in values for arg in ("--set", value)]
    result = run("solve", str(PROBLEMS / path), "--route", "numeric", *sets, "--format", "json")
    assert result.exit_code == 0, result.output
    (answer,) = _strict(result.stdout)["results"]
    assert answer["ok"] and answer["route"] == "numeric" and answer["error_estimate"] < 1e-12
    assert answer["answers"]["solutions"] and answer["values"]["solved"] == answer["answers"]["solved"]


def test_steady_motion_numeric_route_without_a_value_exits_1() -> None:
    result = run("solve", str(PROBLEMS / "steady" / "heavy-top.yaml"), "--route", "numeric", "--set", "m=1",
                 "--format", "json")
    assert result.exit_code == 1, result.output
    (answer,) = _strict(result.stdout)["results"]
    assert answer["route"] == "numeric" and answer["answers"] is None
    assert answer["error"].startswith("the numeric route needs a value for every parameter the answer depends on; give h, J1, J3, g, "
                                      "theta, Omega (")
