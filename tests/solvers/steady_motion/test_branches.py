"""Every branch of a steady motion (issue 19): a heavy top's two precession rates and
the least spin for which they exist, checked by sampling.

By hand (about the fixed point O, I₁ = J₁ + m h² across the axis, I₃ = J₃ along it,
spin s relative to the precessing triad, ω₃ = s + Ω cos θ): the moment balance
m g h sin θ = Ω sin θ (I₃ ω₃ − I₁ Ω cos θ) gives (I₁ − I₃) cos θ Ω² − I₃ s Ω + m g h = 0,
two real rates iff I₃² s² ≥ 4 (I₁ − I₃) m g h cos θ, i.e. s ≥ s_c = 2 √((I₁ − I₃) m g h cos θ)/I₃.
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

TOP = (PROBLEMS / "steady" / "heavy-top.yaml").read_text()
TOP = (TOP.replace("solve_for: spin", "solve_for: Omega").replace("unknowns: [spin]", "unknowns: [Omega]")
       .replace("  Omega: rate of precession\n", "  spin: spin rate relative to the precessing triad\n")
       + "assumptions: [J1 > J3, theta < pi/2]\n")
NAMES = ("m", "h", "J1", "J3", "g", "theta", "spin")


def test_both_precession_rates_and_the_least_spin() -> None:
    (solution,) = solve_problem(build_model(load_text(TOP, "top.yaml"))).solutions
    assert solution.solved, solution.error
    answers = solution.answers
    assert len(answers.branches) == 2
    symbols = {n: sp.Symbol(n, positive=True) for n in NAMES}
    (critical,) = answers.critical
    assert critical.parameter == "spin"
    s_c = sp.parse_expr(str(critical.value), local_dict=symbols)
    rng = random.Random(19)
    for _ in range(30):
        v = {"m": rng.uniform(0.2, 3), "h": rng.uniform(0.1, 1), "J3": rng.uniform(0.05, 1), "g": 9.81,
             "theta": rng.uniform(0.05, 1.5)}
        v["J1"] = v["J3"] * rng.uniform(1.05, 3)
        I1, I3 = v["J1"] + v["m"] * v["h"] ** 2, v["J3"]
        least = 2 * math.sqrt((I1 - I3) * v["m"] * 9.81 * v["h"] * math.cos(v["theta"])) / I3
        at = {symbols[n]: x for n, x in v.items()}
        assert float(s_c.subs(at)) == pytest.approx(least, rel=1e-12)
        v["spin"] = least * rng.choice([rng.uniform(0.3, 0.97), rng.uniform(1.03, 3)])
        at[symbols["spin"]] = v["spin"]
        for branch in answers.branches:
            exists = bool(sp.parse_expr(str(branch.exists_when), local_dict=symbols).subs(at))
            assert exists == (v["spin"] >= least)
            if exists:  # the rate solves the balance by hand
                (rate,) = branch.solved.values()
                W = complex(sp.N(sp.parse_expr(str(rate), local_dict=symbols).subs(at)))
                assert abs(W.imag) < 1e-12
                W = W.real
                residual = (I1 - I3) * math.cos(v["theta"]) * W**2 - I3 * v["spin"] * W + v["m"] * 9.81 * v["h"]
                assert abs(residual) < 1e-9 * (v["m"] * 9.81 * v["h"])


def test_a_rate_under_a_root_is_solved_for() -> None:
    # the rolling coin asked for ω₀ itself, not ω₀²: ω₀² cos θ (6R + r sin θ) = 4 g sin θ (by hand)
    text = (PROBLEMS / "steady" / "rolling-coin.yaml").read_text().replace("solve_for: omega0**2", "solve_for: omega0")
    (solution,) = solve_problem(build_model(load_text(text, "coin.yaml"))).solutions
    assert solution.solved, solution.error
    (w,) = solution.answers.solved.values()
    R, r, g, th = sp.symbols("R r g theta", positive=True)
    w = sp.parse_expr(str(w), local_dict={"R": R, "r": r, "g": g, "theta": th})
    at = {R: 0.4, r: 0.02, g: 9.81, th: 0.3}
    want = math.sqrt(4 * 9.81 * math.sin(0.3) / (math.cos(0.3) * (6 * 0.4 + 0.02 * math.sin(0.3))))
    assert float(w.subs(at)) == pytest.approx(want, rel=1e-12)


def test_a_tilt_with_no_compact_closed_form_falls_back_to_the_numeric_route() -> None:
    """The rolling coin asked for its tilt θ at a given ω₀: ω₀² cos θ (6R + r sin θ) =
    4 g sin θ is a quartic in sin θ. The exact route says so at once; auto takes the
    numeric route (θ needs no value there), whose solutions satisfy the relation by hand."""
    from rbdsolve.solvers import solve_file
    from rbdsolve.solvers.routes.options import Options

    text = (PROBLEMS / "steady" / "rolling-coin.yaml").read_text().replace("solve_for: omega0**2", "solve_for: theta")
    text += "values: {m: 1, r: 1/50, R: 2/5, g: 981/100, omega0: 3}\n"
    (solution,) = solve_file(load_text(text, "coin.yaml"), Options(budget=30)).solutions
    assert solution.solved and solution.route.value == "numeric", solution.error
    assert any("degree 4 in the sine" in w for w in solution.warnings)
    def residual(th: float) -> float:
        return -6 * 0.4 * 9 * math.cos(th) + 4 * 9.81 * math.sin(th) - 9 * 0.02 * math.sin(th) * math.cos(th)

    # every root in one turn, by hand: sign changes of the residual on a fine grid, bisected
    from scipy.optimize import brentq
    grid = [-math.pi + 2 * math.pi * k / 2000 for k in range(2001)]
    roots = [brentq(residual, a, b, xtol=1e-14) for a, b in zip(grid, grid[1:]) if residual(a) * residual(b) < 0]
    assert len(roots) == 2  # the premise: tan θ ≈ 0.55 and the same line the other way
    got = sorted((found.unknowns["theta"] + math.pi) % (2 * math.pi) - math.pi for found in solution.answers.solutions)
    assert got == pytest.approx(sorted(roots), abs=1e-9)
    assert all(abs(residual(th)) < 1e-9 for th in got)


@pytest.mark.parametrize("asked", ["omega0**2", "omega0"])
def test_the_coins_tilt_condition_holds_on_each_side(asked) -> None:
    """ω₀² = 4 g sin θ/((6R + r sin θ) cos θ) must be ≥ 0 (ω₀ real). The tilt is a positive
    angle parameter, studied in (0, π): the condition printed is sampled on both sides
    against the sign of the right side computed here, not by rbdsolve."""
    text = (PROBLEMS / "steady" / "rolling-coin.yaml").read_text().replace("solve_for: omega0**2",
                                                                           f"solve_for: {asked}")
    (solution,) = solve_problem(build_model(load_text(text, "coin.yaml"))).solutions
    (branch,) = solution.answers.branches
    (critical,) = solution.answers.critical
    assert (critical.parameter, critical.value) == ("theta", sp.pi / 2)
    R, r, g, th = sp.symbols("R r g theta", positive=True)
    when = sp.parse_expr(str(branch.exists_when), local_dict={"R": R, "r": r, "g": g, "theta": th})
    rng = random.Random(7)
    for _ in range(40):
        v = {R: rng.uniform(0.01, 5), r: rng.uniform(0.01, 5), g: rng.uniform(1, 20), th: rng.uniform(0.01, 3.13)}
        square = 4 * v[g] * math.sin(v[th]) / ((6 * v[R] + v[r] * math.sin(v[th])) * math.cos(v[th]))
        assert bool(when.subs(v)) == (square > 0)
