"""A floating-point equilibrium's coordinates recognized as simple exact values: a
coordinate within its error bound of 0, ±π/2 or ±π is that value (−3.08e-32 is 0,
3.141592653589793 is π), so the equilibria, the modes about them and the contacts'
pushes there (equilibria/contact_push.py) take the one configuration the same way.

The error bound of a root x of ∂V/∂q = 0 (g its value there, H the Hessian):

    (|H⁻¹ g| + ‖H⁻¹‖ δg) / max(|x|, 1) + cond(H) ε,

one more Newton step, and how far the rounding of ∂V/∂q's terms moves the root: δg =
ROUNDING_UNITS n ε × the size of ∂V/∂q over the search box (``slope_scale``): g in
floats sums terms that large whatever its own size, so at a root where H is small (a
rod on springs near its critical stiffness) the root moves by δg/|H|, and the g
computed there may round to almost 0 and say nothing of it (roots 7e-12 off were said
within 4e-16). On a continuum H and g are taken across it only: along it the
representative is exact by construction.
"""

from __future__ import annotations

import math

import numpy as np
import sympy as sp

from rbdsolve.model.build import Model
from rbdsolve.solvers.numeric.numeric_model import compiled_gradient, rounding, slope_scale

EPS = float(np.finfo(float).eps)
EXACT = {"0": sp.Integer(0), "pi/2": sp.pi / 2, "-pi/2": -sp.pi / 2, "pi": sp.pi, "-pi": -sp.pi}
SIMPLE = tuple((text, float(value)) for text, value in EXACT.items())
RECOGNIZED_BELOW = 1e-6  # a larger bound: a value only near π is not taken as π


def root_error(x: np.ndarray, gradient: np.ndarray, hess: np.ndarray, free, slope: float) -> float:
    """The module docstring's bound, relative to max(|x|, 1); ``free``: the directions
    of a continuum through x; inf where H (across it) is singular."""
    if free:
        from rbdsolve.solvers.numeric.dense import null_space

        P = null_space(np.array(free, dtype=float))  # orthonormal basis across the continuum
        hess, gradient = P.T @ hess @ P, P.T @ gradient
    try:
        step = np.linalg.solve(hess, gradient) if hess.size else np.zeros(0)
        condition = np.linalg.cond(hess) if hess.size else 1.0
        inverse = np.linalg.norm(np.linalg.inv(hess), 2) if hess.size else 0.0
    except np.linalg.LinAlgError:
        return float("inf")
    moved = inverse * rounding(len(x), slope)
    return float((np.max(np.abs(step), initial=0.0) + moved) / max(np.max(np.abs(x)), 1.0) + condition * EPS)


def recognize(at: dict[str, float], bound: float) -> tuple[dict[str, float], dict[str, str], float | None]:
    """Each coordinate within ``bound`` (its error bound, absolute) of a simple exact value
    is that value, with the bound beside it: (values, name -> the value's key in EXACT,
    bound), or (at, {}, None) where none is, or the bound is not finite and below
    RECOGNIZED_BELOW."""
    if not math.isfinite(bound) or bound >= RECOGNIZED_BELOW:
        return at, {}, None
    recognized = {name: text for name, value in at.items() for text, exact in SIMPLE if abs(value - exact) <= bound}
    if not recognized:
        return at, {}, None
    exact = dict(SIMPLE)
    return {n: exact[recognized[n]] if n in recognized else v for n, v in at.items()}, recognized, bound


def shown(name: str, value: float, recognized: dict[str, str]) -> sp.Expr:
    """A coordinate as the listing writes it: exactly where recognized, else its float."""
    return EXACT[recognized[name]] if name in recognized else sp.Float(value, 15)


def recognized_root(model: Model, root, hess: np.ndarray) -> tuple[float, dict, dict, float | None]:
    """A root the numeric search found (``.at``, ``.free``; ``hess``, the Hessian there):
    its relative error bound (``root_error``, with ∂V/∂q there and its scale over the
    box) and ``recognize``'s values, recognized names and bound, with that error as an
    absolute bound. The equilibria's listing and the modes about its roots both read it."""
    g, _ = compiled_gradient(model)
    x = np.array(root.at, dtype=float)
    error = root_error(x, np.asarray(g(x), dtype=float), hess, root.free, slope_scale(model))
    at = dict(zip(model.coordinate_names(), root.at))
    return (error, *recognize(at, error * max(float(np.max(np.abs(x))), 1.0)))


def exactly(model: Model, root) -> dict[str, sp.Expr]:
    """A root the numeric search found, name -> value, each coordinate recognized as the
    equilibria's listing recognizes it exact (π), the others as 17-digit floats: the
    modes about it name it as the listing does."""
    _, H = compiled_gradient(model)
    _, _, recognized, _ = recognized_root(model, root, np.asarray(H(np.array(root.at, dtype=float)), dtype=float))
    return {n: EXACT[recognized[n]] if n in recognized else sp.Float(float(v), 17)
            for n, v in zip(model.coordinate_names(), root.at)}
