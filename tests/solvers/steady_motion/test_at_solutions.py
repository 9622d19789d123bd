"""A solved quantity's value put back where the other answers use it (issue 41): the
rolling ring of the seed exam (problem 3) asks for ω₀², and its spin and ω hold ω₀;
the heavy top asks for its spin, which ω holds. Expected values by hand."""

from __future__ import annotations

import math

import pytest

from rbdsolve.problem import load_file
from rbdsolve.problem.quantities.overrides import checked_values, given_values
from rbdsolve.render.numbers import number_text
from rbdsolve.solvers import Options, RouteChoice, solve_file

from conftest import PROBLEMS

RING = PROBLEMS / "sg2150-2015-10-29" / "p3-rolling-ring.yaml"
TOP = PROBLEMS / "steady" / "heavy-top.yaml"


def _numbers(path, values: dict) -> dict[str, str]:
    """The numeric block on the exact route, as ``--set NAME=VALUE…`` gives it."""
    problem = load_file(path)
    given = checked_values(given_values(values, "values"), problem, "values")
    report = solve_file(problem.with_values(given), Options(route=RouteChoice("exact")))
    (solution,) = report.solutions
    return {number_text(n).split(" = ")[0]: number_text(n) for n in solution.numbers}


def _value(line: str) -> list[float]:
    shown = line.split(" = ")[1].split(" rad/s")[0].strip("()").replace("−", "-")
    return [float(x) for x in shown.split(",")]


def test_the_ring_s_omega0_spin_and_omega_at_its_solution() -> None:
    """ω₀² = 2 g sin θ/((4R + r sin θ) cos θ) (the exam's answer), ω₀ > 0 its root; the
    rolling condition gives the spin −ω₀ (R/r + sin θ) and ω = (−R ω₀/r, 0, ω₀ cos θ)."""
    g, th, R, r = 9.81, 0.5, 0.5, 0.1
    w0 = math.sqrt(2 * g * math.sin(th) / ((4 * R + r * math.sin(th)) * math.cos(th)))
    lines = _numbers(RING, {"m": 1, "r": r, "R": R, "g": g, "theta": th})
    assert _value(lines["ω₀"]) == pytest.approx([w0], rel=1e-5)
    assert _value(lines["spin"]) == pytest.approx([-w0 * (R / r + math.sin(th))], rel=1e-5)
    assert lines["spin"].endswith("rad/s")
    assert _value(lines["ω"]) == pytest.approx([-R * w0 / r, 0, w0 * math.cos(th)], rel=1e-5, abs=1e-9)
    assert lines["ω"].endswith("rad/s")
    assert list(lines).count("ω₀²") == 1  # the one solution is printed once, not again as its branch


def test_the_top_s_omega_holds_the_spin_found() -> None:
    """Moments about O: J₃ Ω s sin θ = (J₁ − J₃) Ω² cos θ sin θ + Ω² h² m cos θ sin θ + m g h sin θ,
    so ω = (0, Ω sin θ, Ω cos θ + s) in the precessing triad."""
    m, h, J1, J3, g, th, W = 1, 0.1, 0.01, 0.005, 9.81, 0.5, 2
    s = ((J1 - J3) * W**2 * math.cos(th) + W**2 * h**2 * m * math.cos(th) + g * h * m) / (J3 * W)
    lines = _numbers(TOP, {"m": m, "h": h, "J1": J1, "J3": J3, "g": g, "theta": th, "Omega": W})
    assert _value(lines["spin"]) == pytest.approx([s], rel=1e-5)
    assert _value(lines["ω"]) == pytest.approx([0, W * math.sin(th), W * math.cos(th) + s], rel=1e-5, abs=1e-9)
