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
