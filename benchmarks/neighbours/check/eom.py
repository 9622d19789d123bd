"""eom: rbdsolve's E_k = d/dt ∂L/∂q̇_k − ∂L/∂q_k against the oracle's generalized
Newton–Euler residual at random states (q, q̇, q̈), term for term (the two are the same
function); its accelerations q̈ = −M⁻¹h against the oracle's at random states and at
the state asked for."""

from __future__ import annotations

import mpmath

from benchmarks.neighbours.check.context import Context, Mismatch, close, fmt, points_for, random_state, rtol


def check(ctx: Context, question, result: dict) -> None:
    answers = result["answers"]
    tol = rtol(result)
    coords = [c.name for c in ctx.scene.coords]
    for i in points_for(ctx, result):
        s = ctx.system(i)
        p = ctx.points[i]
        for _ in range(2):
            q, qd, qdd = random_state(ctx, i)
            t = mpmath.mpf(0) if s.static else mpmath.mpf(float(ctx.rng.uniform(0, 2)))
            E, S = s.residual(q, qd, qdd, t, sizes=True)
            floor = s.force_scale()
            for k, text in enumerate(answers.get("equations") or []):
                got = ctx.reader.value(text, p, q, qd, qdd, t=t)
                if not close(got, E[k], S[k] + floor * 1e-3, tol):
                    raise Mismatch(f"equation {k + 1} at q={fmt(q)}, q̇={fmt(qd)}, q̈={fmt(qdd)}: "
                                   f"rbdsolve {fmt(got)}, oracle {fmt(E[k])}")
            acc = answers.get("accelerations") or {}
            if acc:
                want = s.accelerations(q, qd, t)
                for k, c in enumerate(coords):
                    got = ctx.reader.value(acc[c], p, q, qd, t=t)
                    if not close(got, want[k], _acc_scale(s, q, k), tol * 10):
                        raise Mismatch(f"acceleration of {c} at q={fmt(q)}, q̇={fmt(qd)}: rbdsolve {fmt(got)}, oracle {fmt(want[k])}")
        _frames(ctx, answers, s, p, tol, i)
        at = answers.get("at")
        if at and question.options and s.static:
            q, qd, _ = ctx.state(question.options, i)
            want = s.accelerations(q, qd)
            for k, c in enumerate(coords):
                got = ctx.reader.value(at[c], p)
                if not close(got, want[k], _acc_scale(s, q, k), tol * 10):
                    raise Mismatch(f"acceleration of {c} at the state asked: rbdsolve {fmt(got)}, oracle {fmt(want[k])}")
    _check_values(ctx, question, result)


def _frames(ctx, answers, s, p, tol, i):
    """The equations in each frame asked for: the same coordinates, so the same E_k, at
    a state drawn for parameter point i (the one they are evaluated at: point 0's state
    may put a spring past zero length at point i's, where the equations do not hold)."""
    for frame in answers.get("frames") or []:
        q, qd, qdd = random_state(ctx, i)
        E, S = s.residual(q, qd, qdd, mpmath.mpf(0), sizes=True)
        for k, text in enumerate(frame.get("equations") or []):
            got = ctx.reader.value(text, p, q, qd, qdd, t=mpmath.mpf(0))
            if not close(got, E[k], S[k] + s.force_scale() * 1e-3, tol):
                raise Mismatch(f"equation {k + 1} in frame {frame.get('frame')}: rbdsolve {fmt(got)}, oracle {fmt(E[k])}")
        if frame.get("equivalent") is False:
            raise Mismatch(f"frame {frame.get('frame')}: rbdsolve says its equations are not equivalent")


def _acc_scale(s, q, k):
    """A size of accelerations of coordinate k: the forces' scale over its mass term."""
    return s.force_scale() / max(abs(s.mass_matrix(q)[k][k]), mpmath.mpf("1e-300"))


def _check_values(ctx: Context, question, result: dict) -> None:
    """With every value given: the numbers of ``values.at`` against the oracle's."""
    values = result.get("values") or {}
    at = values.get("at")
    if not (at and ctx.all_given and question.options):
        return
    s = ctx.system(0)
    q, qd, _ = ctx.state(question.options, 0)
    want = s.accelerations(q, qd)
    for k, c in enumerate(ctx.scene.coords):
        got = at.get(c.name)
        if got is not None and not close(mpmath.mpf(got), want[k], _acc_scale(s, q, k), 1e-9):
            raise Mismatch(f"values.at.{c.name}: rbdsolve {got}, oracle {fmt(want[k])}")
