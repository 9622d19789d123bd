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
