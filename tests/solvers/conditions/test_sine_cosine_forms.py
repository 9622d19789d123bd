"""The roots of a polynomial in sin p and cos p, by its form (condition_roots.py,
polynomial.py): a quadratic form plus a constant by the double angle, t = tan p; the
mixed forms whose t = tan(p/2) is a quartic are said to have no closed form a reader
uses (sympy's solve spent minutes on one). Checked against the equation at numbers."""

from __future__ import annotations

import math
import random

import pytest
import sympy as sp

from rbdsolve.solvers.conditions.condition_roots import _double_angle
from rbdsolve.solvers.conditions.polynomial import sine_cosine_quartic

P, g, m, a, b = sp.symbols("P g m a b", positive=True)
x = sp.Symbol("phi0", positive=True)


@pytest.mark.parametrize("factor", [
    3 * P * sp.sin(2 * x) - 3 * g * m * sp.cos(x) ** 2 + 4 * g * m,  # the ladder's N_B at the release
    a * sp.sin(x) ** 2 - b * sp.sin(x) * sp.cos(x) + a * sp.cos(2 * x) - b,
    a * sp.cos(x) ** 2 + b * sp.sin(x) * sp.cos(x) - a,  # c = b: tan p's degree drops, p = ±π/2
])
def test_each_double_angle_root_solves_the_equation(factor) -> None:
    """Each real root makes the factor zero (to 30 digits), and every sign change of the
    factor over one turn has a root there (modulo 2π)."""
    roots = _double_angle(factor, x)
    assert roots
    rng = random.Random(7)
    for _ in range(5):
        point = {s: sp.Float(rng.uniform(0.5, 3), 30) for s in (P, g, m, a, b)}
        at = factor.xreplace(point)
        real = []
        for r in roots:
            z = sp.N(r.xreplace(point), 30)
            if abs(sp.im(z)) < 1e-25:
                real.append(float(sp.re(z)))
                assert abs(sp.N(at.xreplace({x: sp.re(z)}), 30)) < 1e-25
        f = sp.lambdify(x, at, "math")
        step = 2 * math.pi / 4000
        for k in range(4000):
            u, v = -math.pi + k * step, -math.pi + (k + 1) * step
            if f(u) * f(v) < 0:
                assert any(abs((r - u + math.pi) % (2 * math.pi) - math.pi) <= 2 * step for r in real), (u, real)


@pytest.mark.parametrize("expr, quartic", [
    (-18 * P * sp.sin(x) * sp.cos(x) + 12 * P * sp.sin(x) + 9 * g * m * sp.cos(x) ** 2 - 10 * g * m, True),
    (a * sp.sin(x) + b * sp.cos(x) + g, False),  # linear: the half angle
    (a * sp.sin(2 * x) + b * sp.cos(x) ** 2 + g, False),  # a quadratic form: the double angle
    (a * sp.sin(x) ** 3 + b * sp.sin(x) + g, False),  # in sin p alone
    (a * sp.cos(x) + b * sp.sin(x) ** 2 + g, False),  # cos p with sin² p: in cos p alone
    (a * sp.sin(x) ** 2 * sp.cos(x) + b * sp.sin(x), True),
])
def test_which_forms_are_quartics_in_the_half_angle(expr, quartic: bool) -> None:
    assert sine_cosine_quartic(expr, x) is quartic
