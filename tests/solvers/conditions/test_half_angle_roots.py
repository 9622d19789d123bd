"""Roots in an angle of a sin p + b cos p + c by the half-angle tangent (condition_roots
._half_angle): a block pulled up a rough incline gives (μ cos α + sin α) M k² + … = 0, on
which sympy's solve spent 12 s of a new user's 16 s file. Each root checked by putting
it back in, by hand-picked numbers and at random symbolic points."""

from __future__ import annotations

import random

import sympy as sp

from rbdsolve.solvers.conditions.condition_roots import _half_angle

p = sp.Symbol("p", positive=True)


def test_numbers_by_hand() -> None:
    """sin p + cos p − 1 = 0 at p = 0 and p = π/2: (c − b) t² + 2 a t + (b + c) = −2t² + 2t,
    t = 0, 1."""
    roots = _half_angle(sp.sin(p) + sp.cos(p) - 1, p)
    assert sorted(roots, key=float) == [0, sp.pi / 2]


def test_c_equal_to_b_keeps_the_root_at_pi() -> None:
    """2 sin p + cos p + 1: c = b, so t's equation is linear, 2 t·2 + 2 = 0, t = −1/2, and
    p = π solves it too (sin π = 0, cos π = −1)."""
    roots = _half_angle(2 * sp.sin(p) + sp.cos(p) + 1, p)
    assert sp.pi in roots and len(roots) == 2
    for r in roots:
        assert abs(complex(sp.N((2 * sp.sin(p) + sp.cos(p) + 1).subs(p, r), 30))) < 1e-25


def test_symbolic_roots_solve_it() -> None:
    M, k, R, m, mu = sp.symbols("M k R m mu", positive=True)
    f = M * k**2 * (mu * sp.cos(p) + sp.sin(p)) + R**2 * m * (mu * sp.cos(p) + sp.sin(p)) - R**2 * m
    roots = _half_angle(f, p)
    assert len(roots) == 2
    rng = random.Random(7)
    for _ in range(5):
        point = {x: sp.Rational(rng.randint(5, 40), 10) for x in (M, k, R, m)} | {mu: sp.Rational(rng.randint(1, 9), 10)}
        for r in roots:
            value = sp.N(f.subs(point).subs(p, r.subs(point)), 30)
            assert abs(complex(value)) < 1e-20


def test_another_form_is_left_to_others() -> None:
    assert _half_angle(sp.sin(p) ** 2 + sp.cos(p), p) is None
    assert _half_angle(sp.sin(2 * p) + 1, p) is None
