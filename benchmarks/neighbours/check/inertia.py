"""inertia: the body's mass, centre and tensors against the quadrature of its shape
(oracle/shapes.py), placed where the scene puts it at the configuration asked (or at a
random one where the answer keeps the coordinates): J_G = R J_body Rᵀ, J_P = J_G +
m (|d|² 1 − d dᵀ) with d = r_G − r_P, J′ = A J Aᵀ, principal moments by numpy's eigvalsh, each
principal axis e with J e = λ e, and J_axis = eᵀ J_P e."""

from __future__ import annotations

import mpmath
import numpy as np

from benchmarks.neighbours.check.context import Context, Mismatch, close, fmt, points_for, rtol


def _float_vec(s, text, q):
    return np.array([float(x) for x in s.value(text, q)])


def check(ctx: Context, question, result: dict) -> None:
    answers = result["answers"]
    opts = question.options
    tol = max(rtol(result), 1e-9)
    coords = [c.name for c in ctx.scene.coords]
    names = [b.name for b in ctx.scene.bodies]
    name = opts.get("body", names[0] if names else None)
    for i in points_for(ctx, result):
        s = ctx.system(i)
        p = ctx.points[i]
        at = opts.get("at", {})
        q = [ctx.const(at[c], i) if c in at else mpmath.mpf(float(ctx.rng.uniform(-1, 1))) for c in coords]
        body = s.bodies[names.index(name)]
        P = s.pose(q, 0)
        k = names.index(name)
        R = np.array([[float(x) for x in row] for row in P[12 * k + 3:12 * k + 12].reshape(3, 3)])
        rG = np.array([float(x) for x in P[12 * k:12 * k + 3]])
        m = body.mass
        JG = R @ body.inertia @ R.T
        about = opts.get("about")
        if about is None:
            JP = JG
        else:
            rp = _float_vec(s, about, q) if isinstance(about, str) else np.array([float(ctx.const(x, i)) for x in about] + [0.0] * (3 - len(about)))
            d = rG - rp
            JP = JG + m * (d @ d * np.eye(3) - np.outer(d, d))
        A = np.eye(3)
        if "axes" in opts:
            A = np.array([[float(ctx.const(x, i)) for x in row] for row in opts["axes"]])
        JGp, JPp = A @ JG @ A.T, A @ JP @ A.T
        scale = np.abs(JPp).max() + np.abs(JGp).max() + 1e-300
        rd = lambda x: ctx.reader.value(x, p, q)  # noqa: E731
        if "mass" in answers and not close(rd(answers["mass"]), m, 0, tol):
            raise Mismatch(f"mass: rbdsolve {answers['mass']}, oracle {m:.12g}")
        got_c = [float(rd(x)) for x in answers.get("centre", rG)]
        if np.abs(np.array(got_c) - rG).max() > tol * (np.abs(rG).max() + s.length):
            raise Mismatch(f"centre: rbdsolve {fmt(got_c)}, oracle {fmt(list(rG))}")
        for key, want in (("J_G", JGp), ("J", JPp)):
            if key not in answers:
                continue
            got = np.array([[float(rd(x)) for x in row] for row in answers[key]])
            if np.abs(got - want).max() > tol * scale:
                raise Mismatch(f"{key}: rbdsolve {got.round(12).tolist()}, oracle {want.round(12).tolist()}")
        lam = np.linalg.eigvalsh((JPp + JPp.T) / 2)
        got = sorted(float(rd(x)) for x in answers.get("principal_moments", lam))
        if np.abs(np.array(got) - lam).max() > max(tol, 1e-9) * scale:
            raise Mismatch(f"principal moments: rbdsolve {fmt(got)}, oracle {fmt(list(lam))}")
        for lam_s, axis in zip(answers.get("principal_moments", []), answers.get("principal_axes", [])):
            e = np.array([float(rd(x)) for x in axis])
            if abs(np.linalg.norm(e) - 1) > 1e-8 or np.linalg.norm(JPp @ e - float(rd(lam_s)) * e) > max(tol, 1e-9) * scale:
                raise Mismatch(f"principal axis {fmt(list(e))} is not a unit eigenvector of J for {lam_s}")
        if answers.get("J_axis") is not None:
            given = opts.get("axis", answers.get("axis"))  # without 'axis': the plane's normal, answered
            axis = list(ctx.const(given, i)) if isinstance(given, str) else given
            n = np.array([float(ctx.const(x, i)) for x in axis] + [0.0] * (3 - len(axis)))
            e = n / np.linalg.norm(n)
            want = e @ JP @ e
            got = float(rd(answers["J_axis"]))
            if abs(got - want) > tol * scale:
                raise Mismatch(f"J_axis: rbdsolve {got:.12g}, oracle {want:.12g}")
