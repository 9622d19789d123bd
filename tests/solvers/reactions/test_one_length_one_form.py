"""A spring's length written one way in the forces along the motion: its pull from the
positions had |d| = √(x² cos²α + (x sin α − l₀)²), V and the energy's ẋ² the tidied
√(x² − 2 l₀ x sin α + l₀²), and the two never cancelled: a hoop's least friction ran to
forty lines (a new user's trial), where by hand it is three.

A hoop (m, r) rolling on an incline at α, x up the slope, its centre tied to a point l₀
above its start by a spring (k, natural length l₀): by hand D = l₀² − 2 l₀ x sin α + x²
is the spring's length squared, the pull on the hoop −k (√D − l₀) d/√D with d = (x cos α,
x sin α − l₀), T = m ẋ² (a hoop rolling), so 2m ẍ = −V'(x) and m ẋ² = V(0) − V(x); N and
F follow from Newton's law across and along the slope. The test compares rbdsolve's N
and F along the motion with these at random values, and the least friction's length."""

from __future__ import annotations

import random

import sympy as sp

import rbdsolve
from conftest import HOOP_ON_INCLINE

SCENE = HOOP_ON_INCLINE


def _by_hand():
    """N and F along the motion: Newton's laws along and across the slope, ẍ from
    Lagrange (T = m ẋ², a hoop rolling) and ẋ² from the energy."""
    m, r, k, l0, al, g = sp.symbols("m r k l0 alpha g", positive=True)
    x = sp.Symbol("x", real=True)
    D = l0**2 - 2 * l0 * x * sp.sin(al) + x**2
    V = m * g * (x * sp.sin(al) + r * sp.cos(al)) + k * (sp.sqrt(D) - l0) ** 2 / 2
    xdd = -sp.diff(V, x) / (2 * m)  # M = 2m
    xd2 = (V.subs(x, 0) - V) / m  # m ẋ² = V(0) − V
    d = sp.Matrix([x * sp.cos(al), x * sp.sin(al) - l0])  # from W to the centre
    pull = -k * (sp.sqrt(D) - l0) * d / sp.sqrt(D)
    t, n = sp.Matrix([sp.cos(al), sp.sin(al)]), sp.Matrix([-sp.sin(al), sp.cos(al)])
    weight = sp.Matrix([0, -m * g])
    # along t: m ẍ = pull·t + weight·t + F_t (F_C is along −t in rbdsolve's axes); across: 0 = pull·n + weight·n + N
    F_along_t = m * xdd - pull.dot(t) - weight.dot(t)
    N = -(pull.dot(n) + weight.dot(n))
    return (m, r, k, l0, al, g, x), N, -F_along_t, xd2


def test_the_forces_along_the_motion_agree_with_newton_by_hand_and_stay_short(tmp_path) -> None:
    path = tmp_path / "hoop.yaml"
    path.write_text(SCENE, encoding="utf-8")
    (solution,) = rbdsolve.solve(path, budget=600.0)
    symbols, N, F, _ = _by_hand()
    found = solution.answers.along["C"]
    names = {str(s): s for s in symbols}
    rng = random.Random(7)
    for _ in range(4):
        point = {s: sp.Rational(rng.randint(20, 90), 100) for s in symbols}
        point[names["alpha"]] = sp.Rational(rng.randint(10, 60), 100)
        for key, hand in (("N_C", N), ("F_C", F)):
            value = found[key]
            value = value.xreplace({f: names["x"] for f in value.atoms(sp.Function) if str(f.func) == "x"})
            value = value.xreplace({s: names[str(s)] for s in value.free_symbols if str(s) in names})
            assert abs(sp.N((value - hand).xreplace(point), 30)) < 1e-20
    assert sp.count_ops(solution.answers.least_friction["C"]) < 120  # forty lines before
