"""Continua of equilibria on the floating-point route: a cart whose V does not depend
on x has an equilibrium at every x, and Newton's method, started from a grid, would
list one point of that line per start. Each family is reported once instead.

Strategy, at a root x of g = ∂V/∂q (g(x) ≈ 0):

1. Candidate directions: the null space of the Hessian H(x), the eigenvectors whose
   eigenvalue is at most NULL_TOL × max|eig| in size, or within H's rounding. A
   coordinate axis lying in it is tried first (exactly, so that a free coordinate is
   shown at exactly 0), then the null eigenvectors, each made orthogonal to the
   directions already accepted.
2. A candidate v is free when g stays zero (within the root tolerance) all along the
   straight line through the point of it nearest q = 0, x − v (v·x), at the steps
   s = ±STEP_FRACTIONS × the box's half-width along v: every point of that line is an
   equilibrium. A null direction where V is merely flat to second order (V = x⁴)
   fails this, and the root stays isolated.
3. The representative of the family is x − F Fᵀ x for the free directions F (an
   orthonormal basis): the point of the family nearest q = 0 along them, the same
   whichever start found the family, so its roots merge into one. It must be a root
   too, else the directions are dropped and x is kept as found.

A continuum that is curved (a ring of equilibria) has no straight free direction: it
is not detected, and its points are listed as found; the equilibria route then warns
that the Hessian is singular there.
"""

from __future__ import annotations

from typing import Callable, Sequence

import numpy as np

from rbdsolve.errors import UnsolvedError

NULL_TOL = 1e-9  # an eigenvalue of H this small relative to the largest counts as zero
STEP_FRACTIONS = (0.29, 0.61, 0.97)  # of the half-width of the box along a direction
AXIS_TOL = 1e-9

Vector = tuple[float, ...]


def null_count(hess: np.ndarray, floor: float = 0.0) -> int:
    """How many eigenvalues of the symmetric part of H are zero within NULL_TOL, or
    within ``floor``, H's rounding (where its terms cancel every eigenvalue is noise)."""
    eig = np.linalg.eigvalsh((hess + hess.T) / 2)
    return int(np.sum(_zero(eig, floor)))


def free_directions(x: np.ndarray, g: Callable, hess: np.ndarray, half_widths: Sequence[float],
                    tol: float, floor: float = 0.0) -> tuple[Vector, ...]:
    """Orthonormal directions along which every point through x is an equilibrium
    (|g| ≤ tol on the whole line): steps 1 and 2 of the module's strategy."""
    eig, vectors = np.linalg.eigh((hess + hess.T) / 2)
    null = vectors[:, _zero(eig, floor)]
    if null.shape[1] == 0:
        return ()
    accepted: list[np.ndarray] = []
    for v in [*_axes_in(null), *null.T]:
        for a in accepted:
            v = v - (a @ v) * a
        if np.linalg.norm(v) < 0.5:
            continue  # (nearly) in the span of the directions already accepted
        v = v / np.linalg.norm(v)
        if _flat_line(x - v * (v @ x), v, g, half_widths, tol):
            accepted.append(v)
    return tuple(tuple(float(c) for c in v) for v in accepted)


def _zero(eig: np.ndarray, floor: float) -> np.ndarray:
    """Which eigenvalues count as zero: within NULL_TOL of the largest, or ``floor``."""
    return np.abs(eig) <= max(NULL_TOL * np.max(np.abs(eig), initial=0.0), floor)


def representative(x: np.ndarray, free: Sequence[Vector]) -> np.ndarray:
    """x − F Fᵀ x: the point of x's family nearest q = 0 along the free directions."""
    F = np.array(free, dtype=float).T
    return x - F @ (F.T @ x)


def is_axis(v: Vector) -> int | None:
    """The index of the coordinate axis v is (±), else None."""
    big = int(np.argmax(np.abs(v)))
    return big if abs(abs(v[big]) - 1.0) <= AXIS_TOL else None


def _axes_in(null: np.ndarray) -> list[np.ndarray]:
    """The coordinate axes that lie in the span of the null eigenvectors."""
    n = null.shape[0]
    axes = []
    for i in range(n):
        e = np.zeros(n)
        e[i] = 1.0
        if np.linalg.norm(null.T @ e) >= 1.0 - 1e-6:
            axes.append(e)
    return axes


def _flat_line(base: np.ndarray, v: np.ndarray, g: Callable, half_widths: Sequence[float], tol: float) -> bool:
    """|g| ≤ tol at base and at base + s v for the steps s across the box."""
    significant = [w / abs(c) for w, c in zip(half_widths, v) if abs(c) > 1e-3]
    reach = min(significant)
    for s in (0.0, *[sign * f * reach for f in STEP_FRACTIONS for sign in (1, -1)]):
        try:
            if np.max(np.abs(np.asarray(g(base + s * v), dtype=float))) > tol:
                return False
        except UnsolvedError:  # V has no value there: the line is not all equilibria
            return False
    return True
