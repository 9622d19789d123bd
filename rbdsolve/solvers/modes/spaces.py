"""The numeric modes route's conditioning: clusters of eigenvalues, the error of each
mode space, condition numbers, and the warnings when a bound passes the tolerance.

Computed on the pencil K a = λ M a after ``modes_numeric.generalized_eigh`` (λ̂ ascending,
â M-orthonormal, bᵢ the absolute bound of λ̂ᵢ), in the symmetric form A = L⁻¹ K L⁻ᵀ,
M = L Lᵀ, x = Lᵀ a (an angle between x's is the angle in the M inner product).

- Clusters: consecutive eigenvalues with λ̂ᵢ₊₁ − λ̂ᵢ ≤ bᵢ + bᵢ₊₁ are not told apart within
  their bounds: they form one cluster, reported as one mode space (its computed vectors an
  M-orthonormal basis of it), since the vectors inside a cluster are not determined one by
  one (a double eigenvalue has a whole plane of mode shapes).
- The error of a mode space (``shape_errors``, per mode: its cluster's): the sin Θ theorem
  of Davis & Kahan (1970; Parlett, The Symmetric Eigenvalue Problem, Thm 11.7.1):
  ‖sin Θ‖ ≤ (‖R_C‖ + e_C)/δ_C with R_C = L⁻¹(K Â_C − M Â_C Λ̂_C) the cluster's residual
  (Frobenius norm, ≥ the 2-norm), e_C the rounding of the pencil and of R_C in the
  symmetric form, n ε (‖K‖₂ + |λ|max ‖M‖₂)(‖â‖max/√λ_min(M) + 1/(λ_min(M)(1 − η))), and
  δ_C the gap from the cluster's λ̂ to the other exact eigenvalues, each within bⱼ of its
  λ̂ⱼ: min |λ̂ᵢ − λ̂ⱼ| − bⱼ (first order, as the eigenvalue bounds). At most 1; 0 for a
  cluster of every mode (the whole space).
- Condition numbers: κ₂(M) = ‖M‖₂/λ_min(M); per eigenvalue the relative condition
  number of the definite pencil κ(λ) = (‖K‖₂ + |λ| ‖M‖₂) ‖â‖₂²/|λ| with âᵀ M â = 1
  (Higham & Higham 1998, normwise, y = x): the relative error is about ε κ(λ); and the
  spread max |λ|/min |λ| over the modes that are not neutral.
- Tolerance: RELATIVE_TOL = 1e-8. A relative eigenvalue bound, or a mode space's
  sin Θ bound, above it is a warning (the answer is still given, with its bound).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

EPS = float(np.finfo(float).eps)
RELATIVE_TOL = 1e-8


@dataclass(frozen=True)
class Spaces:
    """Conditioning of one numeric eigenproblem (indices 0-based)."""

    condition_M: float  # κ₂(M)
    conditions: tuple[float | None, ...]  # κ(λᵢ); None where λᵢ is neutral
    spread: float | None  # max |λ|/min |λ| over the modes that are not neutral
    clusters: tuple[tuple[int, ...], ...]  # ascending, every mode in exactly one
    shape_errors: tuple[float, ...]  # sin Θ bound of each mode's space (its cluster's)


def analyse(pencil, lam: np.ndarray, vectors: np.ndarray, bounds: np.ndarray, neutral: tuple[bool, ...]) -> Spaces:
    """Clusters, subspace bounds and condition numbers (the module docstring), from the
    factors and norms the eigenvalue bounds used (``modes.numeric.Pencil``)."""
    smallest, eta, norm_K, norm_M = pencil.smallest, pencil.eta, pencil.norm_K, pencil.norm_M
    residual, n = pencil.residual, len(lam)
    groups = clusters(lam, bounds)
    errors = [0.0] * len(lam)
    for group in groups:
        rounding = n * EPS * (norm_K + max(abs(lam[i]) for i in group) * norm_M) * (
            max(np.linalg.norm(vectors[:, i]) for i in group) / np.sqrt(smallest) + 1 / (smallest * (1 - eta)))
        angle = subspace_bound(group, lam, bounds, float(np.linalg.norm(residual[list(group)])) + rounding)
        for i in group:
            errors[i] = angle
    length2 = np.linalg.norm(vectors, axis=0) ** 2
    conditions = tuple(None if z else float((norm_K + abs(x) * norm_M) * n2 / abs(x))
                       for x, n2, z in zip(lam, length2, neutral))
    sizes = [abs(x) for x, z in zip(lam, neutral) if not z]
    spread = float(max(sizes) / min(sizes)) if sizes else None
    return Spaces(float(norm_M / smallest), conditions, spread, tuple(groups), tuple(errors))


def clusters(lam: np.ndarray, bounds: np.ndarray) -> list[tuple[int, ...]]:
    """Runs of ascending eigenvalues whose consecutive gaps are within the sum of
    their bounds."""
    groups = [[0]] if len(lam) else []
    for i in range(1, len(lam)):
        if lam[i] - lam[i - 1] <= bounds[i] + bounds[i - 1]:
            groups[-1].append(i)
        else:
            groups.append([i])
    return [tuple(g) for g in groups]


def subspace_bound(group: tuple[int, ...], lam: np.ndarray, bounds: np.ndarray, residual: float) -> float:
    """sin Θ ≤ residual/δ (Davis–Kahan), δ the gap to the exact eigenvalues outside the
    cluster, each within its bound of its computed value; 1 where δ ≤ residual."""
    others = np.ones(len(lam), dtype=bool)
    others[list(group)] = False
    if not others.any():
        return 0.0
    lam, bounds = np.asarray(lam), np.asarray(bounds)
    gap = min(np.min(np.abs(lam[i] - lam[others]) - bounds[others]) for i in group)
    return 1.0 if gap <= residual else float(residual / gap)


def warnings(spaces: Spaces, lam: np.ndarray, relative: tuple[float | None, ...]) -> tuple[str, ...]:
    """The clusters (a mode space, not single shapes) and the bounds above RELATIVE_TOL."""
    out = []
    for group in spaces.clusters:
        if len(group) > 1:
            names = ", ".join(f"λ{i + 1}" for i in group)
            out.append(f"{names} agree within their error bounds: one mode space of dimension {len(group)}; "
                       f"the shapes {', '.join(f'a{i + 1}' for i in group)} are an M-orthogonal basis of it, not "
                       f"determined one by one (the space itself within sin Θ ≤ {spaces.shape_errors[group[0]]:.1e})")
    loose = [i for i, r in enumerate(relative) if r is not None and r > RELATIVE_TOL]
    if loose:
        out.append("ill-conditioned: the error bound of " + ", ".join(
            f"λ{i + 1} is {relative[i]:.1e} relative (κ(λ{i + 1}) = {spaces.conditions[i]:.1e})" for i in loose)
            + f", above the tolerance {RELATIVE_TOL:.0e}; κ₂(M) = {spaces.condition_M:.1e}. "
            "The exact route (no --route numeric) is not affected")
    vague = [i for i, e in enumerate(spaces.shape_errors) if e > RELATIVE_TOL
             and len(next(g for g in spaces.clusters if i in g)) == 1]
    if vague:
        out.append("the mode shape " + ", ".join(
            f"a{i + 1} is determined only within sin θ ≤ {spaces.shape_errors[i]:.1e}" for i in vague)
            + f" (the angle in the M inner product: residual and rounding over the gap to the other eigenvalues), "
            f"above the tolerance {RELATIVE_TOL:.0e}")
    return tuple(out)
