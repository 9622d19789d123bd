"""A root found by squaring must solve the unsquared equations: a bead on a rod turning at
Ω about an axis it misses by d, on a spring (k, natural length L) to the axis. By hand,
∂V'/∂s = s (k (1 − L/√(d² + s²)) − m Ω²), and the squared form's root s*² = k² L²/(k −
m Ω²)² − d² solves it only where k − m Ω² > 0. The condition rbdsolve gives is sampled on
both sides against ∂V'/∂s evaluated at s* (floating point, by hand's formula)."""

from __future__ import annotations

import math
import random
from pathlib import Path

import sympy as sp

from rbdsolve.model.build import build_model
from rbdsolve.problem import load_file
from rbdsolve.solvers.equilibria.angles import angle_of
from rbdsolve.solvers.equilibria.cases import unsquared_where
from rbdsolve.solvers.equilibria.exact import listing
from rbdsolve.solvers.lagrange.frames import model_in_frame

BEAD = Path(__file__).resolve().parents[3] / "problems" / "frames" / "bead-on-offset-turning-rod.yaml"


def _gradient_at_root(k, m, d, L, W) -> float:
    s2 = (k * L / (k - m * W**2)) ** 2 - d**2
    s = math.sqrt(s2)
    return s * (k * (1 - L / math.sqrt(d**2 + s2)) - m * W**2)


def test_the_off_centre_root_exists_only_where_k_exceeds_m_omega_squared() -> None:
    scene = build_model(load_file(BEAD))
    model = model_in_frame(scene.problem.questions[0], scene)  # the rod's frame: V' holds no t
    off = [x.at for x in listing(model).equilibria if x.at[model.q[0]] != 0]
    assert len(off) == 2
    (condition,) = unsquared_where(off[0], model)
    symbols = {s.name: s for s in condition.free_symbols}
    rng = random.Random(5)
    sides = set()
    for _ in range(200):
        k, m, L = rng.uniform(5, 30), rng.uniform(0.1, 1), rng.uniform(0.1, 0.3)
        d, W = L + rng.uniform(0.01, 0.3), rng.uniform(0.5, 20)
        if (k * L / (k - m * W**2)) ** 2 <= d**2:
            continue  # s* not real here at all
        value = float(condition.xreplace({symbols[n]: v for n, v in
                                          {"k": k, "m": m, "d": d, "L": L, "Omega": W}.items() if n in symbols}))
        solves = abs(_gradient_at_root(k, m, d, L, W)) < 1e-9 * k
        assert (value > 0) == solves, (k, m, d, L, W, value)
        sides.add(solves)
    assert sides == {True, False}  # both sides were sampled


def test_an_angle_whose_sine_sign_is_open_is_asin_where_its_cosine_is_positive() -> None:
    beta = sp.Symbol("beta", real=True)  # an incline tilted either way
    s = -3 * sp.pi * sp.sin(beta) / 4
    c = sp.sqrt(16 - 9 * sp.pi**2 * sp.sin(beta) ** 2) / 4
    found = angle_of(s, c, {})
    assert found == -sp.asin(3 * sp.pi * sp.sin(beta) / 4)
    for b in (0.2, -0.2, 0.35, -0.35):  # sin θ₀ = −(3π/4) sin β with cos θ₀ > 0, by hand
        theta = float(found.subs(beta, b))
        assert math.isclose(math.sin(theta), -3 * math.pi * math.sin(b) / 4, rel_tol=1e-12) and math.cos(theta) > 0
    assert angle_of(s, -c, {}).func is sp.atan2  # the other root: no closed sign for either, atan2 kept


PENDULUM_SPRING = """
title: A rod hanging from O, its end A tied by a spring (natural length h) to C, h above O
parameters: {m: mass, l: length, h: length, k: stiffness, g: gravity}
coordinates: [theta]
gravity: [0, -g]
points:
  C: [0, h]
  G: l/2*[sin(theta), -cos(theta)]
  A: l*[sin(theta), -cos(theta)]
bodies:
  rod: {shape: rod, mass: m, length: l, at: G, angle: theta, axis: y}
springs:
  s: {stiffness: k, between: [A, C], natural_length: h}
questions:
  - equilibria: {for: k}
"""


def test_a_root_of_a_perfect_square_is_taken_at_the_hanging_position() -> None:
    """By hand: |AC| = ρ(θ) = √(h² + 2 h l cos θ + l²), V = −½ m g l cos θ + ½ k (ρ − h)²;
    at θ = 0, ρ = h + l, ρ' = 0, ρ'' = −h l/(h + l), so K = ½ m g l − k h l²/(h + l):
    no √(h² + 2 h l + l²) left in it (a new user's trial printed one)."""
    from rbdsolve.api import loads
    from rbdsolve.solvers import solve_question

    model = build_model(loads(PENDULUM_SPRING))
    solution = solve_question(model.problem.questions[0], model)
    m, l, h, k, g = (sp.Symbol(n, positive=True) for n in "mlhkg")
    hanging = next(e for e in solution.answers.equilibria if list(e.at.values()) == [0])
    (K,) = hanging.hessian
    assert sp.simplify(K - (m * g * l / 2 - k * h * l**2 / (h + l))) == 0
    assert not K.atoms(sp.Pow) & {p for p in K.atoms(sp.Pow) if p.exp == sp.Rational(1, 2)}
