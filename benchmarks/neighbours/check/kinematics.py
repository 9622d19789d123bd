"""kinematics: each point's position, velocity, acceleration and speed at the state,
and each distance with its rate, against the oracle's path derivatives of the points
(fourth-order differences along q + s q̇ + s²/2 q̈, t + s)."""

from __future__ import annotations

import mpmath
import numpy as np

from benchmarks.neighbours.check.context import Context, Mismatch, close, fmt, points_for, rtol


def _path(s, text, q, qd, qdd):
    f = lambda qq, tt: np.array([s.one * x for x in s.value(text, qq, tt)], dtype=object)  # noqa: E731
    return s.path(f, q, qd, qdd, 0)


def check(ctx: Context, question, result: dict) -> None:
    answers = result["answers"]
    tol = rtol(result)
    coords = [c.name for c in ctx.scene.coords]
    at = question.options.get("at", {})
    for i in points_for(ctx, result):
        s = ctx.system(i)
        p = ctx.points[i]
        q = [ctx.const(at[c], i) for c in coords]
        qd = [ctx.const(at.get(f"dot({c})", 0), i) for c in coords]
        qdd = [ctx.const(at.get(f"ddot({c})", 0), i) for c in coords]
        full = all(f"ddot({c})" in at for c in coords) and all(f"dot({c})" in at for c in coords)
        names = question.options.get("points") or []
        names = [names] if isinstance(names, str) else names
        for k_, entry in enumerate(answers.get("points", [])):
            entry = {"point": names[k_], **entry}
            r, v, a = _path(s, entry["point"], q, qd, qdd)
            scale = s.length * (1 + sum(abs(x) for x in qd) + sum(abs(x) for x in qdd)) ** 2
            for key, want in (("position", r), ("velocity", v), ("acceleration", a)):
                if key != "position" and not full or key not in entry:
                    continue
                got = [ctx.reader.value(x, p) for x in entry[key]]
                for k in range(3):
                    if not close(got[k], want[k], scale * 1e-3, tol):
                        raise Mismatch(f"{key} of {entry['point']}: rbdsolve {fmt(got)}, oracle {fmt(list(want))}")
            if full and "speed" in entry:
                speed = ctx.reader.value(entry["speed"], p)
                if not close(speed, mpmath.sqrt(v.dot(v)), scale * 1e-3, tol):
                    raise Mismatch(f"speed of {entry['point']}: rbdsolve {fmt(speed)}, oracle {fmt(mpmath.sqrt(v.dot(v)))}")
        pairs = question.options.get("distance") or []
        pairs = [pairs] if pairs and isinstance(pairs[0], str) else pairs
        for k_, entry in enumerate(answers.get("distances") or []):
            a_, b_ = entry.get("between") or pairs[k_]
            ra, va, _ = _path(s, a_, q, qd, qdd)
            rb, vb, _ = _path(s, b_, q, qd, qdd)
            d = rb - ra
            dist = mpmath.sqrt(d.dot(d))
            got = ctx.reader.value(entry["distance"], p)
            if not close(got, dist, s.length * 1e-3, tol):
                raise Mismatch(f"distance {a_}{b_}: rbdsolve {fmt(got)}, oracle {fmt(dist)}")
            if full and dist > 0 and "rate" in entry:
                rate = d.dot(vb - va) / dist
                got = ctx.reader.value(entry["rate"], p)
                if not close(got, rate, s.length * 1e-3, tol):
                    raise Mismatch(f"rate of the distance {a_}{b_}: rbdsolve {fmt(got)}, oracle {fmt(rate)}")
