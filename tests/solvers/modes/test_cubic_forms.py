"""modes/exact.py: a cubic with two roots nearly equal beside its spread keeps CRootOf.

Three masses on a line joined by springs 1, 10⁹, 1 (unit masses, the first one to a
wall): det(K − λM) = −(λ³ − 2000000003 λ² + 4000000002 λ − 1000000000). Its trig form
came out in some runs and CRootOf in others, by what had been solved before in the same
process; now it is CRootOf in every run."""

from __future__ import annotations

import sympy as sp

from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.solvers import solve_question
from rbdsolve.solvers.modes.exact import _near_double_root

x = sp.Symbol("x")

STIFF_MIDDLE = """
coordinates: [x1, x2, x3]
points: {P0: [0, 0], P1: [x1, 1], P2: [x2, 2], P3: [x3, 3]}
bodies:
  b1: {shape: particle, mass: 1, at: P1}
  b2: {shape: particle, mass: 1, at: P2}
  b3: {shape: particle, mass: 1, at: P3}
springs:
  s1: {stiffness: 1, between: [P0, P1]}
  s2: {stiffness: 1000000000, between: [P1, P2]}
  s3: {stiffness: 1, between: [P2, P3]}
questions:
  - modes: {about: {x1: 0, x2: 0, x3: 0}}
"""


def test_a_near_double_root_is_told_by_the_discriminant() -> None:
    # x³ − 3x + 1: p = −3, q = 1, 1 − x² = −(4p³ + 27q²)/(−4p³) = 81/108, far from 0
    assert not _near_double_root(sp.Poly(x**3 - 3 * x + 1, x))
    # roots 1, 1 + ε, 10 (ε = 10⁻⁸): Δ = Π(rᵢ − rⱼ)² ≈ ε²·81², p ≈ −27, so 1 − x² = Δ/(−4p³) ≈ 8·10⁻¹⁸, below 10⁻⁶
    near = sp.Poly(sp.expand((x - 1) * (x - 1 - sp.Rational(1, 10**8)) * (x - 10)), x)
    assert _near_double_root(near)
    # one real root (p > 0): no trig form to refuse
    assert not _near_double_root(sp.Poly(x**3 + x + 1, x))


def test_the_stiff_middle_spring_keeps_crootof() -> None:
    problem = load_text(STIFF_MIDDLE)
    solution = solve_question(problem.questions[0], build_model(problem))
    eigenvalues = solution.answers.eigenvalues
    assert all(isinstance(e, sp.CRootOf) for e in eigenvalues)
    # by hand: the stiff pair's 2k + 1 (k = 10⁹, mode (1, −1)/√2), moved by the soft
    # spring's coupling −1 to x3 by (1/√2)²/(2k) = 1/(4k), to O(1/k²)
    assert abs(sp.N(max(eigenvalues, key=lambda e: sp.N(e)), 30) - (2 * 10**9 + 1 + sp.Rational(1, 4 * 10**9))) < 1e-15
