"""Values that leave one parameter open but decide a stability for each of its values
(a new user's trial). A bead of mass m on a hoop of radius R turning at Ω about its
vertical diameter, tied by a spring k of zero natural length to the hoop's top; θ from
the bottom. By hand, in the hoop's frame,

    V' = −m g R cos θ + k R² (1 + cos θ) − ½ m Ω² R² sin² θ,
    K(π) = ∂²V'/∂θ² at θ = π = R (R k − g m − Ω² R m),

so with m = R = k = 1 and g = 10 given, K(π) = −9 − Ω² < 0 for every Ω: the top is
unstable. rbdsolve printed "Depends: … as k passes its critical value" there, k_c =
m (Ω² + g/R), though k is given (1, below k_c = Ω² + 10 for every Ω).
"""

from __future__ import annotations

import random

import sympy as sp

import rbdsolve

SCENE = """\
title: a bead on a turning hoop, tied to the top
parameters: [m, R, k, g, Omega]
values: {m: 1, R: 1, k: 1, g: 10}
coordinates: [theta]
gravity: [0, -g, 0]
frames:
  hoop: {axis: y, rate: Omega}
points:
  P: R * [sin(theta)*cos(Omega*t), -cos(theta), -sin(theta)*sin(Omega*t)]
  Top: [0, R, 0]
bodies:
  bead: {shape: particle, mass: m, at: P}
springs:
  s: {stiffness: k, between: [P, Top]}
questions:
  - equilibria: {frame: hoop}
"""


def test_the_top_is_unstable_for_every_rate_with_the_values_given(tmp_path) -> None:
    path = tmp_path / "hoop.yaml"
    path.write_text(SCENE)
    (solution,) = rbdsolve.solve(path, budget=1200.0)  # a budget far from the work
    (top,) = [e for e in solution.answers.equilibria if e.at["theta"] == sp.pi]
    assert top.stability.value == "unstable"
    (K,) = top.hessian
    (Omega,) = [s for s in K.free_symbols if s.name == "Omega"]
    given = {s: {"m": 1, "R": 1, "k": 1, "g": 10}[s.name] for s in K.free_symbols if s is not Omega}
    rng = random.Random(3)
    for _ in range(100):  # the hand's K(π) = −9 − Ω², and rbdsolve's, at rates on both sides of 3
        rate = rng.uniform(0.01, 30)
        assert abs(float(K.xreplace({**given, Omega: rate})) - (-9 - rate**2)) < 1e-9
    # the cases still say where that holds, in k: unstable below k_c = m (Ω² + g/R)
    assert [c.stability.value for c in top.stability_cases] == ["unstable", "stable"]
