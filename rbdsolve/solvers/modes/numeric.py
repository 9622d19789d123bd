"""Small oscillations, the floating-point route: the generalized symmetric eigenproblem

    K a = λ M a,   M = Mᵀ > 0,

solved as LAPACK's dsygv solves it (Cholesky M = L Lᵀ, then the symmetric eigenproblem
of L⁻¹ K L⁻ᵀ; Golub & Van Loan, Matrix Computations, §8.7; numeric/dense.py), with M
and K at the equilibrium as floats. The eigenvectors are scaled M-orthonormal (aᵀ M a = 1).

Error bound, absolute, one per eigenvalue (``eigen_bounds``), the sum of three terms:

- the residual: for the computed pair (λ̂, â) with r = K â − λ̂ M â there is an exact
  eigenvalue of the float pencil within ‖r‖_{M⁻¹}/‖â‖_M (Parlett, The Symmetric
  Eigenvalue Problem, Thm 4.5.1, applied to L⁻¹ K L⁻ᵀ and x = Lᵀ â);
- the rounding of r itself: each entry of the computed r is within about
  n ε (‖K‖₂ + |λ̂| ‖M‖₂) ‖â‖₂ of its value, which in the M⁻¹ norm is at most that over
  √λ_min(M). Over all vectors this is at most the a priori n ε ‖K‖₂/λ_min(M) of the
  Cholesky method (Golub & Van Loan §8.7.2) for λ = 0, and it is nonzero wherever K is,
  so a zero eigenvalue always has a nonzero bound;
- the rounding of M and K to floats, δM and δK of about n ε ‖M‖₂ and n ε ‖K‖₂: to first
  order λ moves by âᵀ (δK − λ δM) â (M-normalized â), at most
  n ε (‖K‖₂ + |λ| ‖M‖₂) ‖â‖₂² (the backward error of the pencil; Higham & Higham,
  Structured backward error and condition of generalized eigenvalue problems, 1998),
  divided by 1 − η, η = n ε ‖M‖₂/λ_min(M), which makes the worst vector's bound rigorous
  (M + δM lies between (1 − η) M and (1 + η) M: Rayleigh quotients). Where η ≥ 1 the
  rounding of M may be as large as its smallest eigenvalue: the question is refused.

To these, the equilibrium's own error (``location.py``): at the point used, ∂V/∂q in 50
digits is not 0 where the equilibrium is known only to floating point, and each λ moves
with the point, twice its first-order move Σ ∂λ/∂q_j δq_j. And the rounding of K's
terms (``stiffness_rounding``): K by automatic differentiation sums the Hessians of
V's terms, so its error is relative to them, not to K, which at a degenerate
equilibrium is all rounding.

An eigenvalue within its bound of zero is neutral (zero within rounding); its relative
error is undefined (None). ``error_estimate`` is the largest relative bound of the
others. A negative λ is reported by its growth rate γ = √(−λ). Clusters of eigenvalues
equal within their bounds, the error of each mode space, condition numbers and the
warnings past the tolerance 1e-8: ``modes_spaces``. The 50-digit reference
(``reference_eigenvalues``) does the same in mpmath.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import sympy as sp

from rbdsolve.errors import UnsolvedError
from rbdsolve.model.build import Model
from rbdsolve.problem.schema import Question
from rbdsolve.report.steps import Route, Solution
from rbdsolve.form.arrange import configuration
from rbdsolve.report import steps as st
from rbdsolve.solvers.modes import gyroscopic_terms
from rbdsolve.solvers.modes.answers import (EachModesAnswers, Motion, NumericModesAnswers, Skipped, none_answered,
                                             with_amplitude_check)
from rbdsolve.solvers.modes.location import location_bounds
from rbdsolve.solvers.modes.spaces import analyse, warnings
from rbdsolve.solvers.modes.steps import numeric_steps
from rbdsolve.solvers.lagrange.frames import require_static
from rbdsolve.solvers.numeric import dense
from rbdsolve.solvers.numeric.chosen import equilibrium_for_modes
from rbdsolve.solvers.numeric.numeric_model import as_floats, linearized
from rbdsolve.solvers.routes.options import Options
from rbdsolve.solvers.configuration.singular import float_reason
from rbdsolve.solvers.routes.needed import require_values

EPS = float(np.finfo(float).eps)


def solve(question: Question, model: Model, options: Options) -> Solution:
    require_values(model, "the numeric route")
    require_static(model, "small oscillations")
    if gyroscopic_terms.applies(question, model):
        from rbdsolve.solvers.modes import gyroscopic_numeric

        return gyroscopic_numeric.solve(question, model)
    if question.options.each:
        return _at_each(model)
    about, notes = equilibrium_for_modes(question, model)
    notes = (*notes, *gyroscopic_terms.spin_notes(question, model))
    answers, steps, warned, estimate = modes_at(about, model)
    return with_amplitude_check(question, model, Solution("modes", Route.NUMERIC, answers, steps,
                                                          warnings=tuple(notes) + warned, error_estimate=estimate))


def _at_each(model: Model) -> Solution:
    """The modes at every equilibrium the numeric search lists (as 'equilibria' numbers
    them), each under its own heading; one that cannot be answered says why."""
    from rbdsolve.solvers.numeric.numeric_model import find_numeric
    from rbdsolve.solvers.numeric.recognized import exactly
    from rbdsolve.solvers.configuration.placement import numeric_listing

    names = model.coordinate_names()
    found, skipped, steps, warned, estimates = [], [], [], [], []
    for k, (root, _) in enumerate(numeric_listing(model, find_numeric(model).equilibria)[0], 1):
        about = exactly(model, root)  # π where the listing writes π
        steps.append(st.result(f"About equilibrium {k}:", configuration(
            model.state.functions(), [sp.Float(v, 15) if v.is_Float else v for v in about.values()])))
        try:
            answers, more, w, estimate = modes_at(about, model)
        except UnsolvedError as exc:
            skipped.append(Skipped({n: float(x) for n, x in zip(names, root.at)}, str(exc)))
            steps.append(st.note(f"Not answered here: {exc}."))
            continue
        found.append(answers)
        steps += more
        warned += [f"equilibrium {k}: {x}" for x in w]
        estimates += [estimate] if estimate is not None else []
    if not found:
        raise UnsolvedError(none_answered(skipped, "in the numeric search's box"))
    return Solution("modes", Route.NUMERIC, EachModesAnswers(tuple(found), tuple(skipped)), tuple(steps),
                    warnings=tuple(warned), error_estimate=max(estimates, default=None))


def modes_at(about: dict, model: Model):
    """(answers, steps, warnings, error estimate) of the small oscillations about one
    equilibrium ({name: value})."""
    M, K, how = linearized(model, about)
    if singular := float_reason(M, model.coordinate_names(), "at this configuration"):
        raise UnsolvedError(singular)
    lam, vectors, absolute, pencil = solve_pencil(K, M)
    absolute = (absolute + location_bounds(model, about, K, lam, lambda at: linearized(model, at)[:2])
                + stiffness_rounding(model, about, vectors))
    motions = tuple(classify(x, a) for x, a in zip(lam, absolute))
    relative = tuple(None if m is Motion.NEUTRAL else float(a / abs(x)) for x, a, m in zip(lam, absolute, motions))
    spaces = analyse(pencil, lam, vectors, absolute, tuple(m is Motion.NEUTRAL for m in motions))
    answers = NumericModesAnswers(
        as_floats(model, about), _rows(M), _rows(K),
        tuple(float(x) for x in lam),
        tuple(float(np.sqrt(x)) if m is Motion.OSCILLATION else None for x, m in zip(lam, motions)),
        motions, tuple(normalized(v) for v in vectors.T), tuple(float(a) for a in absolute), relative,
        tuple(float(np.sqrt(-x)) if m is Motion.GROWTH else None for x, m in zip(lam, motions)),
        _rows(vectors.T), tuple(tuple(i + 1 for i in g) for g in spaces.clusters), spaces.shape_errors,
        spaces.condition_M, spaces.conditions, spaces.spread)
    # Only the modes that are not neutral have a relative error; with none, there is no estimate.
    estimate = max((e for e in relative if e is not None), default=None)
    return answers, numeric_steps(answers, model, how, about), warnings(spaces, lam, relative), estimate


def stiffness_rounding(model: Model, about: dict, vectors: np.ndarray) -> np.ndarray:
    """What rounding K's terms moves each λ by. K by automatic differentiation sums the
    Hessians of V's terms (each weight, each spring), whatever its own size, so each
    entry is within a few (ROUNDING_UNITS) n ε of Σ |the terms' entries|
    (``NumericScene.term_curvatures``), and λ = aᵀ K a (aᵀ M a = 1) within that times
    ‖a‖₂². Where the terms cancel to K ≈ 0 (a degenerate equilibrium: an inverted rod on
    springs at exactly the critical stiffness) it is all of λ: λ = 2.7e-15 with a bound
    of 2e-30 was printed as an oscillation of period 1.2·10⁸ s, beside the equilibria
    question's "undetermined" for the same point. (K from the exact Hessian, rounded
    once, has only its own rounding, which ``eigen_bounds`` counts.)"""
    from rbdsolve.solvers.numeric.numeric_model import numeric_scene, rounding

    scene = numeric_scene(model)
    if scene is None:
        return np.zeros(vectors.shape[1])
    q0 = list(as_floats(model, about).values())
    scale = float(np.max(scene.term_curvatures(q0), initial=0.0))
    return rounding(len(vectors), scale) * np.sum(vectors * vectors, axis=0)


def classify(lam: float, bound: float) -> Motion:
    """Neutral where |λ| ≤ its bound (the sign of λ is not known), else by the sign of λ."""
    if not (np.isfinite(lam) and np.isfinite(bound)):  # never classify NaN: a comparison with it is False
        raise UnsolvedError(f"the eigenvalue {lam} or its error bound {bound} is not finite")
    if abs(lam) <= bound:
        return Motion.NEUTRAL
    return Motion.OSCILLATION if lam > 0 else Motion.GROWTH


@dataclass(frozen=True)
class Pencil:
    """What the eigenvalue bounds and the conditioning (``spaces.analyse``) share of one
    K a = λ M a, each computed once: L⁻¹ (M = L Lᵀ), λ_min(M) = 1/‖L⁻¹‖₂²,
    η = n ε ‖M‖₂/λ_min(M), ‖K‖₂, ‖M‖₂ and the residuals ‖L⁻¹(K âᵢ − λ̂ᵢ M âᵢ)‖ (one per mode).
    Arrays inside: compared by identity, never hashed."""

    Linv: np.ndarray
    smallest: float
    eta: float
    norm_K: float
    norm_M: float
    residual: np.ndarray


def generalized_eigh(K: np.ndarray, M: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """λ ascending, M-orthonormal eigenvectors (columns) and each λ's absolute error bound
    (the module docstring derives it)."""
    lam, vectors, bounds, _ = solve_pencil(K, M)
    return lam, vectors, bounds


def solve_pencil(K: np.ndarray, M: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, Pencil]:
    """``generalized_eigh`` and the Pencil its bounds were computed from."""
    try:
        L = dense.cholesky_lower(M)
    except dense.LinAlgError:
        raise UnsolvedError("the mass matrix is not positive definite at this configuration: "
                            "a coordinate carries no inertia") from None
    Linv = dense.lower_inverse(L)
    norm_M = np.linalg.norm(M, 2)
    smallest, eta = _conditioning(M, Linv, norm_M)
    lam, vectors = dense.symmetric_pencil(K, L)
    # eigh's vectors are M-orthonormal only to rounding (less so as M is ill-conditioned);
    # ‖Lᵀ a‖ is √(aᵀ M a) without the cancellation that could make it negative.
    vectors = vectors / np.linalg.norm(L.T @ vectors, axis=0)
    residual = np.linalg.norm(Linv @ (K @ vectors - M @ vectors * lam), axis=0)
    pencil = Pencil(Linv, smallest, eta, np.linalg.norm(K, 2), norm_M, residual)
    return lam, vectors, eigen_bounds(pencil, lam, vectors), pencil


def _conditioning(M: np.ndarray, Linv: np.ndarray, norm_M: float) -> tuple[float, float]:
    """λ_min(M) = 1/‖L⁻¹‖₂² (the same factor as eigh's) and η = n ε ‖M‖₂/λ_min(M), the
    rounding of M relative to its smallest eigenvalue; refused where η ≥ 1."""
    smallest = 1.0 / np.linalg.norm(Linv, 2) ** 2
    eta = len(M) * EPS * norm_M / smallest
    if not eta < 1:  # also refuses a NaN
        raise UnsolvedError(f"the mass matrix is singular in floating point (condition number "
                            f"{norm_M / smallest:.3g}): its rounding may be as large as its smallest "
                            "eigenvalue, so the eigenvalues are not determined; a coordinate carries (almost) no "
                            "inertia")
    return smallest, eta


def eigen_bounds(pencil: Pencil, lam: np.ndarray, vectors: np.ndarray) -> np.ndarray:
    """|λ̂ − λ| ≤ ‖r‖_{M⁻¹} + n ε (‖K‖ + |λ̂| ‖M‖) (‖â‖/√λ_min(M) + ‖â‖²/(1 − η)), â M-normalized
    (Parlett Thm 4.5.1; Higham & Higham 1998; the module docstring)."""
    scale = len(lam) * EPS * (pencil.norm_K + np.abs(lam) * pencil.norm_M)
    length = np.linalg.norm(vectors, axis=0)
    return pencil.residual + scale * (length / np.sqrt(pencil.smallest) + length**2 / (1 - pencil.eta))


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


def normalized(v: np.ndarray) -> tuple[float, ...]:
    """Scaled so the first entry that is not round-off is 1, as the exact route shows."""
    big = np.max(np.abs(v))
    first = next(x for x in v if abs(x) > 1e-9 * big)
    return tuple(float(x / first) for x in v)
