"""The numeric route's rounding of ∂V/∂q and K relative to the terms they sum
(solvers/numeric/numeric_model.py, ROUNDING_UNITS): at and near a degenerate equilibrium,
where those terms cancel, an eigenvalue of K must be said neutral rather than an
oscillation of period 10⁸ s (solvers/modes/numeric.py, ``stiffness_rounding``), and a
root's stated error must cover how far rounding moves it (solvers/equilibria/numeric.py,
``_error``).

By hand (a new user's scene): a uniform rod (m, l) on a pivot O at its lower end, θ from
the upward vertical, its point A at height a tied by two springs (k, natural length L0)
to (±d, a). V(θ) = m g (l/2) cos θ + Σ ½ k (ℓ± − L0)², ℓ±² = (a sin θ ∓ d)² + a² (cos θ −
1)². At θ = 0 each ℓ = d has ℓ' = ∓a and ℓ'' = 0, so V''(0) = 2 k a² − m g l/2 and, with
M = m l²/3, λ = (2 k a² − m g l/2)/(m l²/3): zero at k = m g l/(4 a²) = 3.83203125 N/m for
m = 1, l = 1, a = 0.8, g = 9.81. Just above it the roots near 0 are found below from V
with mpmath at 40 digits."""

from __future__ import annotations

import json

import mpmath
import pytest
from click.testing import CliRunner

from rbdsolve.cli import main

ROD = """\
parameters: {{m: mass, l: length, a: height, d: half width, L0: natural length, k: stiffness, g: gravity}}
values: {{m: 1, l: 1, a: 4/5, d: 1/2, L0: 3/10, k: {k}, g: 981/100}}
coordinates: [theta]
gravity: [0, -g]
points:
  O: [0, 0]
  A: a*[sin(theta), cos(theta)]
  G: l/2*[sin(theta), cos(theta)]
bodies:
  rod: {{shape: rod, mass: m, length: l, at: G, angle: theta, axis: y}}
springs:
  left: {{stiffness: k, between: [A, [-d, a]], natural_length: L0}}
  right: {{stiffness: k, between: [A, [d, a]], natural_length: L0}}
questions:
  - {question}
"""

CRITICAL = 9.81 / (4 * 0.8**2)


def _answer(tmp_path, k: str, question: str) -> dict:
    path = tmp_path / "rod.yaml"
    path.write_text(ROD.format(k=k, question=question), encoding="utf-8")
    result = CliRunner().invoke(main, ["solve", str(path), "--format", "json", "--route", "numeric"])
    found = json.loads(result.stdout)["results"][0]
    assert found["ok"] and found["route"] == "numeric", found
    return found


def test_at_the_critical_stiffness_the_mode_is_neutral(tmp_path) -> None:
    answers = _answer(tmp_path, "981/256", "modes: {about: {theta: 0}}")["answers"]  # = m g l/(4 a²) exactly
    assert answers["motions"] == ["neutral"]
    assert answers["frequencies"] == [None]
    assert abs(answers["eigenvalues"][0]) <= answers["absolute_errors"][0]


@pytest.mark.parametrize("factor", [0.99, 1.01])
def test_on_either_side_the_sign_of_lambda_is_told(tmp_path, factor: float) -> None:
    k = CRITICAL * factor
    answers = _answer(tmp_path, repr(k), "modes: {about: {theta: 0}}")["answers"]
    expected = (2 * k * 0.8**2 - 9.81 / 2) / (1 / 3)
    assert answers["eigenvalues"][0] == pytest.approx(expected, rel=1e-9)
    assert answers["motions"] == (["oscillation"] if factor > 1 else ["growth"])
    assert answers["absolute_errors"][0] < 1e-10 * abs(expected)


def test_a_root_near_a_degenerate_one_is_within_its_stated_error(tmp_path) -> None:
    """k = 3.83203508203125, the critical value times 1 + 1e-6: a pitchfork's branch at
    θ ≈ 0.0018257, where H is 1e-6 of its size and ∂V/∂q rounds to almost 0 at any point
    within ~1e-11 of the root (a root 7e-12 off was said within 4e-16)."""
    found = _answer(tmp_path, "3.83203508203125", "equilibria")
    near = [e["at"]["theta"] for e in found["answers"]["equilibria"] if 0 < e["at"]["theta"] < 0.1]
    assert len(near) == 1
    a, d, L0, g, k = (mpmath.mpf(x) for x in ("0.8", "0.5", "0.3", "9.81", "3.83203508203125"))

    def V(t):
        stretch = [mpmath.sqrt((a * mpmath.sin(t) - s * d) ** 2 + a**2 * (mpmath.cos(t) - 1) ** 2) - L0 for s in (1, -1)]
        return g / 2 * mpmath.cos(t) + sum(k / 2 * x**2 for x in stretch)

    with mpmath.workdps(40):
        reference = mpmath.findroot(lambda t: mpmath.diff(V, t), mpmath.mpf(near[0]))
    assert 1e-3 < reference < 3e-3
    assert abs(near[0] - float(reference)) <= found["error_estimate"] * max(abs(near[0]), 1.0)
