"""steady_spin: the principal moments against the quadrature's (as a set); in each case
the parameters allow, every steady spin ω must satisfy Euler's equations ω × Jω = 0
with those moments, and its stability and rate come from the eigenvalues of the
Jacobian of Euler's equations ω̇ = J⁻¹ (Jω × ω) at ω, computed numerically: all
imaginary (stable, ν the largest), one real positive (unstable, γ), all zero
(neutral). The precession of an axisymmetric body: ω = φ̇ L̂ + ψ̇ e₃ splits ω along L
and the axis, φ̇ = |L|/A the space rate, −ψ̇ the body rate; the angles from the vectors."""

from __future__ import annotations

import mpmath
import numpy as np

from benchmarks.neighbours.check.context import Context, Mismatch, close, fmt, points_for, rtol

FREE = {"Omega": 1.3, "w1": 0.7, "w2": -0.4, "w3": 0.9}


def _cross_matrix(v):
    return np.array([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])


def _euler_jacobian(J, w):
    """Eigenvalues of ∂/∂ω of J⁻¹ (Jω × ω): δ(Jω × ω) = (Jδ) × ω + (Jω) × δ."""
    J = np.asarray(J, float)
    A = np.diag(1 / J) @ (-_cross_matrix(w) @ np.diag(J) + _cross_matrix(J * w))
    return np.linalg.eigvals(A)


def check(ctx: Context, question, result: dict) -> None:
    answers = result["answers"]
    tol = max(rtol(result), 1e-9)
    for i in points_for(ctx, result):
        s = ctx.system(i)
        p = ctx.points[i]
        J_or = np.linalg.eigvalsh(s.bodies[0].inertia)
        if result.get("route") == "numeric":
            got = sorted(float(x) for x in answers["moments"])
            if np.abs(np.array(got) - J_or).max() > tol * J_or.max():
                raise Mismatch(f"moments: rbdsolve {fmt(got)}, oracle {fmt(list(J_or))}")
            continue
        extra = {k: mpmath.mpf(v) for k, v in FREE.items() if k not in p}
        rd = lambda x: ctx.reader.value(x, p, extra=extra)  # noqa: E731
        if "moments" not in answers:
            J = list(J_or)
        else:
            J = [float(rd(x)) for x in answers["moments"]]
        if np.abs(np.sort(J) - J_or).max() > tol * J_or.max():
            raise Mismatch(f"moments: rbdsolve {fmt(J)}, oracle {fmt(list(J_or))}")
        for case in answers.get("cases") or []:
            if not _holds(ctx, case.get("condition") or {}, p, extra, J_or.max()):
                continue
            for j, entry in enumerate(case.get("stability") or []):
                entry = {"spin": case["steady_spins"][j], **entry}
                w = np.array([float(rd(x)) for x in entry["spin"]])
                if np.linalg.norm(np.cross(np.array(J) * w, w)) > 1e-9 * J_or.max() * (w @ w):
                    raise Mismatch(f"steady spin {entry['spin']} is not one: ω × Jω ≠ 0 with J = {fmt(J)}")
                _stability(ctx, entry, J, w, rd, J_or.max())
        if answers.get("precession"):
            _precession(ctx, question, answers["precession"], J, rd, i)


def _holds(ctx, condition, p, extra, scale) -> bool:
    for a, b in condition.get("equal", []):
        if abs(ctx.reader.value(a, p, extra=extra) - ctx.reader.value(b, p, extra=extra)) > 1e-9 * scale:
            return False
    for a, b in condition.get("different", []):
        if abs(ctx.reader.value(a, p, extra=extra) - ctx.reader.value(b, p, extra=extra)) <= 1e-9 * scale:
            return False
    return True


def _stability(ctx, entry, J, w, rd, scale):
    ev = _euler_jacobian(J, w)
    top = np.abs(w).max()
    real, imag = np.abs(ev.real).max(), np.abs(ev.imag).max()
    want = "unstable" if real > 1e-6 * top else ("stable" if imag > 1e-6 * top else "neutral")
    word = entry["stability"]
    if word == "conditional":
        word = "stable" if float(rd(entry["condition"])) > 0 else "unstable"
    if word != want:
        raise Mismatch(f"spin {entry['spin']}: rbdsolve {entry['stability']} ({word}), the oracle's Euler Jacobian "
                       f"has eigenvalues {fmt(list(ev))}: {want}")
    if entry.get("rate") is not None:
        rate = abs(float(rd(entry["rate"])))
        mine = real if want == "unstable" else imag
        if abs(rate - mine) > 1e-5 * max(mine, 1e-12):
            raise Mismatch(f"spin {entry['spin']}: rate rbdsolve {rate:.10g}, oracle {mine:.10g}")


def _precession(ctx, question, pre, J, rd, i):
    opts = question.options["precession"]
    J = sorted(J)
    A, C = (J[1], J[0]) if abs(J[1] - J[2]) < 1e-9 * J[2] else (J[1], J[2])  # A repeated, C about the axis
    J = [A, A, C]
    axis = 2
    w3 = float(ctx.const(opts["spin"], i))
    if "transverse" in opts:
        wt = float(ctx.const(opts["transverse"], i))
    else:
        wt = w3 * float(mpmath.tan(ctx.const(opts["angle"], i)))
    omega = np.zeros(3)
    omega[axis] = w3
    omega[(axis + 1) % 3] = wt
    Jv = np.array(J)
    L = Jv * omega
    Ln = np.linalg.norm(L)
    e3 = np.zeros(3)
    e3[axis] = 1
    space = Ln / A
    body = -(omega - space * L / Ln) @ e3  # ω = φ̇ L̂ + ψ̇ e₃, the body rate −ψ̇
    ang = lambda a, b: float(np.arccos(np.clip(a @ b / np.linalg.norm(a) / np.linalg.norm(b), -1, 1)))  # noqa: E731
    want = {"omega": np.linalg.norm(omega), "angular_momentum": Ln, "space_rate": space, "body_rate": body,
            "alpha": ang(omega, e3), "nu": ang(L, e3), "gamma": ang(omega, L)}
    for key, value in want.items():
        if pre.get(key) is None:
            continue
        got = float(rd(pre[key]))
        if abs(got - value) > 1e-8 * max(abs(value), 1.0):
            raise Mismatch(f"precession {key}: rbdsolve {got:.12g}, oracle {value:.12g}")
