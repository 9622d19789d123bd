"""The numeric modes' bound, widened by the equilibrium's own error.

The pencil's bound (numeric.py ``eigen_bounds``) holds for M and K at the point q₀ the
route uses. An equilibrium found in floating point (or a value such as π rounded to a
float) is not the equilibrium q*: there, in 50 digits, ∂V/∂q = g ≠ 0, and to first
order q* = q₀ − δq with δq = K⁻¹ g. Each eigenvalue then moves by about

    Δλ = Σ_j (∂λ/∂q_j) δq_j,

∂λ/∂q_j by central differences of the float pencil (steps far above rounding:
h = 1e-6 max(|q_j|, 1)). Twice |Δλ| is added to the bound (first order, with room for
the second). A weighted disk rolling in a track, λ about φ₀ = −acos(5/6): the float
root is 5e-16 from φ₀, |∂λ/∂φ| = 84, so λ is off by 2.5e-14 where the pencil's bound
said 1.2e-14. Zero where g = 0 at q₀ (an equilibrium exact in floats, the hanging
state 0 of a chain); not measured past SIZE coordinates or where the scene has no
50-digit model (frames, 3D turns: the exact Jacobians' path).
"""

from __future__ import annotations

from typing import Callable, Mapping

import numpy as np
import sympy as sp

from rbdsolve.model.build import Model

SIZE = 12  # up to this many coordinates the equilibrium's own error is measured
STEP = 1e-6  # the central differences' step, relative to max(|q_j|, 1)

PencilAt = Callable[[Mapping[str, sp.Expr]], tuple[np.ndarray, np.ndarray]]  # about -> (M, K) as floats


def location_bounds(model: Model, about: Mapping[str, sp.Expr], K: np.ndarray, lam: np.ndarray,
                    pencil: PencilAt) -> np.ndarray:
    """2 |Σ_j ∂λ/∂q_j δq_j| per eigenvalue (the module docstring); zeros where not measured."""
    from rbdsolve.model.numeric.jet import MP50
    from rbdsolve.solvers.numeric.numeric_model import as_floats, numeric_scene

    zero = np.zeros(len(lam))
    scene = numeric_scene(model, MP50) if len(about) <= SIZE else None
    if scene is None:
        return zero
    names = list(about)
    q0 = np.array(list(as_floats(model, about).values()))
    g = np.array([float(x) for x in scene.gradient(list(q0))])
    if not np.any(g):
        return zero
    try:
        dq = np.linalg.solve(K, g)
    except np.linalg.LinAlgError:
        return zero
    slope = np.zeros((len(lam), len(names)))
    for j in range(len(names)):
        h = STEP * max(abs(q0[j]), 1.0)
        ahead, behind = (_eigenvalues(pencil, dict(zip(names, q0 + s * h * np.eye(len(names))[j]))) for s in (1, -1))
        slope[:, j] = (ahead - behind) / (2 * h)
    return 2 * np.abs(slope @ dq)


def _eigenvalues(pencil: PencilAt, about: Mapping[str, float]) -> np.ndarray:
    from rbdsolve.solvers.numeric.dense import symmetric_pencil_values

    M, K = pencil({n: sp.Float(v, 17) for n, v in about.items()})
    return symmetric_pencil_values(K, M)
