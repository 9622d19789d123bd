"""An inverted rod held at its top by a spring of natural length, k open (a new user's
trial): ∂V/∂θ = 0 reduces to θ = 0 beside an irreducible quintic, and the exact route
refused the whole question ("an exact list would leave solutions out"), though the
question was the upright position's least stiffness.

By hand: the rod OA (mass m, length l) stands on a pivot O, A = l (−sin θ, cos θ); the
spring (k, natural length c) runs from A to W = (c, l), unstretched upright. For small
θ its stretch is l θ, so V ≈ m g (l/2)(1 − θ²/2) + ½ k l² θ², K = ∂²V/∂θ² at 0 =
k l² − m g l/2: stable for k > k_c = m g/(2 l) (9.81 N/m at m = 2 kg, l = 1 m). Now the
exact route lists θ = 0 with that case split and says the rest is not listed; with k
given, the numeric route (chosen from the structure) lists every equilibrium, and
θ = 0's curvature is k l² − m g l/2 there."""

from __future__ import annotations

import pytest
import sympy as sp

from rbdsolve.solvers.equilibria.answers import Stability

from conftest import solved_scene

ROD = """\
parameters: [m, l, c, k, g]
values: {m: 2 kg, l: 1 m, c: 30 cm, g: 9.81 m/s^2VALUES}
coordinates: [theta]
gravity: [0, -g]
points:
  O: [0, 0]
  A: l*[-sin(theta), cos(theta)]
  W: [c, l]
bodies:
  rod: {shape: rod, mass: m, length: l, at: "l/2*[-sin(theta), cos(theta)]", angle: theta}
springs:
  s: {stiffness: k, between: [A, W], natural_length: c}
questions:
  - equilibria: {for: k}
"""


def _solved(tmp_path, values: str = ""):
    return solved_scene(tmp_path, ROD.replace("VALUES", values), "rod.yaml")


def test_the_upright_position_is_listed_with_its_least_stiffness(tmp_path) -> None:
    solution = _solved(tmp_path)
    assert solution.solved and solution.route == "exact"
    (upright,) = solution.answers.equilibria
    assert [sp.simplify(v) for v in upright.at.values()] == [0]
    (critical,) = solution.answers.critical
    assert float(critical.value.xreplace({sp.Symbol("m", positive=True): 2, sp.Symbol("g", positive=True): 9.81,
                                          sp.Symbol("l", positive=True): 1})) == pytest.approx(9.81, rel=1e-12)
    (said,) = [w for w in solution.warnings if "degree 5" in w]
    assert "Other equilibria may exist" in said


@pytest.mark.parametrize("k, stable", [(5, False), (20, True)])
def test_with_k_given_every_equilibrium_is_searched(tmp_path, k, stable) -> None:
    solution = _solved(tmp_path, f", k: {k} N/m")
    assert solution.solved and solution.route == "numeric"
    (upright,) = [e for e in solution.answers.equilibria if abs(e.at["theta"]) < 1e-9]
    assert upright.curvatures == pytest.approx((k * 1.0 - 2 * 9.81 * 1.0 / 2,), rel=1e-9)
    assert (upright.stability is Stability.STABLE) is stable
