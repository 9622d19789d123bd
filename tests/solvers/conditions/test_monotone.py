"""Exact roots a monotone left side proves (θ = k sin θ, |k| < 1), and numeric roots
recognized as simple exact values within their error bound; expectations by hand."""

from __future__ import annotations

import math

import sympy as sp

from rbdsolve.model.build import build_model
from rbdsolve.problem import load_file, load_text
from rbdsolve.solvers.equilibria import numeric as equilibria_numeric
from rbdsolve.solvers.numeric.recognized import recognize
from rbdsolve.solvers import solve_problem
from rbdsolve.solvers.equilibria import exact as equilibria_exact
from rbdsolve.solvers.conditions.monotone import monotone_root
from rbdsolve.solvers.routes.options import Options, RouteChoice

from conftest import PROBLEMS

theta = sp.Symbol("theta", real=True)
k = sp.Symbol("k", positive=True)


def test_theta_equals_k_sin_theta_with_k_below_one() -> None:
    # f' = 1 − cos θ/2 ≥ 1/2 > 0: increasing, f(0) = 0
    found = monotone_root(theta - sp.sin(theta) / 2, theta, {})
    assert found.root == 0 and found.increasing and found.bound == sp.Rational(1, 2)


def test_two_theta_less_three_halves_sin_theta() -> None:
    found = monotone_root(2 * theta - sp.Rational(3, 2) * sp.sin(theta), theta, {})
    assert found.root == 0 and found.bound == sp.Rational(1, 2)


def test_decreasing() -> None:
    # f' = −3 + cos θ ≤ −2 < 0
    found = monotone_root(-3 * theta + sp.sin(theta), theta, {})
    assert found.root == 0 and not found.increasing and found.bound == -2


def test_a_root_at_pi() -> None:
    # f = 2(θ − π) − sin θ: f' = 2 − cos θ ≥ 1, f(π) = 0
    assert monotone_root(2 * (theta - sp.pi) - sp.sin(theta), theta, {}).root == sp.pi


def test_not_proved() -> None:
    assert monotone_root(theta - 2 * sp.sin(theta), theta, {}) is None  # three roots: 0, ±1.895
    assert monotone_root(theta - k * sp.sin(theta), theta, {}) is None  # k unknown: 1 − k undecided
    assert monotone_root(theta - k * sp.sin(theta), theta, {k: sp.Rational(1, 3)}).root == 0
    assert monotone_root(2 * theta - sp.sin(theta) - 1, theta, {}) is None  # one root, not a simple value
    assert monotone_root(theta - sp.sin(theta) * theta / 2, theta, {}) is None  # θ in f' outside sin, cos


def test_recognize_within_the_bound_only() -> None:
    at, recognized, bound = recognize({"a": -3.08e-32, "b": math.pi + 1e-17, "c": 1.2}, 2e-16)
    assert at == {"a": 0.0, "b": math.pi, "c": 1.2} and recognized == {"a": "0", "b": "pi"} and bound == 2e-16
    assert recognize({"a": 1e-9}, 2e-16)[1] == {}
    assert recognize({"a": 0.0}, float("inf"))[1] == {}


def test_the_numeric_route_prints_zero_not_round_off() -> None:
    text = """\
parameters: {m: mass, l: length, g: gravity, c: stiffness}
values: {m: 1, l: 1, g: 9.81, c: 1/4}
coordinates:
  theta: {kind: angle, periodic: false, range: [-20, 20]}
gravity: [0, -g]
points:
  G: l/2 * [sin(theta), cos(theta)]
bodies:
  rod: {shape: rod, mass: m, length: l, at: G, angle: theta, axis: y}
springs:
  pivot: {stiffness: c, angle: theta}
questions: [equilibria]
"""
    solution = equilibria_numeric.solve(None, build_model(load_text(text, "r.yaml")), Options())
    zero = [eq for eq in solution.answers.equilibria if eq.recognized]
    assert len(zero) == 1 and zero[0].at == {"theta": 0.0} and zero[0].recognized == {"theta": "0"}


def test_an_assumption_proves_the_bound(tmp_path) -> None:
    """problems/edges/eccentric-wheel-spring.yaml: ∂V/∂θ = k r² θ − m g e sin θ, no values;
    k r² > m g e (assumed) makes it increasing, so θ = 0 is the only root. Without the
    assumption the sign of k r² − m g e is open: the exact route gives θ = 0, where every
    term vanishes, and says that other equilibria may exist, not that it is the only one."""
    path = PROBLEMS / "edges" / "eccentric-wheel-spring.yaml"
    solution = equilibria_exact.solve(None, build_model(load_file(path)), Options())
    assert [(eq.at, eq.stability.value) for eq in solution.answers.equilibria] == [({"theta": 0}, "stable")]
    assert any("which is positive by the assumptions" in w for w in solution.warnings)
    open_bound = tmp_path / "w.yaml"
    open_bound.write_text(path.read_text(encoding="utf-8").replace("assumptions: [k*r**2 > m*g*e]\n", ""))
    unproved = solve_problem(build_model(load_file(open_bound)), Options(route=RouteChoice.EXACT)).solutions[0]
    assert [eq.at for eq in unproved.answers.equilibria] == [{"theta": 0}]
    assert not any("is its only root" in w for w in unproved.warnings)
    assert any("other equilibria may exist" in w.lower() for w in unproved.warnings)
