"""Modes whose kind depends on the parameters (issue 19): oscillation on one side of a
critical value, growth on the other, each case checked by sampling.

By hand: the bead on the hoop turning at Ω, about θ = 0 in the hoop's frame:
M = m R², K = m R (g − Ω² R), λ = g/R − Ω²: an oscillation iff Ω < √(g/R).
An inverted rod (m, l) on a pivot with a torsional spring c, about θ = 0:
M = m l²/3, K = c − m g l/2, λ = 3 (2c − m g l)/(2 m l²): an oscillation iff c > m g l/2.
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


def _without_values(path) -> str:
    return "\n".join(line for line in path.read_text().splitlines() if not line.startswith("values:"))


def _modes(text: str):
    report = solve_problem(build_model(load_text(text, "scene.yaml")))
    (solution,) = [s for s in report.solutions if s.question == "modes"]
    assert solution.solved, solution.error
    return solution.answers


def _holds(condition, at: dict) -> bool:
    names = {str(s): s for s in at}
    return bool(sp.parse_expr(str(condition), local_dict=names).subs(at))


def _check(answers, names: tuple[str, ...], critical, kind_at) -> None:
    (c,) = answers.critical
    assert c.parameter == critical[0]
    symbols = {n: sp.Symbol(n, positive=True) for n in names}
    assert sp.simplify(sp.parse_expr(str(c.value), local_dict=symbols) - critical[1](symbols)) == 0
    (cases,) = answers.cases
    rng = random.Random(19)
    for _ in range(40):
        at = {symbols[n]: rng.uniform(0.1, 5) for n in names}
        (case,) = [x for x in cases if _holds(x.when, at)]
        assert case.kind.value == kind_at({n: float(at[symbols[n]]) for n in names})


def test_the_hoop_oscillates_below_the_critical_rate_and_grows_above() -> None:
    answers = _modes(_without_values(PROBLEMS / "frames" / "rotating-hoop-slow.yaml"))
    _check(answers, ("m", "R", "g", "Omega"), ("Omega", lambda s: sp.sqrt(s["g"] / s["R"])),
           lambda v: "oscillation" if v["g"] / v["R"] - v["Omega"] ** 2 > 0 else "growth")


def test_the_inverted_rod_oscillates_when_the_spring_is_stiff_enough() -> None:
    text = _without_values(PROBLEMS / "edges" / "inverted-rod-torsion-spring.yaml")
    text = text[:text.index("questions:")] + "questions:\n  - modes: {about: {theta: 0}}\n"
    answers = _modes(text)
    _check(answers, ("m", "l", "g", "c"), ("c", lambda s: s["m"] * s["g"] * s["l"] / 2),
           lambda v: "oscillation" if v["c"] - v["m"] * v["g"] * v["l"] / 2 > 0 else "growth")
    (lam,) = answers.eigenvalues
    m, l, g, c = (sp.Symbol(n, positive=True) for n in "mlgc")
    assert sp.simplify(sp.parse_expr(str(lam), local_dict={"m": m, "l": l, "g": g, "c": c})
                       - 3 * (2 * c - m * g * l) / (2 * m * l**2)) == 0


def test_modes_at_every_equilibrium_with_their_cases() -> None:
    """about: each on the hoop (no values): θ = 0 oscillates below Ω_c and grows above;
    ±acos(g/(R Ω²)) exist only above Ω_c, where they oscillate with
    λ = Ω² − g²/(Ω² R²) (K/M by hand); θ = π grows at γ = √(g/R + Ω²)."""
    text = _without_values(PROBLEMS / "frames" / "rotating-hoop-slow.yaml")
    text = text[:text.index("questions:")] + "questions:\n  - modes: {frame: hoop, about: each}\n"
    report = solve_problem(build_model(load_text(text, "hoop.yaml")))
    (solution,) = report.solutions
    assert solution.solved, solution.error
    bottom, left, right, top = solution.answers.modes
    assert [m.value for m in bottom.motions] == ["depends"]
    R, g, Om = (sp.Symbol(n, positive=True) for n in ("R", "g", "Omega"))
    local = {"R": R, "g": g, "Omega": Om}
    for side in (left, right):
        assert [m.value for m in side.motions] == ["oscillation"]
        (lam,) = side.eigenvalues
        assert sp.simplify(sp.parse_expr(str(lam), local_dict=local) - (Om**2 - g**2 / (Om**2 * R**2))) == 0
    assert [m.value for m in top.motions] == ["growth"]
    (gamma,) = top.growth_rates
    assert sp.simplify(sp.parse_expr(str(gamma), local_dict=local) ** 2 - (g / R + Om**2)) == 0


def test_about_each_on_the_numeric_route() -> None:
    """The inverted rod with c = 3/10 (m = 1, l = 2, g = 1): equilibria −θ*, 0, θ* with
    λ = c (1 − k cos θ)/M, k = 10/3, M = 4/3 (by hand; θ* by mpmath)."""
    import mpmath as mp

    text = (PROBLEMS / "edges" / "inverted-rod-torsion-spring.yaml").read_text()
    text = text[:text.index("values:")] + "values: {m: 1, l: 2, g: 1, c: 3/10}\n" + text[text.index("coordinates:"):]
    text = text[:text.index("questions:")] + "questions:\n  - modes: {about: each}\n"
    (solution,) = solve_problem(build_model(load_text(text, "rod.yaml"))).solutions
    assert solution.solved and solution.route.value == "numeric", solution.error
    k = mp.mpf(10) / 3
    root = float(mp.findroot(lambda x: x - k * mp.sin(x), 2.5))
    for modes, theta in zip(solution.answers.modes, (-root, 0.0, root)):
        assert modes.about["theta"] == pytest.approx(theta, abs=1e-9)
        (lam,) = modes.eigenvalues
        assert lam == pytest.approx(0.3 * (1 - float(k) * math.cos(theta)) / (4 / 3), rel=1e-9)
