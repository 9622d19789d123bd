"""The numeric routes' dense linear algebra, on numpy's LAPACK alone.

scipy.linalg gives the same, but importing it costs ~0.14 s of a process (its array-API
layer, fft and special functions come with it), and scipy.optimize ~0.27 s: more than a
numeric route's whole work on an exam's few coordinates (an inverted rod on two
springs: 1.3 s in all, 0.3 s of it importing scipy). Each function is the reduction
LAPACK's own drivers make:

- ``symmetric_pencil``: K a = λ M a with M = L Lᵀ (Cholesky) is the standard symmetric
  problem C y = λ y, C = L⁻¹ K L⁻ᵀ, a = L⁻ᵀ y (Golub & Van Loan, Matrix Computations,
  §8.7.2; LAPACK's dsygv, which scipy's ``eigh(K, M)`` calls, does the same);
- ``null_space``: the right singular vectors past A's numerical rank, the singular
  values σ ≤ max(m, n) ε σ₁ counted as zero (Golub & Van Loan §2.5.3, §5.5.8);
- ``pencil_eigenvalues``: A x = s B x with B invertible is B⁻¹ A x = s x.
"""

from __future__ import annotations

import numpy as np

EPS = float(np.finfo(float).eps)
LinAlgError = np.linalg.LinAlgError


def cholesky_lower(M: np.ndarray) -> np.ndarray:
    """L with M = L Lᵀ, lower triangular; LinAlgError where M is not positive definite."""
    return np.linalg.cholesky(np.asarray(M, dtype=float))


def lower_inverse(L: np.ndarray) -> np.ndarray:
    """L⁻¹ of a lower triangular L (its inverse is lower triangular too)."""
    return np.tril(np.linalg.solve(L, np.eye(len(L))))


def symmetric_pencil(K: np.ndarray, L: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """λ ascending and the vectors a (columns) of K a = λ M a, given L of M = L Lᵀ:
    the eigenpairs of C = L⁻¹ K L⁻ᵀ, a = L⁻ᵀ y (by solving with L, not multiplying by
    its inverse: the inverse's own rounding would enter twice)."""
    lam, y = np.linalg.eigh(_reduced(K, L))
    return lam, np.linalg.solve(L.T, y)


def symmetric_pencil_values(K: np.ndarray, M: np.ndarray) -> np.ndarray:
    """λ ascending of K a = λ M a (``symmetric_pencil``, the eigenvalues only)."""
    return np.linalg.eigvalsh(_reduced(K, cholesky_lower(M)))


def _reduced(K: np.ndarray, L: np.ndarray) -> np.ndarray:
    """C = L⁻¹ K L⁻ᵀ, made exactly symmetric (K is)."""
    C = np.linalg.solve(L, np.linalg.solve(L, np.asarray(K, dtype=float)).T)
    return (C + C.T) / 2


def null_space(A: np.ndarray) -> np.ndarray:
    """An orthonormal basis (columns) of the null space of A."""
    A = np.atleast_2d(np.asarray(A, dtype=float))
    _, sigma, vh = np.linalg.svd(A, full_matrices=True)
    largest = sigma[0] if sigma.size else 0.0
    rank = int(np.sum(sigma > max(A.shape) * EPS * largest))
    return vh[rank:].T.conj()


def pencil_eigenvalues(A: np.ndarray, B: np.ndarray) -> np.ndarray:
    """s of A x = s B x, B invertible (LinAlgError where B is singular)."""
    return np.linalg.eigvals(np.linalg.solve(np.asarray(B, dtype=float), np.asarray(A, dtype=float)))
