"""Modes about an equilibrium written θ₀ = ±acos(c) of several parameters: a rod pivoted
at O, its tip B joined by a spring of natural length L₀ to A = (0, h) above the pivot
(k, h, L₀ given; m, l, g left symbolic). By hand, with s the spring's length,

    s² = l² + h² + 2 l h cos θ,   V = −½ m g l cos θ + ½ k (s − L₀)²,
    ∂V/∂θ = sin θ (½ m g l − k l h (1 − L₀/s)),

so off θ = 0 and π the spring's length is s* = 2 k h L₀/(2 k h − m g) (a length only
where 2 k h > m g), cos θ₀ = c = (s*² − l² − h²)/(2 l h), and at θ₀

    K = ∂²V/∂θ² = k l² h² L₀ sin²θ₀/s*³ > 0,   M = m l²/3,   λ = K/M,

an oscillation wherever the equilibrium exists (sin²θ₀ = 1 − c² > 0 off θ = 0, π).
Expected values from this derivation, never from rbdsolve's output."""

from __future__ import annotations

import math
from pathlib import Path

import pytest
import sympy as sp

from rbdsolve.solvers.conditions.signs import over_sines

SCENE = """\
title: a rod on a spring of natural length to a point above its pivot
parameters: {m: mass, l: length, g: acceleration, k: stiffness, h: length, L0: length}
values: {k: 200 N/m, h: 0.5, L0: 60 cm}
coordinates: [theta]
gravity: [0, -g]
points:
  G: l/2 * [sin(theta), -cos(theta)]
  B: l * [sin(theta), -cos(theta)]
  A: "[0, h]"
bodies:
  rod: {shape: rod, mass: m, length: l, at: G, angle: theta, axis: y}
springs:
  s: {stiffness: k, between: [B, A], natural_length: L0}
questions:
  - equilibria
  - modes: {about: each}
  - modes
"""

K_, H_, L0_ = 200.0, 0.5, 0.6


def _by_hand(m: float, l: float, g: float) -> tuple[float, float]:
    """(cos θ₀, λ) of the off-axis equilibrium, or None where it does not exist."""
    s = 2 * K_ * H_ * L0_ / (2 * K_ * H_ - m * g)
    c = (s * s - l * l - H_ * H_) / (2 * l * H_)
    K = K_ * l * l * H_ * H_ * L0_ * (1 - c * c) / s ** 3
    return c, K / (m * l * l / 3)


@pytest.fixture(scope="module")
def solved(tmp_path_factory):
    import rbdsolve

    path = Path(tmp_path_factory.mktemp("rod")) / "rod.yaml"
    path.write_text(SCENE)
    # a budget far from the work (the equilibria take about 12 s alone, and a busy
    # machine may double that): what is tested is the answer, not the time
    return rbdsolve.solve(path, budget=1200.0)


@pytest.fixture(scope="module")
def each(solved):
    return solved[1].answers


def _off_axis(each):
    """The modes about ±acos(…), each with its λ as a function of (m, l, g)."""
    return [a for a in each.modes if any(isinstance(v, sp.Expr) and v.has(sp.acos) for v in a.about.values())]


def test_both_off_axis_equilibria_oscillate_with_the_hand_eigenvalue(each):
    off = _off_axis(each)
    assert len(off) == 2
    names = {s.name: s for a in off for s in a.eigenvalues[0].free_symbols}
    checked = 0
    for a in off:
        assert [m.value for m in a.motions] == ["oscillation"]
        assert sp.simplify(a.M[0, 0] - names["m"] * names["l"] ** 2 / 3) == 0  # m l²/3, not c² + (1 − c²)
        for m, l, g in [(1.0, 1.0, 9.81), (3.0, 0.8, 9.81), (0.5, 1.7, 1.62), (9.0, 1.2, 9.81)]:
            c, lam = _by_hand(m, l, g)
            if not -1 < c < 1:
                continue  # no off-axis equilibrium at these values
            at = {names["m"]: m, names["l"]: l, names["g"]: g, **_given(a.eigenvalues[0])}
            got = float(a.eigenvalues[0].xreplace(at))
            assert math.isclose(got, lam, rel_tol=1e-10), (m, l, g, got, lam)
            assert lam > 0
            checked += 1
    assert checked == 6  # three of the four samples have the equilibrium, for each of ±acos


def test_the_equilibria_call_both_off_axis_equilibria_stable(solved):
    """K > 0 wherever they exist (the derivation above): stable, not undetermined."""
    found = solved["equilibria"].answers.equilibria
    off = [e for e in found if any(isinstance(v, sp.Expr) and v.has(sp.acos) for v in e.at.values())]
    assert len(off) == 2
    assert {e.stability.value for e in off} == {"stable"}


def test_modes_without_about_take_an_equilibrium_the_equilibria_call_stable(solved):
    """Plain 'modes' takes the first stable equilibrium: θ = 0 and π depend on the
    parameters, ±acos(c) are stable wherever they exist (above), so it is one of those,
    an oscillation with the hand eigenvalue and no case past 2 k h = m g, where the
    equilibrium does not exist (it said "no stable equilibrium found")."""
    answer = solved[2]
    assert answer.error is None, answer.error
    modes = answer.answers
    (theta,) = modes.about.values()
    assert theta.has(sp.acos)
    assert [m.value for m in modes.motions] == ["oscillation"] and not modes.cases
    names = {s.name: s for s in modes.eigenvalues[0].free_symbols}
    for m, l, g in [(1.0, 1.0, 9.81), (0.5, 1.7, 1.62)]:
        _, lam = _by_hand(m, l, g)
        at = {names["m"]: m, names["l"]: l, names["g"]: g, **_given(modes.eigenvalues[0])}
        assert math.isclose(float(modes.eigenvalues[0].xreplace(at)), lam, rel_tol=1e-10)
    assert any("2 equilibria are stable" in w for w in answer.solution.warnings)


def _given(expr: sp.Expr) -> dict:
    """k, h and L₀ at the file's values (the answers keep them as symbols)."""
    table = {"k": K_, "h": H_, "L0": L0_}
    return {s: table[s.name] for s in expr.free_symbols if s.name in table}


def test_a_square_of_the_sine_is_taken_out_of_a_sign_only_where_it_divides():
    a, b = sp.symbols("a b", positive=True)
    c = (a - b) / (a + b)  # at θ₀ = acos(c): 1 − c² = 4 a b/(a + b)²
    at = [sp.acos(c)]
    value = sp.factor(sp.together((1 - c ** 2) * (a - 2 * b)))
    assert sp.simplify(over_sines(value, at) - (a - 2 * b)) == 0
    assert over_sines(a - 2 * b, at) == a - 2 * b  # nothing to take out
    assert over_sines(value, []) == value  # no inverse cosine among the coordinates
