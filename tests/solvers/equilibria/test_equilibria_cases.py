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


# By hand (R = 1, g = 9.81): Ω = 2 is below Ω_c = √9.81 ≈ 3.13 (θ = 0 stable, no off-axis
# equilibrium), Ω = 5 above it (θ = 0 unstable, ±acos(g/(R Ω²)) stable); θ = π is unstable.
@pytest.mark.parametrize("values, want", [
    ("values: {m: 1, R: 1, g: 9.81, Omega: 2}", {"0": "stable", "pi": "unstable"}),
    ("values: {m: 1, R: 1, g: 9.81, Omega: 5}", {"0": "unstable", "pi": "unstable", "acos(g/(Omega**2*R))": "stable",
                                                 "-acos(g/(Omega**2*R))": "stable"}),
])
def test_with_values_the_case_is_decided(values, want) -> None:
    report = solve_problem(build_model(load_text(HOOP + "\n" + values + "\n", "hoop.yaml")))
    (solution,) = [s for s in report.solutions if s.question == "equilibria"]
    at = {n: sp.Symbol(n, positive=True) for n in ("R", "g", "m", "Omega")}
    numbers = {at["R"]: 1, at["g"]: sp.Rational(981, 100), at["m"]: 1, at["Omega"]: 2 if "Omega: 2" in values else 5}
    existing = {str(eq.at["theta"]): eq.stability.value for eq in solution.answers.equilibria
                if bool(sp.sympify(_names(eq.exists_when)).subs(numbers))}
    assert existing == want


# A cylinder (m, r) rolling inside a fixed hollow cylinder (R): G on a circle of radius
# R − r, V = −m g (R − r) cos θ; rolling, it turns by −(R − r) θ/r, so
# T = ½ m (R − r)² θ̇² + ½ (m r²/2) ((R − r) θ̇/r)² = ¾ m (R − r)² θ̇².
# θ = 0: V'' = m g (R − r): stable iff R > r; ω² = m g (R − r)/(3/2 m (R − r)²) = 2g/(3(R − r)).
CYLINDER = """\
parameters: {m: mass, r: radius of the cylinder, R: radius of the hollow, g: gravity}
coordinates: [theta]
gravity: [0, -g]
points:
  G: (R - r)*[sin(theta), -cos(theta)]
bodies:
  cylinder: {shape: disk, mass: m, radius: r, at: G, angle: -(R - r)*theta/r}
questions:
  - equilibria
  - modes: {about: {theta: 0}}
"""


def test_without_the_assumption_the_condition_is_r_below_R() -> None:
    report = solve_problem(build_model(load_text(CYLINDER, "cylinder.yaml")))
    bottom = report.solutions[0].answers.equilibria[0]
    assert str(bottom.at["theta"]) == "0" and bottom.stability.value == "depends"
    stable = [c for c in bottom.stability_cases if c.stability.value == "stable"]
    R, r = sp.symbols("R r", positive=True)
    (case,) = stable
    assert sp.simplify(_names_in(case.when, R, r)) in (sp.Lt(r, R), sp.Gt(R, r))


def _names_in(when, R, r):
    return sp.parse_expr(str(when), local_dict={"R": R, "r": r})


def test_with_the_assumption_it_is_stable_and_the_frequency_is_real() -> None:
    report = solve_problem(build_model(load_text(CYLINDER + "assumptions: [R > r]\n", "cylinder.yaml")))
    equilibria, modes = report.solutions
    assert equilibria.answers.equilibria[0].stability.value == "stable"
    assert modes.solved and modes.answers.motions[0].value == "oscillation"
    R, r, g = sp.symbols("R r g", positive=True)
    (w,) = modes.answers.frequencies
    w = sp.parse_expr(str(w), local_dict={"R": R, "r": r, "g": g})
    for values in ({R: 2, r: 1, g: 9.81}, {R: 5, r: sp.Rational(1, 3), g: 1}):
        assert float(w.subs(values)) == pytest.approx(math.sqrt(2 * float(values[g]) / (3 * float(values[R] - values[r]))))


def test_stability_between_two_critical_rates_is_sampled() -> None:
    """Two beads on a turning rod (problems/conditions/beads-on-turning-rod.yaml): det K
    vanishes at two rates, K = [[k − 2mΩ², −mΩ²], [−mΩ², k − mΩ²]] by hand; at random
    k, m and Ω the printed case must agree with the signs of K's eigenvalues computed
    here (stable iff both are positive), and only the smaller root is a critical value
    (the stability does not change at the larger one)."""
    text = (PROBLEMS / "conditions" / "beads-on-turning-rod.yaml").read_text()
    (solution,) = solve_problem(build_model(load_text(text, "beads.yaml"))).solutions
    (eq,) = solution.answers.equilibria
    assert len(solution.answers.critical) == 1
    names = {n: sp.Symbol(n, positive=True) for n in ("m", "k", "a", "Omega")}
    rng = random.Random(11)
    for _ in range(40):
        m, k = rng.uniform(0.1, 5), rng.uniform(0.1, 50)
        Om = math.sqrt(k / m) * rng.uniform(0.05, 2.5)
        at = {names["m"]: m, names["k"]: k, names["Omega"]: Om}
        K11, K12, K22 = k - 2 * m * Om**2, -m * Om**2, k - m * Om**2
        mean, radius = (K11 + K22) / 2, math.hypot((K11 - K22) / 2, K12)
        stable = mean - radius > 0
        if abs(mean - radius) < 1e-9 * (abs(mean) + radius):
            continue  # on the boundary
        (case,) = [c for c in eq.stability_cases
                   if bool(sp.parse_expr(str(c.when), local_dict=names).subs(at))]
        assert case.stability.value == ("stable" if stable else "unstable")


# A bead on a circle of radius R − r, with the assumption R² > r² (not linear in any
# parameter, so it decides no sign by substitution, only the samples): V = −m g (R − r)
# cos θ, K = m g (R − r) at θ = 0 and −m g (R − r) at π (by hand). Under the assumption
# R > r: stable at 0, unstable at π, with no case R < r (issue 38).
SQUARED = """\
parameters: {m: mass, R: outer radius, r: inner radius, g: gravity}
assumptions: [R**2 > r**2]
coordinates: [theta]
gravity: [0, -g]
points:
  P: (R - r)*[sin(theta), -cos(theta)]
bodies:
  bead: {shape: particle, mass: m, at: P}
questions:
  - equilibria
"""


def test_a_case_the_assumptions_rule_out_is_no_case() -> None:
    (solution,) = solve_problem(build_model(load_text(SQUARED, "bead.yaml"))).solutions
    found = {str(eq.at["theta"]): eq for eq in solution.answers.equilibria}
    assert found["0"].stability.value == "stable" and found["0"].stability_cases == ()
    assert found["pi"].stability.value == "unstable" and found["pi"].stability_cases == ()
    assert solution.answers.critical == ()
    rng = random.Random(38)
    for _ in range(20):  # the hand K at 0 is positive wherever the assumption holds
        R, r, m, g = (rng.uniform(0.1, 5) for _ in range(4))
        if R**2 > r**2:
            assert m * g * (R - r) > 0


# The elastic pendulum (problems/forces/elastic-pendulum.yaml), by hand: V = ½ k (r − L)²
# − m g r cos θ with r ≥ 0 a polar distance; θ = π, r = L − m g/k is an equilibrium only
# where r > 0, i.e. k > k_c = m g/L. At k = k_c it is r = 0, the spring at zero length
# pushing with k L along no direction: no equilibrium (V has a cone at P = O), so the
# printed condition is strict. Sampled below k_c, at it and above it (m = 1, g = 10,
# L = 1: k_c = 10).
ELASTIC = (PROBLEMS / "forces" / "elastic-pendulum.yaml").read_text()


def test_the_elastic_pendulums_inverted_equilibrium_exists_where_k_exceeds_k_c() -> None:
    report = solve_problem(build_model(load_text(ELASTIC, "elastic.yaml")))
    (solution,) = report.solutions
    (inverted,) = [eq for eq in solution.answers.equilibria if eq.at["theta"] == sp.pi]
    assert isinstance(inverted.exists_when, sp.StrictGreaterThan)
    k, g, m, L = (sp.Symbol(n, positive=True) for n in ("k", "g", "m", "L"))
    condition = _elastic_names(inverted.exists_when)
    for value, held in ((8, False), (10, False), (sp.Rational(101, 10), True), (12, True)):
        assert bool(condition.subs({k: value, g: 10, m: 1, L: 1})) is held


@pytest.mark.parametrize("k, listed", [(8, {0}), (10, {0}), (12, {0, sp.pi})])
def test_the_elastic_pendulum_with_values_lists_the_inverted_one_only_past_k_c(k, listed) -> None:
    text = ELASTIC + f"values: {{m: 1, g: 10, L: 1, k: {k}}}\n"
    report = solve_problem(build_model(load_text(text, "elastic.yaml")))
    (solution,) = report.solutions
    assert solution.solved, solution.error
    existing = {eq.at["theta"] for eq in solution.answers.equilibria
                if bool(_elastic_names(eq.exists_when).subs({sp.Symbol(n, positive=True): v for n, v in
                                                             (("k", k), ("g", 10), ("m", 1), ("L", 1))}))}
    assert existing == listed


def _elastic_names(expr: sp.Basic) -> sp.Basic:
    return sp.sympify(sp.parse_expr(str(expr), local_dict={n: sp.Symbol(n, positive=True) for n in ("k", "g", "m", "L")}))
