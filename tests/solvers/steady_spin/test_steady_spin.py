"""Steady spin: a numeric simulation of Euler's equations confirms which spins are
stable, and the growth rate of the unstable one.

The simulation integrates J₁ ω̇₁ = (J₂ − J₃) ω₂ ω₃ (and cyclic) with scipy's solve_ivp
(rtol 1e-10) from Ω e_k plus a perturbation of 1e-7 in the other two components; the
moments are those rbdsolve reports for the box of problems/spin/box-three-sides.yaml at
m = a = 1 (the shape library itself is checked against integration elsewhere). A
stable spin keeps the perturbation below 1e-5 until t = 40; the unstable one grows at
the reported rate γ, measured from the slope of log |ε| over 10 ≤ t ≤ 25 to 2 %.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp

from rbdsolve.model.build import build_model
from rbdsolve.problem import load_file, load_text
from rbdsolve.solvers import solve_problem

from conftest import PROBLEMS

BOX = PROBLEMS / "spin" / "box-three-sides.yaml"


def answers():
    return solve_problem(build_model(load_file(BOX))).solutions[0].answers


def number(expr: sp.Expr) -> float:
    return float(expr.xreplace({s: 1 for s in expr.free_symbols}))


def simulate(J: list[float], k: int, t_end: float) -> tuple[np.ndarray, np.ndarray]:
    def euler(_, w):
        return [(J[1] - J[2]) * w[1] * w[2] / J[0],
                (J[2] - J[0]) * w[2] * w[0] / J[1],
                (J[0] - J[1]) * w[0] * w[1] / J[2]]

    w0 = np.full(3, 1e-7)
    w0[k] = 1.0
    times = np.linspace(0, t_end, 801)
    run = solve_ivp(euler, (0, t_end), w0, t_eval=times, rtol=1e-10, atol=1e-14, method="DOP853")
    off_axis = np.delete(run.y, k, axis=0)
    return times, np.linalg.norm(off_axis, axis=0)


@pytest.mark.parametrize("k", [0, 1, 2])
def test_simulation_confirms_the_stability_of_each_spin(k: int) -> None:
    found = answers()
    J = [number(x) for x in found.moments]
    spin = found.cases[0].stability[k]
    times, size = simulate(J, k, 40.0)
    if spin.stability.value == "stable":
        assert size.max() < 1e-5
    else:
        assert spin.stability.value == "unstable"
        window = (times >= 10) & (times <= 25)
        slope = np.polyfit(times[window], np.log(size[window]), 1)[0]
        gamma = number(spin.rate)  # Ω = 1
        assert slope == pytest.approx(gamma, rel=0.02)
        assert size.max() > 1e-2


def test_symmetric_body_spins_about_its_axis_and_in_its_equatorial_plane() -> None:
    text = """
parameters: {m: mass, r: radius, h: height}
bodies:
  can: {shape: cylinder, mass: m, radius: r, height: h, at: [0, 0, 0]}
questions: [steady_spin]
"""
    found = solve_problem(build_model(load_text(text, "can.yaml"))).solutions[0].answers
    patterns = [(len(c.condition.equal), len(c.steady_spins)) for c in found.cases]
    # J1 = J2 always (the axis is z); J3 may or may not equal them (h = √3 r)
    assert patterns == [(0, 2), (1, 1)]
    axis, plane = found.cases[0].stability
    assert axis.stability.value == "stable" and plane.stability.value == "neutral"
    J1, J3 = found.moments[0], found.moments[2]
    assert sp.simplify(axis.rate - sp.Symbol("Omega") * (J3 - J1) / J1) == 0
    assert math.isclose(number(J1), 1 / 3, rel_tol=1e-12)  # m (3 r² + h²)/12 at 1


def test_a_case_is_said_in_the_printer_of_the_answers() -> None:
    """J₁ = J₂, J₁ ≠ J₃, not J1 = J2 in sympy's spelling."""
    from rbdsolve.solvers.steady_spin.answers import Condition
    from rbdsolve.solvers.steady_spin.steps import describe

    J1, J2, J3 = sp.symbols("J1 J2 J3", positive=True)
    assert describe(Condition(((J1, J2),), ((J1, J3),))) == "J₁ = J₂, J₁ ≠ J₃"
    assert describe(Condition((), ())) == "in every case"


def test_the_numeric_route_names_the_intermediate_axis_unstable_by_hand() -> None:
    """The box of sides 1, 2, 3 (m = 1) on the numeric route: J = (2² + 3², 1 + 3², 1 + 2²)/12
    = (13, 10, 5)/12. Spin about e_k: (J_k − J_i)(J_k − J_j) > 0 stable, turning at
    √((J_k − J_i)(J_k − J_j)/(J_i J_j)) per unit spin, < 0 unstable, growing at the same root
    of its size: 5/12: 40 > 0, √(40/130); 10/12: −15 < 0, √(15/65); 13/12: 24 > 0, √(24/50)."""
    from rbdsolve.solvers import Options, RouteChoice

    text = BOX.read_text() + "values: {m: 1, a: 1}\n"
    (solution,) = solve_problem(build_model(load_text(text, "box.yaml")), Options(route=RouteChoice.NUMERIC)).solutions
    assert solution.solved and solution.route.value == "numeric", solution.error
    spins = sorted(solution.answers.spins, key=lambda s: s.moment)
    assert [s.moment for s in spins] == pytest.approx([5 / 12, 10 / 12, 13 / 12], rel=1e-12)
    assert [s.stability.value for s in spins] == ["stable", "unstable", "stable"]
    assert [s.rate for s in spins] == pytest.approx([math.sqrt(40 / 130), math.sqrt(15 / 65), math.sqrt(24 / 50)],
                                                    rel=1e-12)
