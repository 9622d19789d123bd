"""Equilibria whose existence and stability depend on the parameters (issue 19): the
critical value, the cases, and every printed condition checked by sampling.

Expected by hand for the bead on a hoop turning at Ω (in the hoop's frame):
V' = −m R (g cos θ + ½ Ω² R sin²θ), ∂V'/∂θ = m R sin θ (g − Ω² R cos θ);
θ = 0: V'' = m R (g − Ω² R), stable iff Ω² < g/R; θ = ±acos(g/(R Ω²)) exist iff
Ω² ≥ g/R, with V'' = m (Ω² R² − g²/Ω²) > 0 there; θ = π: V'' = −m R (g + Ω² R) < 0.
So Ω_c = √(g/R).
"""

from __future__ import annotations

import math
import random

import pytest
import sympy as sp

from conftest import PROBLEMS
from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.solvers import solve_problem

HOOP = "\n".join(line for line in (PROBLEMS / "frames" / "rotating-hoop-slow.yaml").read_text().splitlines()
                 if not line.startswith("values:"))


def _answers():
    report = solve_problem(build_model(load_text(HOOP, "hoop.yaml")))
    (solution,) = [s for s in report.solutions if s.question == "equilibria"]
    assert solution.solved, solution.error
    return solution.answers


def _names(expr: sp.Basic) -> sp.Basic:
    """The answer's symbols as plain positive symbols, as a script reading the JSON has them."""
    return sp.parse_expr(str(expr), local_dict={n: sp.Symbol(n, positive=True) for n in ("R", "g", "m", "Omega")})


def test_the_critical_rate_is_named() -> None:
    (critical,) = _answers().critical
    R, g = sp.symbols("R g", positive=True)
    assert critical.parameter == "Omega" and sp.simplify(_names(critical.value) - sp.sqrt(g / R)) == 0


def test_every_printed_condition_holds_at_sampled_values() -> None:
    """Sample R, g, m and Ω on both sides of Ω_c: each case claimed for the sample must
    agree with the hand derivation (the sign of V'' at the equilibrium, and whether
    acos(g/(R Ω²)) is real)."""
    answers = _answers()
    by_place = {str(eq.at["theta"]): eq for eq in answers.equilibria}
    rng = random.Random(19)
    for _ in range(40):
        R, g, m = (rng.uniform(0.1, 5) for _ in range(3))
        Om = math.sqrt(g / R) * rng.choice([rng.uniform(0.2, 0.98), rng.uniform(1.02, 4)])
        at = {sp.Symbol(n, positive=True): v for n, v in (("R", R), ("g", g), ("m", m), ("Omega", Om))}
        # θ = 0: stable iff Ω² < g/R
        (case,) = [c for c in by_place["0"].stability_cases if bool(_names(c.when).subs(at))]
        assert case.stability.value == ("stable" if m * R * (g - Om**2 * R) > 0 else "unstable")
        for place in ("acos(g/(Omega**2*R))", "-acos(g/(Omega**2*R))"):
            eq = by_place[place]
            assert bool(_names(eq.exists_when).subs(at)) == (g / (R * Om**2) <= 1)
            if g / (R * Om**2) <= 1:
                assert eq.stability.value == "stable" and m * (Om**2 * R**2 - g**2 / Om**2) > 0
        assert by_place["pi"].stability.value == "unstable"


def test_the_cases_read_as_an_exam_writes_them() -> None:
    from rbdsolve.cli import main
    from click.testing import CliRunner

    out = CliRunner().invoke(main, ["solve", "-"], input=HOOP).output
    assert "stable when Ω < Ω_c" in out and "unstable when Ω > Ω_c" in out
    assert "Ω ≥ Ω_c" in out and "Ω_c = √(g/R)" in out


@pytest.mark.parametrize("values", ["values: {m: 1, R: 1, g: 9.81, Omega: 2}", "values: {m: 1, R: 1, g: 9.81, Omega: 5}"])
def test_with_values_the_case_is_decided(values) -> None:
    report = solve_problem(build_model(load_text(HOOP + "\n" + values + "\n", "hoop.yaml")))
    (solution,) = [s for s in report.solutions if s.question == "equilibria"]
    assert all(eq.stability.value != "depends" for eq in solution.answers.equilibria)
