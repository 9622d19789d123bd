"""Parameter values as the answers print the names: v₀ = 300 m/s, $\\Omega = 10$."""

from __future__ import annotations

from rbdsolve.form.printers import significant_digits
from rbdsolve.render.numbers import value_latex
from rbdsolve.report.steps import ModelSummary, ProblemReport


def test_values_in_text_and_in_latex() -> None:
    report = ProblemReport("p.yaml", "t", "", "", ModelSummary((), None, None, ()), (),
                           {"v0": 300.0, "Omega": 2.0 / 3.0}, ("v0", "Omega"), {"v0": "m/s"})
    assert report.value_text("v0") == "v₀ = 300 m/s" and report.value_text("Omega") == "Ω = 0.666667"
    assert value_latex("Omega", 1.5e-7) == "\\Omega = 1.5 \\cdot 10^{-7}"
    with significant_digits(2):
        assert report.value_text("Omega") == "Ω = 0.67"


INCLINE = """\
title: Block on an incline
parameters: {m: mass, alpha: angle of the incline, beta: another angle, g: gravity}
coordinates: [s]
values: {m: 2 kg, alpha: 30 deg, beta: pi/6, g: 9.81}
gravity: [0, -g*cos(beta - alpha)]
points:
  P: s*[cos(alpha), sin(alpha)]
bodies:
  block: {shape: particle, mass: m, at: P}
questions: [eom]
"""


def test_an_angle_given_in_degrees_shows_its_degrees_in_every_format(tmp_path) -> None:
    """α = 30 deg is π/6 in every answer; beside its value the header shows (30°), as the
    file wrote it. β = pi/6, a plain number, shows none; --set takes degrees alike."""
    from click.testing import CliRunner

    from rbdsolve.cli import main

    path = tmp_path / "incline.yaml"
    path.write_text(INCLINE)
    text = CliRunner().invoke(main, ["solve", str(path)]).output
    assert "m = 2 kg, α = 0.523599 (30°), β = 0.523599, g = 9.81" in " ".join(text.split())
    markdown = CliRunner().invoke(main, ["solve", "-f", "markdown", str(path)]).output
    assert "$\\alpha = 0.523599$ (30°), $\\beta = 0.523599$," in markdown
    latex = CliRunner().invoke(main, ["solve", "-f", "latex", str(path)]).output
    assert "$\\alpha = 0.523599$ (30\\ensuremath{^\\circ})" in latex
    given = CliRunner().invoke(main, ["solve", str(path), "--set", "alpha=2/5 rev", "--set", "beta=45"]).output
    assert "α = 2.51327 (144°), β = 45," in " ".join(given.split())
