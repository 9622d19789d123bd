"""Small oscillations, the floating-point route: the generalized symmetric eigenproblem

    K a = λ M a,   M = Mᵀ > 0,

solved by scipy.linalg.eigh (Cholesky M = L Lᵀ, then the symmetric eigenproblem of
L⁻¹ K L⁻ᵀ; Golub & Van Loan, Matrix Computations, §8.7), with M and K at the
equilibrium as floats. The eigenvectors come M-orthonormal (aᵀ M a = 1).

Error estimate. For an M-normalized pair (λ̂, â) with residual r = K â − λ̂ M â there is
an eigenvalue within ‖r‖_{M⁻¹} = √(rᵀ M⁻¹ r) of λ̂ (Parlett, The Symmetric Eigenvalue
Problem, Thm 4.5.1, applied to L⁻¹ K L⁻ᵀ). Rounding M and K to floats moves every λ by
up to about n ε ‖L⁻¹ K L⁻ᵀ‖₂ = n ε max|λ| (Weyl). The relative error estimate of λᵢ
is the sum of the two over |λᵢ|; the report gives the largest.

The 50-digit reference (``reference_eigenvalues``) does the same in mpmath.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Mapping

import numpy as np
import sympy as sp

from rbdsolve.errors import UnsolvedError
from rbdsolve.model.build import Model
from rbdsolve.problem.schema import Question
from rbdsolve.report import steps as st
from rbdsolve.report.steps import Relation, Route, Solution
from rbdsolve.solvers.common import Options, configuration, require_values
from rbdsolve.solvers.equilibria import require_static
from rbdsolve.solvers.modes import Motion
from rbdsolve.solvers.numeric_model import equilibrium_for_modes, linearized

EPS = float(np.finfo(float).eps)
NEUTRAL_TOL = 1e3  # |λ| below this many estimated round-offs is taken as zero


@dataclass(frozen=True)
class NumericModesAnswers:
    about: Mapping[str, float]
    M: tuple[tuple[float, ...], ...]
    K: tuple[tuple[float, ...], ...]
    eigenvalues: tuple[float, ...]  # λ, ascending
    frequencies: tuple[float | None, ...]  # ω = √λ where λ > 0
    motions: tuple[Motion, ...]
    shapes: tuple[tuple[float, ...], ...]  # first nonzero entry 1, as on the exact route
    relative_errors: tuple[float, ...]  # the estimate for each λ


def solve(question: Question, model: Model, options: Options) -> Solution:
    require_values(model, "the numeric route")
    require_static(model, "small oscillations")
    about, notes = equilibrium_for_modes(question, model)
    M, K, how = linearized(model, about)
    lam, vectors, errors = generalized_eigh(K, M)
    absolute = np.abs(lam) * errors
    motions = tuple(Motion.NEUTRAL if abs(x) <= max(a, NEUTRAL_TOL * EPS * np.max(np.abs(lam), initial=0.0))
                    else Motion.OSCILLATION if x > 0 else Motion.GROWTH for x, a in zip(lam, absolute))
    answers = NumericModesAnswers(
        {n: float(sp.N(v.xreplace(dict(model.values)), 20)) for n, v in about.items()}, _rows(M), _rows(K), tuple(float(x) for x in lam),
        tuple(float(np.sqrt(x)) if m is Motion.OSCILLATION else None for x, m in zip(lam, motions)),
        motions, tuple(_normalized(v) for v in vectors.T), tuple(float(e) for e in errors))
    estimate = max((e for e, m in zip(errors, motions) if m is not Motion.NEUTRAL), default=0.0)
    return Solution("modes", Route.NUMERIC, answers, _steps(answers, model, how), warnings=notes,
                    error_estimate=float(estimate))


def generalized_eigh(K: np.ndarray, M: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """λ ascending, M-orthonormal eigenvectors (columns) and each λ's relative error estimate."""
    from scipy.linalg import LinAlgError, cho_factor, cho_solve, eigh

    try:
        factor = cho_factor(M)
    except LinAlgError:
        raise UnsolvedError("the mass matrix is not positive definite at this configuration: "
                            "a coordinate carries no inertia") from None
    lam, vectors = eigh(K, M)
    residuals = K @ vectors - M @ vectors * lam
    bound = np.sqrt(np.einsum("ij,ij->j", residuals, cho_solve(factor, residuals)))
    rounding = len(lam) * EPS * np.max(np.abs(lam), initial=0.0)
    with np.errstate(divide="ignore"):
        relative = (bound + rounding) / np.abs(lam)
    return lam, vectors, relative


def reference_eigenvalues(K, M, digits: int = 50) -> list:
    """λ of K a = λ M a to ``digits`` digits (mpmath): Cholesky M = L Lᵀ, then the
    symmetric eigenvalues of L⁻¹ K L⁻ᵀ. K and M may hold exact or mpf entries."""
    import mpmath

    with mpmath.workdps(digits + 10):
        Km, Mm = mpmath.matrix(_mp_rows(K)), mpmath.matrix(_mp_rows(M))
        L = mpmath.cholesky(Mm)
        Linv = mpmath.inverse(L)
        A = Linv * Km * Linv.T
        A = (A + A.T) / 2
        return sorted(mpmath.eigsy(A, eigvals_only=True))


def _mp_rows(A) -> list[list]:
    import mpmath

    rows = A.tolist() if hasattr(A, "tolist") else [list(r) for r in A]
    return [[mpmath.mpf(sp.N(x, mpmath.mp.dps)) if isinstance(x, sp.Basic) else mpmath.mpf(x) for x in r]
            for r in rows]


def _rows(A: np.ndarray) -> tuple[tuple[float, ...], ...]:
    return tuple(tuple(float(x) for x in row) for row in A)


def _normalized(v: np.ndarray) -> tuple[float, ...]:
    """Scaled so the first entry that is not round-off is 1, as the exact route shows."""
    big = np.max(np.abs(v))
    first = next(x for x in v if abs(x) > 1e-9 * big)
    return tuple(float(x / first) for x in v)


MAX_SHOWN = 8  # larger matrices and mode shapes are left to the JSON answers


def _steps(a: NumericModesAnswers, model: Model, how: str) -> tuple[st.Step, ...]:
    n = len(a.eigenvalues)
    matrices = ((Relation(sp.Symbol("M"), _floats(a.M)), Relation(sp.Symbol("K"), _floats(a.K)))
                if n <= MAX_SHOWN else ())
    steps = [
        st.given("Small motions q = q₀ + u about the equilibrium",
                 configuration(model.state.functions(), [sp.Float(v, 15) for v in a.about.values()])),
        st.equation(f"Linearized equations M u\u0308 + K u = 0 at the equilibrium, in numbers ({how}"
                    + (f"; M and K are {n}×{n}, in the JSON answers):" if n > MAX_SHOWN else "):"), *matrices),
        st.equation("The generalized symmetric eigenproblem K a = λ M a, by Cholesky factorization of M "
                    "(scipy.linalg.eigh):",
                    *[Relation(sp.Symbol(f"lambda_{i}"), sp.Float(x, 15)) for i, x in enumerate(a.eigenvalues, 1)]),
    ]
    for i, (lam, w, motion, shape) in enumerate(zip(a.eigenvalues, a.frequencies, a.motions, a.shapes), 1):
        rel = []
        if motion is Motion.OSCILLATION:
            rel.append(Relation(sp.Symbol(f"omega_{i}"), sp.Float(w, 15)))
            text = f"Mode {i}: λ > 0, an oscillation at ω = √λ with amplitudes a:"
        elif motion is Motion.GROWTH:
            rel.append(Relation(sp.Symbol(f"gamma_{i}"), sp.Float(np.sqrt(-lam), 15)))
            text = f"Mode {i}: λ < 0, exponential growth at the rate γ = √(−λ): unstable:"
        else:
            text = f"Mode {i}: λ = 0 within round-off, neutral:"
        if n <= MAX_SHOWN:
            rel.append(Relation(sp.Symbol(f"a_{i}"), _floats((shape,))))
        steps.append(st.result(text, *rel))
    return tuple(steps)


def _floats(rows) -> sp.ImmutableMatrix:
    return sp.ImmutableMatrix([[sp.Float(x, 15) for x in row] for row in rows])
