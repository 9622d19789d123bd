"""Certified decimals (solvers/modes/certified.py) against a 50-digit reference.

The reference is independent of rbdsolve's model: the n-link pendulum of point masses m
on massless links l, hanging, has by hand (Goldstein §6.4 for n = 2)

    M_ij = m l² (n − max(i, j) + 1),   K = m g l diag(n, n − 1, …, 1)

(i, j from 1), and its eigenpairs come from mpmath at 50 digits: M = L Lᵀ (Cholesky),
the symmetric L⁻¹ K L⁻ᵀ by mpmath.eigsy, a = L⁻ᵀ y. Every certified decimal must be
that reference correctly rounded to its digits: equal to it, not merely close.
"""

from __future__ import annotations

from decimal import ROUND_HALF_EVEN, Decimal, localcontext

import mpmath
import pytest
import sympy as sp

from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.solvers import solve_problem
from rbdsolve.solvers.modes.answers import Form
from rbdsolve.solvers.modes.certified import _rounded, certified_roots

N = 6  # det(K − λM) is irreducible of degree 6 over QQ for this chain


def chain_text(n: int) -> str:
    points = "\n".join(f"  P{i}: P{i - 1} + l * [sin(th{i}), -cos(th{i})]" for i in range(1, n + 1))
    bodies = "\n".join(f"  bob{i}: {{shape: particle, mass: m, at: P{i}}}" for i in range(1, n + 1))
    names = ", ".join(f"th{i}" for i in range(1, n + 1))
    about = ", ".join(f"th{i}: 0" for i in range(1, n + 1))
    return (f"title: chain\nparameters: {{m: mass, l: length, g: acceleration}}\ncoordinates: [{names}]\n"
            f"gravity: [0, -g]\npoints:\n  P0: [0, 0]\n{points}\nbodies:\n{bodies}\n"
            f"questions:\n  - modes: {{about: {{{about}}}}}\n")


def reference(n: int, digits: int = 50):
    """(μ_k, √μ_k, a_k) ascending, for det(K̂ − μM̂) = 0 with λ = μ g/l, at ``digits``."""
    with mpmath.workdps(digits):
        M = mpmath.matrix(n, n)
        K = mpmath.matrix(n, n)
        for i in range(n):
            K[i, i] = n - i
            for j in range(n):
                M[i, j] = n - max(i, j)
        L = mpmath.cholesky(M)
        Linv = L ** -1
        values, vectors = mpmath.eigsy(Linv * K * Linv.T)
        out = []
        for k in range(n):
            a = Linv.T * vectors[:, k]
            out.append((values[k], mpmath.sqrt(values[k]), [a[i] / a[0] for i in range(n)]))
        return sorted(out, key=lambda x: x[0])


def rounded(x, digits: int) -> Decimal:
    with localcontext() as context:
        context.prec, context.rounding = digits, ROUND_HALF_EVEN
        return context.plus(Decimal(mpmath.nstr(x, 60, min_fixed=-mpmath.inf, max_fixed=mpmath.inf)))


def decimal_of(x: sp.Float) -> Decimal:
    return Decimal(str(x))


@pytest.fixture(scope="module")
def answers():
    return solve_problem(build_model(load_text(chain_text(N), "chain.yaml"))).solutions[0].answers


def test_every_eigenvalue_of_the_chain_is_certified(answers) -> None:
    assert answers.forms == (Form.CERTIFIED,) * N
    assert answers.certified_digits == 15


def test_certified_decimals_are_the_50_digit_reference_correctly_rounded(answers) -> None:
    g, l = sp.symbols("g l", positive=True)
    digits = answers.certified_digits
    for (mu, root, shape), lam, w, a in zip(reference(N), answers.eigenvalues, answers.frequencies, answers.shapes):
        mu_shown = sp.simplify(lam * l / g)
        assert mu_shown.is_Float and decimal_of(mu_shown) == rounded(mu, digits)
        root_shown = sp.simplify(w / sp.sqrt(g / l))
        assert root_shown.is_Float and decimal_of(root_shown) == rounded(root, digits)
        assert a[0] == 1
        assert [decimal_of(x) for x in a[1:]] == [rounded(x, digits) for x in shape[1:]]


def test_a_ball_across_a_rounding_boundary_is_not_rounded() -> None:
    import flint

    # [0.12345 ± 1e-9] rounds to 0.1235 at its upper end and 0.1234 at its lower
    straddling = flint.arb("0.12345") + flint.arb(0, flint.arb("1e-9"))
    assert _rounded(straddling, 4) is None
    assert _rounded(straddling, 3) == sp.Float("0.123", 3)


def test_a_true_zero_in_a_shape_is_not_certified_but_left_exact() -> None:
    # x₆ decoupled: a root μ = 1 of its own, and the degree-5 factor's shapes have an
    # exact 0 in the last entry, which no ball excludes: certified_roots declines.
    n = 5
    M = sp.Matrix(n + 1, n + 1, lambda i, j: (n - max(i, j)) if i < n and j < n else 0)
    M[n, n] = 1
    K = sp.diag(*[n - i for i in range(n)], 1)
    mu = sp.Symbol("mu")
    factor = next(f for f, _ in sp.Poly((K - mu * M).det(), mu).factor_list()[1] if f.degree() == 5)
    assert certified_roots(factor, K, M) is None


def test_a_high_degree_spectrum_is_exact_where_certification_declines() -> None:
    # a sixth, separate pendulum ph: μ = 1 on its own, and a zero entry in every other shape
    text = chain_text(5).replace("bodies:\n", "  R: [5*l + l*sin(ph), -l*cos(ph)]\nbodies:\n  bob: {shape: particle, mass: m, at: R}\n")
    text = text.replace("th5]", "th5, ph]").replace("th5: 0}", "th5: 0, ph: 0}")
    answers = solve_problem(build_model(load_text(text, "chain.yaml"))).solutions[0].answers
    assert len(answers.eigenvalues) == 6 and Form.CERTIFIED not in answers.forms
    assert sum(lam.has(sp.CRootOf) for lam in answers.eigenvalues) == 5
