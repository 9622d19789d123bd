"""Every body's pose at many points at once, in floats: the placement expressions
evaluated once on arrays of coordinates (one element per point, ``expr.ARRAYS``)
instead of once per point.

The formulas are System.pose's: r_b = o_b + R_b c_b (o_b the body's origin, c_b its
centre in body axes), R_b the product of its turns about coordinate axes, each by
Rodrigues R = 1 + sin a K + (1 − cos a) K² (K = u× for the axis u), or one turn about
z in a plane. A finite difference needs f at 4 points per coordinate (System.stencil)
and a path derivative at 5 (System.path); numpy's cost is per call, nearly whatever the
number of points, so one call for all of them (and, in the search, for the points of
many Newton runs at once) is what makes the float searches cheap."""

from __future__ import annotations

import numpy as np

from benchmarks.neighbours.expr import Env, evaluate

_AXES = {"x": (1, 0, 0), "y": (0, 1, 0), "z": (0, 0, 1), "-x": (-1, 0, 0), "-y": (0, -1, 0), "-z": (0, 0, -1)}


def _spread(x, count: int) -> np.ndarray:
    """x at every point: a value that does not depend on the point is repeated."""
    if isinstance(x, np.ndarray) and x.shape == (count,):
        return x
    return np.full(count, float(x))


def _turn(axis: str, a, count: int) -> np.ndarray:
    """The rotations by the angles ``a`` about a coordinate axis, shape (points, 3, 3)."""
    c, s = np.cos(_spread(a, count)), np.sin(_spread(a, count))
    if axis == "z":
        R = np.zeros((count, 3, 3))
        R[:, 0, 0], R[:, 0, 1], R[:, 1, 0], R[:, 1, 1], R[:, 2, 2] = c, -s, s, c, 1.0
        return R
    u = _AXES[axis]
    K = np.array([[0, -u[2], u[1]], [u[2], 0, -u[0]], [-u[1], u[0], 0]], float)
    # the sum in System's order, 1 + s K + (1 − c) K², term by term
    return np.eye(3) + s[:, None, None] * K + (1 - c)[:, None, None] * K.dot(K)


def _rotation(body, env: Env, count: int) -> np.ndarray:
    if body.turns:
        R = np.broadcast_to(np.eye(3), (count, 3, 3))
        for axis, angle in body.turns:
            R = R @ _turn(axis, evaluate(angle, env), count)
        return R
    return _turn("z", evaluate(body.angle, env) if body.angle else 0.0, count)


def poses(system, env: Env, count: int) -> np.ndarray:
    """[r (3), R (9)] per body down the rows, one column per point: shape (12 bodies, points)."""
    rows = []
    for mb, c in zip(system.bodies, system.centres):
        R = _rotation(mb.spec, env, count)
        o = np.stack([_spread(x, count) for x in evaluate(mb.spec.origin, env)])
        rows.append(o + (R @ c).T)
        rows.append(R.reshape(count, 9).T)
    return np.concatenate(rows) if rows else np.zeros((0, count))


def at_points(f, n: int, points: list) -> list:
    """f(q, t) at each of ``points``, from one call of f on arrays (q_k and t with one
    element per point; f's result has the points along its last axis).

    math raises where numpy would go on with inf or nan (a square root of a negative, a
    division by zero): where numpy meets one, or f fails on arrays at all, the points
    are evaluated one by one, so that the values and the exceptions stay the floats'."""
    Q = [np.array([q[k] for q, _ in points], float) for k in range(n)]
    try:
        with np.errstate(divide="raise", over="raise", invalid="raise"):
            F = np.asarray(f(Q, np.array([t for _, t in points], float)), float)
    except Exception:  # noqa: BLE001 - any failure on arrays: the scalar evaluation decides
        return [f(q, t) for q, t in points]
    if F.ndim == 0:  # f does not depend on the point (no springs: V = 0)
        F = np.full(len(points), float(F))
    return [F[..., j] for j in range(len(points))]
