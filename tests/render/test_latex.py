"""LaTeX output: plain ASCII-safe text for pdflatex, and, where a TeX engine is
installed, the whole corpus compiles."""

from __future__ import annotations

import subprocess

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


def test_the_corpus_compiles(tmp_path) -> None:
    needs_tex()
    files = sorted(p for p in PROBLEMS.rglob("*.yaml") if not p.name.endswith(".expected.yaml"))
    reports = [solved_file(p)[1] for p in files]  # solved already where this process ran a file's golden test
    source = tmp_path / "all.tex"
    source.write_text(render_document(reports), encoding="utf-8")
    run = subprocess.run(["pdflatex", "-interaction=nonstopmode", "-halt-on-error", source.name],
                         cwd=tmp_path, capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stdout[-2000:]
    assert (tmp_path / "all.pdf").stat().st_size > 10_000


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
