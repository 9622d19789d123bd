"""The numeric modes route on long chains, against M and K derived by hand.

An n-link planar chain hangs from O, link k at angle θ_k from the downward vertical;
at θ = 0 every point moves horizontally, ∂x/∂θ_j = l for each link j above it.

- Point masses m at the link ends P_k = Σ_{j≤k} l e(θ_j): M_ij = m l² (n − max(i, j) + 1),
  and V = −m g Σ_k Σ_{j≤k} l cos θ_j gives K = diag(m g l (n − i + 1)).
- Uniform rods (mass m, length l, J = m l²/12 about the centre G_k = P_{k−1} + l/2 e(θ_k)),
  for i < j, M_ij = m l² (n − j + ½) (rod j contributes l · l/2, the n − j rods below
  it l · l); M_jj = m l² (n − j + ¼ + 1/12) = m l² (n − j + ⅓); K = diag(m g l (n − j + ½)).

The eigenvalues are compared with scipy's eigh of the hand matrices (relative 1e-10, far
above either side's rounding at these sizes), and at a smaller n each stated bound
|λ̂ − λ| ≤ absolute_errors is checked against the eigenvalues of the hand matrices at
40 digits (mpmath, Cholesky reduction written here).
"""

from __future__ import annotations

from fractions import Fraction

import mpmath
import numpy as np
import pytest
import scipy.linalg

from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.solvers import Options, RouteChoice, solve_problem

from conftest import chain, hand_matrices

G = Fraction(981, 100)
N = 40  # the chains' length: M and K have N² entries each
SMALL = 12  # the length at which the bounds are checked at 40 digits


def problem_text(n: int, rods: bool) -> str:
    """The chain with m = l = 1, g = 9.81, asked for its modes about θ = 0."""
    rest = ", ".join(f"th{k}: 0" for k in range(1, n + 1))
    return chain(n, rods).replace("questions: [modes]",
                                  f"values: {{m: 1, l: 1, g: {G}}}\nquestions:\n  - modes: {{about: {{{rest}}}}}")


def hand(n: int, rods: bool) -> tuple[list[list[Fraction]], list[list[Fraction]]]:
    """M and K at θ = 0 by the formulas of the module docstring (conftest.hand_matrices)."""
    return hand_matrices(n, rods, Fraction(1), Fraction(1), G)


def answers(n: int, rods: bool):
    report = solve_problem(build_model(load_text(problem_text(n, rods))), Options(route=RouteChoice.NUMERIC))
    solution = report.solutions[0]
    assert solution.solved, solution.error
    return solution.answers


@pytest.fixture(scope="module", params=[False, True], ids=["points", "rods"])
def long_chain(request):
    rods = request.param
    return answers(N, rods), hand(N, rods)


def test_M_and_K_are_the_hand_matrices(long_chain) -> None:
    got, (M, K) = long_chain
    for name, mine, theirs in (("M", got.M, M), ("K", got.K, K)):
        exact = np.array(theirs, dtype=float)
        assert np.max(np.abs(np.array(mine) - exact)) <= 1e-12 * np.max(np.abs(exact)), name


def test_the_eigenvalues_are_those_of_the_hand_matrices(long_chain) -> None:
    got, (M, K) = long_chain
    reference = scipy.linalg.eigh(np.array(K, dtype=float), np.array(M, dtype=float), eigvals_only=True)
    assert np.allclose(got.eigenvalues, reference, rtol=1e-10, atol=0)
    assert all(f is not None and f > 0 for f in got.frequencies)


def _eigenvalues_40_digits(M: list[list[Fraction]], K: list[list[Fraction]]) -> list:
    """λ of K a = λ M a: M = L Lᵀ, then the symmetric eigenvalues of L⁻¹ K L⁻ᵀ."""
    with mpmath.workdps(40):
        exact = lambda A: mpmath.matrix([[mpmath.mpf(x.numerator) / x.denominator for x in row] for row in A])  # noqa: E731
        L_inv = mpmath.inverse(mpmath.cholesky(exact(M)))
        A = L_inv * exact(K) * L_inv.T
        return sorted(mpmath.eigsy((A + A.T) / 2, eigvals_only=True))


@pytest.mark.parametrize("rods", [False, True], ids=["points", "rods"])
def test_each_stated_bound_holds_against_40_digits(rods: bool) -> None:
    got = answers(SMALL, rods)
    for lam, bound, want in zip(got.eigenvalues, got.absolute_errors, _eigenvalues_40_digits(*hand(SMALL, rods))):
        assert abs(mpmath.mpf(lam) - want) <= bound, (lam, want, bound)
        assert bound <= 1e-9 * abs(want)  # and the bound is a useful one at this size
