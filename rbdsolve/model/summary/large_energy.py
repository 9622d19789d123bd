"""The model section of a large model: energies as matrices, not sums of dozens of terms.

A chain of n links has n(n + 1)/2 products q̇ᵢq̇ⱼ in T; past about a dozen a reader
cannot scan the sum, and a textbook writes instead (Goldstein, §6.1)

    T = ½ q̇ᵀ M(q) q̇,   M(q) = Σ_bodies (m J_vᵀ J_v + J_ωᵀ J_G J_ω),

with M written out as a matrix with a common scale, and for a potential that is a
quadratic form in q (springs from rest) V = ½ qᵀ K q with K = ∂²V/∂q∂q. Building M
from the velocity Jacobians is also cheaper than expanding and collecting T.
"""

from __future__ import annotations

from typing import Callable

import sympy as sp

from rbdsolve.form.arrange import arranged, scaled_matrix
from rbdsolve.form.display import Relation
from rbdsolve.model.build import Model
from rbdsolve.model.energies.energy import Energy, hessian, jacobians
from rbdsolve.report import steps as st

SCAN_TERMS = 12  # an energy with more terms than this is shown as a matrix, or as its total alone


def quadratic_products(model: Model) -> int | None:
    """How many products q̇ᵢq̇ⱼ (i ≤ j) T has, from which rates each body's v and ω
    hold; None when T is not a quadratic form in the rates (a body moving when every
    q̇ is 0: a driven frame, a given velocity), which no M(q) alone describes."""
    if model.instant:
        return None
    pairs = set()
    for b in jacobians(model):
        if b.moves_at_rest:
            return None
        used = [j for j in range(len(model.qd)) if any(x != 0 for x in (*b.J_v[:, j], *b.J_w[:, j]))]
        pairs |= {(j, k) for i, j in enumerate(used) for k in used[i:]}
    return len(pairs)


def kinetic_from_matrix(M: sp.Matrix, qd: tuple[sp.Expr, ...]) -> sp.Expr:
    """T = ½ Σᵢⱼ Mᵢⱼ q̇ᵢ q̇ⱼ = Σᵢ ½ Mᵢᵢ q̇ᵢ² + Σ_{i<j} Mᵢⱼ q̇ᵢ q̇ⱼ (M symmetric)."""
    n = len(qd)
    return sp.Add(*[M[i, i] * qd[i] ** 2 / 2 for i in range(n)],
                  *[M[i, j] * qd[i] * qd[j] for i in range(n) for j in range(i + 1, n)])


def kinetic_steps(text: str, products: int, M: sp.Matrix, model: Model) -> list[st.Step]:
    """T = ½ q̇ᵀ M(q) q̇ with M(q) written out."""
    symbols = set(model.symbols.parameters.values())
    timed = in_time(M, model.to_time)
    return [st.definition(
        f"{text}. T has {products} products q̇ᵢq̇ⱼ, so it is written as a matrix: T = ½ q̇ᵀ M(q) q̇ with "
        f"M(q) = Σ (m J_vᵀ J_v + J_ωᵀ J_G J_ω) over the bodies (J_v, J_ω: the Jacobians of v_G and ω "
        "with respect to q̇):",
        Relation(_M_of_q(), scaled_matrix(timed, symbols)))]


def potential_steps(text: str, energy: Energy, model: Model) -> list[st.Step]:
    """V = ½ qᵀ K q with K written out when V is a quadratic form in q; else V in one
    sum (form/arrange.py ``arranged``), its per-body parts left out."""
    symbols, reading = set(model.symbols.parameters.values()), model.reading()
    if _quadratic_form(energy.total, model.q):
        K = in_time(hessian(energy.total, tuple(model.q)), model.to_time)
        return [st.definition(f"{text}. V is a quadratic form in q, written as a matrix: V = ½ qᵀ K q with "
                              "K = ∂²V/∂q∂q:", Relation(sp.Symbol("K"), scaled_matrix(K, symbols)))]
    return [st.definition(f"{text}; summed:", Relation(sp.Symbol("V"), arranged(energy.total, reading)))]


def in_time(matrix: sp.Matrix, to_time: Callable[[sp.Expr], sp.Expr]) -> sp.ImmutableMatrix:
    """q → q(t) in each entry, each distinct entry once (M and K are symmetric). Before
    the matrix is arranged: substituting into entries already factored would undo their
    form (it rebuilds 3/2 (1 + cos θ) as 3/2 + 3/2 cos θ)."""
    timed: dict[sp.Expr, sp.Expr] = {}
    for x in matrix:
        if x not in timed:
            timed[x] = to_time(x)
    return sp.ImmutableMatrix(matrix.rows, matrix.cols, [timed[x] for x in matrix])


def terms(expr: sp.Expr) -> int:
    """The number of terms of an energy written out."""
    return len(sp.Add.make_args(sp.expand(expr)))


def _quadratic_form(V: sp.Expr, q: tuple[sp.Expr, ...]) -> bool:
    """V = ½ qᵀ K q: a polynomial in q whose every term has degree 2."""
    if not V.free_symbols & set(q):
        return False
    try:
        poly = sp.Poly(V, *q)
    except sp.PolynomialError:
        return False
    return all(sum(monomial) == 2 for monomial in poly.monoms())


def _M_of_q() -> sp.Expr:
    return sp.Function("M")(sp.Symbol("q"))
