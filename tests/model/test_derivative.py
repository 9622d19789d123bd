"""model/derivative.py: ∂e/∂x is the very expression sympy.diff gives (the oracle), on
the forms a model has and on forms where sympy's order of operations shows (a power of
a sum whose derivative is a sum: sympy distributes the exponent into it)."""

from __future__ import annotations

import itertools

import sympy as sp

from rbdsolve.model.derivative import derivative
from rbdsolve.model.state import t, user_function

x, y = sp.symbols("x y", real=True)
m, r, g = sp.symbols("m r g", positive=True)
theta = user_function("theta")(t)
PIECES = [sp.Integer(3), sp.Rational(-1, 4), m * r**2, x, y**2, x * y, sp.sqrt(x), 1 / x, sp.sin(x - y),
          sp.cos(x) ** 2, sp.cos(2 * x + y), (x + x * y) ** 3, (x - y) ** 2, m * (sp.cos(x) + 2 * sp.sin(y)),
          sp.exp(x * y), x**y, theta, sp.sin(theta * x), sp.Abs(x), (1 + sp.cos(x)) ** -1]


def test_every_combination_agrees_with_sympy_diff_exactly() -> None:
    for p, q in itertools.combinations(PIECES, 2):
        for e in (p + q, p * q, p * q + g * p, (p + g) * q):
            for v in (x, y, t):
                assert derivative(e, v) == sp.diff(e, v), (e, v)


def test_a_lagrangian_and_its_rules() -> None:
    L = sp.Rational(7, 8) * m * r**2 * y**2 + m * r**2 * sp.cos(x) * y / 4 + 2 * g * m * r * sp.cos(x)
    assert derivative(L, y) == sp.Rational(7, 4) * m * r**2 * y + m * r**2 * sp.cos(x) / 4
    assert derivative(L, x) == -m * r**2 * sp.sin(x) * y / 4 - 2 * g * m * r * sp.sin(x)
    assert derivative(L, g) == 2 * m * r * sp.cos(x) and derivative(L, sp.Symbol("k")) == 0


def test_a_matrix_is_differentiated_entry_by_entry_as_matrix_diff_does() -> None:
    from rbdsolve.model.derivative import matrix_derivative

    for M in (sp.Matrix([[x * sp.sin(y), (x - y) ** 2], [m * r, theta]]), sp.ImmutableMatrix([x**2, sp.cos(x * y)])):
        for v in (x, t):
            mine, theirs = matrix_derivative(M, v), M.diff(v)
            assert mine == theirs and type(mine) is type(theirs)
