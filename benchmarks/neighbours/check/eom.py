"""eom: rbdsolve's E_k = d/dt ∂L/∂q̇_k − ∂L/∂q_k against the oracle's generalized
Newton–Euler residual at random states (q, q̇, q̈), term for term (the two are the same
function); its accelerations q̈ = −M⁻¹h against the oracle's at random states and at
the state asked for."""

from __future__ import annotations

import mpmath

from benchmarks.neighbours.check.common import Context, Mismatch, close, fmt, points_for, random_state, rtol


def check(ctx: Context, question, result: dict) -> None:
    answers = result["answers"]
    tol = rtol(result)
    coords = [c.name for c in ctx.scene.coords]
    for i in points_for(ctx, result):
        s = ctx.system(i)
        p = ctx.points[i]
        for _ in range(2):
            q, qd, qdd = random_state(ctx, i)
            E, S = s.residual(q, qd, qdd, sizes=True)
            floor = s.force_scale()
            for k, text in enumerate(answers["equations"]):
                got = ctx.reader.value(text, p, q, qd, qdd)
                if not close(got, E[k], S[k] + floor * 1e-3, tol):
                    raise Mismatch(f"equation {k + 1} at q={fmt(q)}, q̇={fmt(qd)}, q̈={fmt(qdd)}: "
                                   f"rbdsolve {fmt(got)}, oracle {fmt(E[k])}")
            acc = answers.get("accelerations") or {}
            if acc:
                want = s.accelerations(q, qd)
                for k, c in enumerate(coords):
                    got = ctx.reader.value(acc[c], p, q, qd)
                    if not close(got, want[k], _acc_scale(s, q, k), tol * 10):
                        raise Mismatch(f"acceleration of {c} at q={fmt(q)}, q̇={fmt(qd)}: rbdsolve {fmt(got)}, oracle {fmt(want[k])}")
        at = answers.get("at")
        if at and question.options:
            q, qd, _ = ctx.state(question.options, i)
            want = s.accelerations(q, qd)
            for k, c in enumerate(coords):
                got = ctx.reader.value(at[c], p)
                if not close(got, want[k], _acc_scale(s, q, k), tol * 10):
                    raise Mismatch(f"acceleration of {c} at the state asked: rbdsolve {fmt(got)}, oracle {fmt(want[k])}")
    _check_values(ctx, question, result)


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
