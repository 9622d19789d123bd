"""q̈'s 2 × 2 determinants written directly, a d − b c, are Berkowitz's (the oracle)
once expanded, term for term: on entries that are sums with radicals, sines and cosines,
negative and rational coefficients and monomial denominators, as a two-coordinate M(q)
and h(q, q̇) hold. With a sum in a denominator Berkowitz's own is taken."""

from __future__ import annotations

import random

import sympy as sp

from rbdsolve.form.expansion import expanded
from rbdsolve.solvers.lagrange.accelerations import _det

th, ph, m, r, g, w = sp.symbols("theta phi m r g w", real=True)
ATOMS = [m, r, g, w, sp.sin(th), sp.cos(ph), sp.cos(ph - th), sp.sin(th) ** 2, sp.sqrt(3), sp.sqrt(6) * m,
         sp.Rational(-3, 4), sp.Rational(7, 2), 1 / m, r**-2, sp.sqrt(m)]


def _entry(rng: random.Random) -> sp.Expr:
    terms = []
    for _ in range(rng.randint(1, 5)):
        factors = [rng.choice(ATOMS) for _ in range(rng.randint(1, 4))]
        terms.append(rng.choice([1, -1, 2, sp.Rational(1, 3)]) * sp.Mul(*factors))
    return sp.Add(*terms)


def test_a_two_by_two_is_berkowitzs_expanded() -> None:
    rng = random.Random(37)
    for _ in range(60):  # Berkowitz's expanded is ~0.1 s each
        M = sp.Matrix(2, 2, lambda i, j: _entry(rng))
        assert sp.srepr(expanded(_det(M))) == sp.srepr(expanded(M.det(method="berkowitz"))), M


def test_larger_ones_and_sums_in_a_denominator_are_berkowitzs() -> None:
    rng = random.Random(38)
    M = sp.Matrix(3, 3, lambda i, j: _entry(rng))
    assert _det(M) == M.det(method="berkowitz")
    N = sp.Matrix(2, 2, lambda i, j: _entry(rng) + 1 / (m + 2 * r))
    assert _det(N) == N.det(method="berkowitz")
