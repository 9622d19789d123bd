"""The numeric routes' error bounds: zero eigenvalues, ill-conditioned mass matrices and
zero principal moments, and strict JSON out of each.

Expected values are derived by hand below (and solved in mpmath at 50 digits), not
taken from rbdsolve's output.
"""

from __future__ import annotations

import json
import math
from fractions import Fraction

import mpmath
import pytest

from rbdsolve.errors import UnsolvedError
from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.render.json import render_report
from rbdsolve.solvers import Options, RouteChoice, solve_problem
from rbdsolve.solvers.modes.answers import Motion
from rbdsolve.solvers.modes.numeric import classify

from conftest import CART_PENDULUM

NUMERIC = Options(route=RouteChoice.NUMERIC)

CART = CART_PENDULUM + """\
values: {m: 1, M: 2, l: 1, g: 981/100}
questions:
  - modes: {about: {x: 0, theta: 0}}
  - equilibria
"""

# Two unit particles at A = (u + v, 0) and B = (0, u + (1 + d) v), springs k and 3k on u
# and v: T = ½ (u̇ + v̇)² + ½ (u̇ + (1 + d) v̇)², so M = [[2, 2 + d], [2 + d, 1 + (1 + d)²]]
# with det M = d²: M is ill-conditioned as d → 0 (cond M ≈ 16/d²); K = diag(k, 3k).
ILL = """
parameters: {d: small, k: stiffness}
coordinates: [u, v]
points:
  A: [u + v, 0]
  B: [0, u + (1 + d) * v]
  U: [u, 3]
  V: [v, 5]
  U0: [0, 3]
  V0: [0, 5]
bodies:
  a: {shape: particle, mass: 1, at: A}
  b: {shape: particle, mass: 1, at: B}
springs:
  s1: {stiffness: k, between: [U, U0]}
  s2: {stiffness: 3*k, between: [V, V0]}
questions:
  - modes: {about: {u: 0, v: 0}}
"""

ROD = """
parameters: {m: mass, l: length}
values: {m: 1, l: 2}
points:
  G: [0, 0]
bodies:
  rod: {shape: rod, mass: m, length: l, at: G, angle: 0, axis: x}
questions:
  - inertia: {body: rod}
"""


def _solve(text: str, values: dict[str, Fraction] | None = None):
    model = build_model(load_text(text, "scene.yaml"))
    return solve_problem(model.with_values(values) if values else model, NUMERIC)


def _strict(report) -> dict:
    """The JSON line, read by a strict reader: NaN and Infinity tokens are refused."""

    def refuse(token: str):
        raise ValueError(f"not strict JSON: {token}")

    return json.loads(render_report(report), parse_constant=refuse)


def test_the_carts_free_translation_is_a_neutral_mode() -> None:
    report = _solve(CART)
    modes = report.solutions[0]
    a = modes.answers
    # By hand: K = diag(0, m g l), M = [[M + m, m l], [m l, m l²]],
    # det(K − λM) = λ (λ M m l² − (M + m) m g l): λ = 0 and (M + m) g/(M l) = 14.715.
    assert a.motions == (Motion.NEUTRAL, Motion.OSCILLATION)
    assert abs(a.eigenvalues[0]) <= a.absolute_errors[0] and 0 < a.absolute_errors[0] < 1e-12
    assert abs(a.eigenvalues[1] - 14.715) <= a.absolute_errors[1] < 1e-12
    assert a.relative_errors[0] is None and a.frequencies[0] is None
    assert a.shapes[0] == pytest.approx((1.0, 0.0), abs=1e-12)  # the whole system drifts
    assert math.isfinite(modes.error_estimate)
    line = _strict(report)
    assert line["results"][0]["answers"]["motions"] == ["neutral", "oscillation"]
    assert line["results"][0]["answers"]["relative_errors"][0] is None


def test_every_error_estimate_is_finite_or_null() -> None:
    # The cart's equilibria form a continuum in x (a singular Hessian): whatever the
    # equilibria route estimates there, the solution carries a number or None.
    report = _solve(CART)
    for solution in report.solutions:
        assert solution.error_estimate is None or math.isfinite(solution.error_estimate)
    for result in _strict(report)["results"]:
        assert result["error_estimate"] is None or math.isfinite(result["error_estimate"])


def _exact_eigenvalues(d: Fraction, k: int = 1) -> list:
    """det(K − λM) = d² λ² − k (M₂₂ + 3 M₁₁) λ + 3k² = 0 with M₁₁ = 2,
    M₂₂ = 1 + (1 + d)², solved at 50 digits."""
    with mpmath.workdps(50):
        dd = mpmath.mpf(d.numerator) / d.denominator
        a, b, c = dd**2, k * (1 + (1 + dd) ** 2 + 6), mpmath.mpf(3 * k * k)
        root = mpmath.sqrt(b * b - 4 * a * c)
        return [2 * c / (b + root), (b + root) / (2 * a)]  # the small root without cancellation


DS = [Fraction(m, 10**e) for e in range(3, 10) for m in (1, 3)]


@pytest.mark.parametrize("d", DS, ids=str)
def test_the_bound_holds_for_an_ill_conditioned_mass_matrix(d: Fraction) -> None:
    solution = _solve(ILL, {"d": d, "k": Fraction(1)}).solutions[0]
    if d >= Fraction(1, 10**6):
        assert solution.solved, solution.error
    if d <= Fraction(1, 10**8):  # M's rounding is as large as its smallest eigenvalue d²/4
        assert not solution.solved
    if not solution.solved:
        assert any(why in solution.error for why in ("singular in floating point", "not positive definite"))
        return
    a = solution.answers
    for got, want, bound in zip(a.eigenvalues, _exact_eigenvalues(d), a.absolute_errors):
        assert abs(mpmath.mpf(got) - want) <= bound, (got, want, bound)
    # The small eigenvalue (≈ 3/8) is well determined whatever d: it stays an oscillation.
    assert a.motions[0] is Motion.OSCILLATION
    assert solution.error_estimate is not None and math.isfinite(solution.error_estimate)


def test_a_rods_zero_moment_has_an_absolute_bound_and_strict_json() -> None:
    report = _solve(ROD)
    solution = report.solutions[0]
    a = solution.answers
    # By hand: a thin rod along x: J = diag(0, m l²/12, m l²/12) = diag(0, 1/3, 1/3).
    assert abs(a.principal_moments[0]) <= a.absolute_error
    assert all(abs(x - 1 / 3) <= a.absolute_error for x in a.principal_moments[1:])
    assert math.isfinite(solution.error_estimate)
    answers = _strict(report)["results"][0]["answers"]
    assert answers["absolute_error"] == a.absolute_error


def test_nan_is_never_classified() -> None:
    # A comparison with NaN is False: it would fall through to 'growth'.
    with pytest.raises(UnsolvedError, match="not finite"):
        classify(float("nan"), 1.0)
    with pytest.raises(UnsolvedError, match="not finite"):
        classify(0.0, float("inf"))
    assert classify(-1e-20, 1e-15) is Motion.NEUTRAL
    assert classify(-1.0, 1e-15) is Motion.GROWTH


# Two particles (m, on light rods l) upright above pivots 3 apart, each held by a torsion
# spring (c1 on θ, c2 on φ): V = ½ c1 θ² + ½ c2 φ² + m g l (cos θ + cos φ), so about
# θ = φ = 0, M = m l² 1 and K = diag(c1 − m g l, c2 − m g l). With m = l = 1, g = 9.81,
# c1 = 5, c2 = 20: λ = −4.81 (growth at √4.81, along θ) and 10.19 (oscillation at √10.19,
# along φ).
UPRIGHT = """
parameters: {m: mass, l: length, g: gravity, c1: stiffness, c2: stiffness}
values: {m: 1, l: 1, g: 981/100, c1: 5, c2: 20}
coordinates:
  theta: {kind: angle, periodic: false}
  phi: {kind: angle, periodic: false}
gravity: [0, -g]
points:
  P: l * [sin(theta), cos(theta)]
  Q: [3 + l*sin(phi), l*cos(phi)]
bodies:
  a: {shape: particle, mass: m, at: P}
  b: {shape: particle, mass: m, at: Q}
springs:
  s1: {stiffness: c1, angle: theta}
  s2: {stiffness: c2, angle: phi}
questions:
  - modes: {about: {theta: 0, phi: 0}}
"""


def test_the_numeric_route_names_a_growth_and_an_oscillation_by_hand() -> None:
    a = _solve(UPRIGHT).solutions[0].answers
    assert a.eigenvalues == pytest.approx((-4.81, 10.19), abs=1e-12)
    assert a.motions == (Motion.GROWTH, Motion.OSCILLATION)
    assert a.growth_rates[0] == pytest.approx(math.sqrt(4.81), rel=1e-14) and a.growth_rates[1] is None
    assert a.frequencies[1] == pytest.approx(math.sqrt(10.19), rel=1e-14) and a.frequencies[0] is None
    assert [abs(x) for x in a.shapes[0]] == pytest.approx([1.0, 0.0], abs=1e-12)
    assert [abs(x) for x in a.shapes[1]] == pytest.approx([0.0, 1.0], abs=1e-12)
