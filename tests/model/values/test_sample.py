"""values.sample: ordering symbolic answers at a sample point never fails on a division
by zero at the all-ones point (found on a bead on a spring along a turning rod, where
the equilibrium is x = k L/(k − m Ω²): 1/0 with every symbol 1)."""

from __future__ import annotations

import math

import sympy as sp

from rbdsolve.model.values.values import sample


def test_a_division_by_zero_at_ones_is_sampled_elsewhere() -> None:
    k, m, W, L = sp.symbols("k m Omega L", positive=True)
    z = sample(k * L / (k - m * W**2), {})
    assert math.isfinite(z.real) and z.imag == 0


def test_values_given_are_used_as_they_are() -> None:
    k, m = sp.symbols("k m", positive=True)
    assert sample(k / m, {k: sp.Integer(6), m: sp.Integer(3)}) == 2


def test_no_number_at_all_is_nan_not_an_error() -> None:
    x = sp.Symbol("x")
    assert math.isnan(sample(sp.zoo * x, {}).real)
