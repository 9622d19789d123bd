"""An equilibrium's angle in the form an exam writes it (solvers/equilibria/angles.py):
from the sine where the sine has no root in it and the cosine has. Each expectation is
checked against the sine and cosine it must have, by hand."""

from __future__ import annotations

import json
import math

import sympy as sp
from click.testing import CliRunner

from conftest import PLATE_ON_A_CORNER
from rbdsolve.cli import main
from rbdsolve.solvers.equilibria.angles import angle_of

C, R, g, m = sp.symbols("C R g m", positive=True)
S = C / (m * g * R)  # a wheel held by a couple: m g R sin θ₀ = C
ROOT = sp.sqrt(m * g * R - C) * sp.sqrt(m * g * R + C) / (m * g * R)  # cos θ₀ = ±√(1 − S²) where C ≤ m g R


def test_the_two_roots_of_a_sine_read_asin_and_pi_minus_asin() -> None:
    """cos θ₀ > 0: θ₀ = asin(S); cos θ₀ < 0 with S > 0: θ₀ = π − asin(S), in (−π, π];
    with S < 0: −π − asin(S)."""
    assert angle_of(S, ROOT, {}) == sp.asin(S)
    assert angle_of(S, -ROOT, {}) == sp.pi - sp.asin(S)
    assert angle_of(-S, -ROOT, {}) == -sp.pi + sp.asin(S)
    point = {C: 0.6, R: 0.2, g: 9.81, m: 0.5}
    for s, c in ((S, ROOT), (S, -ROOT), (-S, -ROOT)):
        theta = float(angle_of(s, c, {}).xreplace(point))
        assert math.isclose(math.sin(theta), float(s.xreplace(point)), rel_tol=1e-12)
        assert math.isclose(math.cos(theta), float(c.xreplace(point)), rel_tol=1e-12)
        assert -math.pi < theta <= math.pi


WHEEL = """title: a wheel on a fixed axle, a particle on its rim, held by a couple
parameters: {M: mass, m: mass, R: radius, C: moment, g: acceleration of gravity}
coordinates: [theta]
gravity: [0, -g]
points:
  P: R*[sin(theta), -cos(theta)]
bodies:
  wheel: {shape: disk, mass: M, radius: R, at: [0, 0], angle: theta}
  bob: {shape: particle, mass: m, at: P}
couples:
  drive: {on: wheel, moment: C}
questions:
  - equilibria
"""


def test_a_wheel_held_by_a_couple_lists_asin_first(tmp_path) -> None:
    """V = −m g R cos θ − C θ, ∂V/∂θ = m g R sin θ − C: sin θ₀ = C/(m g R), the lower root
    (cos θ₀ > 0, K = m g R cos θ₀ > 0) stable and listed first, π − asin(…) unstable."""
    result = _solved(tmp_path / "wheel.yaml", WHEEL)
    found = [(e["at"]["theta"], e["stability"]) for e in result["answers"]["equilibria"]]
    assert found == [("asin(C/(R*g*m))", "stable"), ("pi - asin(C/(R*g*m))", "unstable")]


def _solved(path, scene: str) -> dict:
    """The one question's result in the JSON of ``rbdsolve solve``, run as a user does."""
    path.write_text(scene, encoding="utf-8")
    out = CliRunner().invoke(main, ["solve", str(path), "--format", "json"])
    assert out.exit_code == 0, out.output
    (result,) = json.loads(out.stdout)["results"]
    return result


PLATE = PLATE_ON_A_CORNER


def test_a_numeric_root_in_the_sine_keeps_the_asin_form_and_the_critical_value_plain(tmp_path) -> None:
    """A new user's plate: its centre a/√2 from the corner, so by hand V = −(m g a/√2) cos θ
    − C θ and sin θ₀ = √2 C/(m g a): θ₀ = asin(√2 C/(a g m)) (stable) and π − asin(…),
    where C ≤ C_c = m g a/√2. √2 is no root of the parameters: it read acos(√(a²g²m² −
    2C²)/(a g m)) and C_c = √(a²g²m²/2)."""
    result = _solved(tmp_path / "plate.yaml", PLATE)
    found = [(e["at"]["theta"], e["stability"]) for e in result["answers"]["equilibria"]]
    assert found == [("asin(sqrt(2)*C/(a*g*m))", "stable"), ("pi - asin(sqrt(2)*C/(a*g*m))", "unstable")]
    assert result["answers"]["critical"] == [{"parameter": "C", "value": "sqrt(2)*a*g*m/2"}]
    point = {"C": 1.1, "a": 0.4, "g": 9.81, "m": 2.0}  # the sine by hand at a point where C < C_c
    theta = math.asin(math.sqrt(2) * point["C"] / (point["a"] * point["g"] * point["m"]))
    assert math.isclose(math.sqrt(2) / 2 * point["a"] * point["g"] * point["m"] * math.sin(theta), point["C"])
