"""LaTeX output: plain ASCII-safe text for pdflatex, and, where a TeX engine is
installed, every problem file's document compiles."""

from __future__ import annotations

import subprocess

import pytest

from rbdsolve.model.build import build_model
from rbdsolve.render.latex import render_document, text
from rbdsolve.solvers import solve_problem

from conftest import PROBLEMS, needs_tex, solved_file


def test_prose_becomes_latex_text() -> None:
    assert text("λ₁ > 0, J_xy = −∫ x y dm, ½ m v·v") == (
        "\\ensuremath{\\lambda_1} > 0, J\\_xy = \\ensuremath{-\\int} x y dm, "
        "\\ensuremath{\\tfrac12} m v\\ensuremath{\\cdot}v"
    )
    assert text("θ̇ and φ̈") == "\\ensuremath{\\dot{\\theta}} and \\ensuremath{\\ddot{\\varphi}}"
    assert text("50% & #1") == "50\\% \\& \\#1"
    assert text("☃") == "[U+2603]"
    # a stability decided past K = 0 names V's derivative of order 3 to 6 (equilibria/higher_order.py)
    assert text("∂⁶V/∂x⁶") == "\\ensuremath{\\partial^6}V/\\ensuremath{\\partial}x\\ensuremath{^6}"


FILES = sorted(p for p in PROBLEMS.rglob("*.yaml") if not p.name.endswith(".expected.yaml"))


@pytest.mark.parametrize("path", FILES, ids=lambda p: str(p.relative_to(PROBLEMS)))
def test_every_problem_compiles(tmp_path, path) -> None:
    """One document per file, not one for the corpus: each runs beside the file's golden,
    JSON and audit checks (conftest's ordering), so its solve is the one they share,
    where one document of all would solve the corpus again in whichever process ran it
    (100 s of the suite); and a failure names its file."""
    needs_tex()
    source = tmp_path / "one.tex"
    source.write_text(render_document([solved_file(path)[1]]), encoding="utf-8")
    run = subprocess.run(["pdflatex", "-interaction=nonstopmode", "-halt-on-error", source.name],
                         cwd=tmp_path, capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stdout[-2000:]
    assert (tmp_path / "one.pdf").stat().st_size > 10_000


def test_cases_and_conditions_compile(tmp_path) -> None:
    """Answers case by case (issue 19): "stable when Ω < Ω_c", a mode's cases, a critical
    value, an equilibrium that exists only where Ω ≥ Ω_c, in one document."""
    needs_tex()
    from rbdsolve.problem import load_text

    text = "\n".join(line for line in (PROBLEMS / "frames" / "rotating-hoop-slow.yaml").read_text().splitlines()
                     if not line.startswith("values:"))
    text = text[:text.index("questions:")] + "questions:\n  - equilibria: {frame: hoop}\n  - modes: {frame: hoop, about: each}\n"
    report = solve_problem(build_model(load_text(text, "hoop.yaml")))
    source = tmp_path / "cases.tex"
    source.write_text(render_document([report]), encoding="utf-8")
    assert "\\text{stable when}" in source.read_text() and "\\text{oscillation when}" in source.read_text()
    run = subprocess.run(["pdflatex", "-interaction=nonstopmode", "-halt-on-error", source.name],
                         cwd=tmp_path, capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stdout[-2000:]


def test_accented_text_passes_through() -> None:
    assert text("Müller, café, Å, ö") == "Müller, café, Å, ö"
    assert text("M u\u0308 + K u = 0") == "M \\ensuremath{\\ddot{u}} + K u = 0"
