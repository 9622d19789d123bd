"""A critical value counts only where it lies inside its parameter's range for every
value of the others the assumptions allow (condition_roots._positive_everywhere).

A rod of length l and mass m pivoted at O, its point B at 3l/4 from O joined by a
spring of stiffness k and natural length L₀ to A = (0, h) above O (seed 2039's scene
61). By hand, about θ = π (B straight up, the spring's length s = |h − 3l/4| = D/4 with
D = |4h − 3l|):

    V = −½ m g (l/2) cos θ + ½ k (s(θ) − L₀)²,   s² = h² + 9l²/16 + (3/2) h l cos θ,
    K = ∂²V/∂θ² = −m g l/4 + (3/4) k h l (1 − L₀/s),   M = m l²/12 + m l²/16 = 7 m l²/48,

so λ = K/M = 12 (3 h k D − 12 L₀ h k − g m D)/(7 l m D): its root in k,
k = g m D/(3 h (D − 4 L₀)), is positive only where D > 4 L₀; where D < 4 L₀ (the spring
compressed there) λ < 0 for every k. rbdsolve printed "growth when k < k_c, oscillation
when k > k_c" for every value, because its eight samples all had D > 4 L₀; the oracle's
draw (m 1.12743, l 1.36802, g 11.4662, k 151.271, h 0.357022, L₀ 1.26246) has λ = −174.12.
"""

from __future__ import annotations

import json
from pathlib import Path

import sympy as sp
from click.testing import CliRunner

from rbdsolve.cli import main
from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.solvers.conditions import condition_roots

SCENE = """\
title: a rod on a spring of natural length to a point above its pivot, its end offset
parameters: {m: mass, l: length, g: acceleration, k: stiffness, h: length, L0: length}
coordinates: [theta]
gravity: [0, -g]
points:
  G: l/4 * [sin(theta), -cos(theta)]
  B: 3*l/4 * [sin(theta), -cos(theta)]
  A: "[0, h]"
bodies:
  rod: {shape: rod, mass: m, length: l, at: G, angle: theta, axis: y}
springs:
  s: {stiffness: k, between: [B, A], natural_length: L0}
questions:
  - modes: {about: {theta: pi}}
"""


def _by_hand(m, l, g, k, h, L0):
    D = abs(4 * h - 3 * l)
    return 12 * (3 * h * k * D - 12 * L0 * h * k - g * m * D) / (7 * l * m * D)


def test_a_root_outside_the_range_where_the_others_are_otherwise_is_no_critical_value() -> None:
    model = build_model(load_text(SCENE))
    m, l, g, k, h, L0 = (model.symbols.parameters[n] for n in ("m", "l", "g", "k", "h", "L0"))
    D = sp.Abs(4 * h - 3 * l)
    lam = 12 * (3 * h * k * D - 12 * L0 * h * k - g * m * D) / (7 * l * m * D)
    condition_roots._roots_in.cache_clear()
    assert condition_roots.parameter_roots(lam, k, {}, model) is None
    # the oracle's point: growth, and no k_c > 0 there
    assert _by_hand(1.12743, 1.36802, 11.4662, 151.271, 0.357022, 1.26246) < -174


def test_a_root_positive_for_every_value_is_still_a_critical_value() -> None:
    """k a − b g: k = b g/a > 0 for every positive a, b, g (proved, not sampled)."""
    model = build_model(load_text(SCENE))
    k, l, g, h = (model.symbols.parameters[n] for n in ("k", "l", "g", "h"))
    assert condition_roots.parameter_roots(k * l - h * g, k, {}, model) == [g * h / l]


def test_the_modes_about_the_top_are_not_split_at_a_wrong_stiffness(tmp_path: Path) -> None:
    path = tmp_path / "rod.yaml"
    path.write_text(SCENE)
    out = CliRunner().invoke(main, ["solve", str(path), "--format", "json"])
    (result,) = json.loads(out.stdout)["results"]
    # no case split rbdsolve can say for every value: it says so, and asks for values
    assert not result["ok"] and result["answers"] is None
    assert "cannot split into cases" in result["error"] and "give values" in result["error"]
