"""Issue 28, findings 1-2: names that sympy uses for its own classes, and a batch in
which one file is hostile. Every good file keeps its solution and its JSON line, in
text, in JSON and with --jobs, and the exit code is the worst file's."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
import sympy as sp
from click.testing import CliRunner

from rbdsolve.cli import main

from conftest import SIMPLE_PENDULUM

# Names sympy's printers look up as classes (precedence by class name, printer methods).
CLASS_NAMES = ["Integer", "Rational", "Float", "PolyElement", "FracElement", "UnevaluatedExpr", "Add", "Mul"]
QUESTIONS = "questions: [eom, equilibria, modes]\n"


def run(*args):
    return CliRunner().invoke(main, [str(a) for a in args])


def pendulum(coordinate: str = "theta", mass: str = "m") -> str:
    text = SIMPLE_PENDULUM.replace("theta", coordinate).replace("{m: mass", "{" + mass + ": mass")
    return text.replace("mass: m,", f"mass: {mass},") + "values: {" + mass + ": 1, l: 1, g: 10}\n" + QUESTIONS


def assert_clean(result) -> None:
    assert result.exception is None or isinstance(result.exception, SystemExit), repr(result.exception)
    assert "Traceback" not in result.output and "internal error" not in result.output, result.output


@pytest.mark.parametrize("fmt", ["terminal", "json", "markdown", "latex"])
@pytest.mark.parametrize("name", CLASS_NAMES)
def test_a_coordinate_named_like_a_sympy_class_is_solved(tmp_path: Path, name: str, fmt: str) -> None:
    path = tmp_path / "p.yaml"
    path.write_text(pendulum(coordinate=name), encoding="utf-8")
    result = run("solve", path, "-f", fmt)
    assert_clean(result)
    assert result.exit_code == 0, result.output
    if fmt == "json":  # the small-oscillation frequency squared is g/l = 10, whatever the name
        line = json.loads(result.stdout)
        eom = line["results"][0]["answers"]
        names = {name: sp.Function(name), "t": sp.Symbol("t"), "l": sp.Symbol("l"), "m": sp.Symbol("m"),
                 "g": sp.Symbol("g")}
        text = json.dumps(eom)
        assert f"{name}(t)" in text
        omega2 = [sp.sympify(w, locals=names) ** 2 for w in line["results"][2]["answers"]["frequencies"]]
        assert [sp.simplify(w - sp.Symbol("g") / sp.Symbol("l")) for w in omega2] == [0]


@pytest.mark.parametrize("name", ["Integer", "Float", "Rational"])
def test_a_parameter_named_like_a_sympy_class_is_solved(tmp_path: Path, name: str) -> None:
    path = tmp_path / "p.yaml"
    path.write_text(pendulum(mass=name), encoding="utf-8")
    for route in ("auto", "numeric"):
        result = run("solve", path, "-f", "json", "--route", route)
        assert_clean(result)
        assert result.exit_code == 0, result.output


def _folder(tmp_path: Path) -> Path:
    """Five files in path order: four plain pendulums (lengths 1..4) and, third, one whose
    coordinate is named Float (it crashed the writer after every file was solved)."""
    folder = tmp_path / "exam"
    folder.mkdir()
    for i in range(5):
        text = pendulum(coordinate="Float" if i == 2 else "theta").replace("l: 1,", f"l: {i + 1},")
        (folder / f"p{i}.yaml").write_text(text, encoding="utf-8")
    return folder


@pytest.mark.parametrize("jobs", ["1", "2"])
def test_a_hostile_name_in_a_batch_loses_nothing(tmp_path: Path, jobs: str) -> None:
    folder = _folder(tmp_path)
    text = run("solve", folder, "--jobs", jobs, "--quiet")
    assert_clean(text)
    assert text.exit_code == 0 and text.stdout.count("Question 3: modes") == 5, text.output
    lines = run("solve", folder, "-f", "json", "--jobs", jobs, "--quiet")
    assert_clean(lines)
    assert lines.exit_code == 0, lines.output
    bodies = [json.loads(x) for x in lines.stdout.splitlines()]
    assert [Path(b["file"]).name for b in bodies] == [f"p{i}.yaml" for i in range(5)]
    assert all(b["ok"] for b in bodies)


def test_a_renderer_bug_in_one_file_costs_only_that_file(tmp_path: Path, monkeypatch) -> None:
    """A bug that shows only when one report is rendered: every other file's text and
    JSON line is written, the broken file gets an error line, and the exit code is 3."""
    import rbdsolve.render.json as json_renderer
    import rbdsolve.render.terminal as terminal_renderer

    folder = _folder(tmp_path)
    for module, name in ((json_renderer, "render_report"), (terminal_renderer, "render")):
        real = getattr(module, name)

        def broken(report, *args, real=real):
            if report.file.endswith("p3.yaml"):
                raise RuntimeError("a renderer bug")
            return real(report, *args)

        monkeypatch.setattr(module, name, broken)
    lines = run("solve", folder, "-f", "json", "--quiet")
    assert lines.exit_code == 3
    bodies = [json.loads(x) for x in lines.stdout.splitlines()]
    assert [b["ok"] for b in bodies] == [True, True, True, False, True]
    assert "a renderer bug" in bodies[3]["error"]["message"] and bodies[3]["exit_code"] == 3
    assert lines.stderr.count("\n") == 1 and "p3.yaml: rbdsolve: internal error" in lines.stderr
    text = run("solve", folder)
    assert text.exit_code == 3 and text.stdout.count("Question 3: modes") == 4
    assert "Summary" in text.stderr


def test_a_worker_that_dies_costs_only_its_file(tmp_path: Path, monkeypatch) -> None:
    """A file that kills its process (memory, a signal) with --jobs 2: the pool breaks,
    the files it still held are solved again one by one, and only that file fails."""
    import os

    import rbdsolve.cli.batch as batch

    real = batch.solve_source

    def dying(source, settings):
        if source.name.endswith("p1.yaml"):
            os._exit(9)
        return real(source, settings)

    monkeypatch.setattr(batch, "solve_source", dying)  # the workers are forked: they see it
    folder = _folder(tmp_path)
    lines = run("solve", folder, "-f", "json", "--quiet", "--jobs", "2")
    assert lines.exit_code == 3
    bodies = [json.loads(x) for x in lines.stdout.splitlines()]
    assert [b["ok"] for b in bodies] == [True, False, True, True, True], lines.stderr
    assert "p1.yaml: rbdsolve: internal error" in lines.stderr
