"""impact: the velocities after, the points' and particles' velocities, the collision
and sticking impulses, the generalized impulses, the energies and the supports'
impulse, against impulse and momentum on the bodies (oracle/impact.py)."""

from __future__ import annotations

import mpmath
import numpy as np

from benchmarks.neighbours.check.context import Context, Mismatch, close, fmt, points_for, rtol
from benchmarks.neighbours.oracle.impact import Collision, solve

_AXES = {"x": [1, 0], "-x": [-1, 0], "y": [0, 1], "-y": [0, -1]}


def _vec(ctx, v, i):
    if isinstance(v, str) and v in _AXES:
        return [mpmath.mpf(x) for x in _AXES[v]]
    if isinstance(v, str):
        return list(ctx.const(v, i))[:2]
    return [ctx.const(x, i) for x in v][:2]


def _unit(v):
    n = mpmath.sqrt(v[0] ** 2 + v[1] ** 2)
    return [v[0] / n, v[1] / n]


def oracle(ctx: Context, question, i: int):
    """The oracle's impact at point i: (system, q, q̇ before, result, collisions, impulses)."""
    s = ctx.system(i)
    opts = question.options
    coords = [c.name for c in ctx.scene.coords]
    q = [ctx.const(opts.get("at", {}).get(c, 0), i) for c in coords]
    qd0 = [ctx.const(opts.get("before", {}).get(c, 0), i) for c in coords]
    cols = []
    for point, c in (opts.get("collisions") or {}).items():
        particle = c.get("particle") or {}
        cols.append(Collision(point, _unit(_vec(ctx, c["normal"], i)) if "normal" in c else None,
                              ctx.const(c["restitution"], i) if "restitution" in c else None,
                              ctx.const(particle["mass"], i) if particle else None,
                              _vec(ctx, particle["velocity"], i) if particle else None,
                              _vec(ctx, particle["after"], i) if "after" in particle else None,
                              bool(c.get("sticks"))))
    imp = {p: _vec(ctx, v, i) for p, v in (opts.get("impulses") or {}).items()}
    return s, q, qd0, solve(s, q, qd0, cols, imp), cols, imp


def check(ctx: Context, question, result: dict) -> None:
    answers = result["answers"]
    tol = rtol(result)
    coords = [c.name for c in ctx.scene.coords]
    for i in points_for(ctx, result):
        s, q, qd0, out, cols, imp = oracle(ctx, question, i)
        if out["residual"] > 1e-15:
            raise AssertionError(f"the oracle's bodies leave the coordinates' motions (residual {fmt(out['residual'])}): "
                                 "a support the coordinates imply is not among the oracle's (from_problem.SUPPORTS)")
        p = ctx.points[i]
        rd = lambda x: ctx.reader.value(x, p)  # noqa: E731
        vscale = max([abs(x) for x in out["V0"] + out["V1"]] + [mpmath.mpf(1)])
        qd1 = out["qd"]
        for k, c in enumerate(coords):
            got = rd(answers["velocities"][c])
            if not close(got, qd1[k], vscale / s.scale[k], tol):
                raise Mismatch(f"{c} after: rbdsolve {fmt(got)}, oracle {fmt(qd1[k])}")
        for name, vec in (answers.get("points") or {}).items():
            f = lambda qq, tt: np.array([s.one * x for x in s.value(name, qq, tt)], dtype=object)  # noqa: E731
            d = s.partials(f, q, 0)
            want = sum((d[k] * qd1[k] for k in range(s.n)), np.zeros(3, dtype=object) * s.one)
            got = [rd(x) for x in vec]
            if any(not close(got[k], want[k], vscale, tol) for k in range(3)):
                raise Mismatch(f"velocity of {name} after: rbdsolve {fmt(got)}, oracle {fmt(list(want))}")
        part_after, sizes, sticking = {}, {}, {}
        for j, (kind, obj, d) in enumerate(out["columns"]):
            if kind == "collision":
                sizes[obj.point] = out["impulses"][j]
                part_after[obj.point] = [obj.velocity[k] - out["impulses"][j] * obj.normal[k] / obj.mass
                                         for k in range(2)] if obj.mass is not None else None
            elif kind == "stick":
                sticking.setdefault(obj.point, [s.zero, s.zero])[d] = out["impulses"][j]
        for c in cols:
            if c.sticks and c.velocity is not None:  # a particle that sticks (a body's point has no velocity of its own)
                P = sticking[c.point]
                part_after[c.point] = [c.velocity[k] - P[k] / c.mass for k in range(2)]
            elif c.after is not None:
                part_after[c.point] = c.after
        pscale = max([abs(x) for x in out["impulses"]] + [abs(m) * vscale for m in out["mass"]])
        for name, size in (answers.get("contact_impulses") or {}).items():
            if not close(rd(size), sizes[name], pscale, tol):
                raise Mismatch(f"impulse at {name}: rbdsolve {size} = {fmt(rd(size))}, oracle {fmt(sizes[name])}")
        for name, vec in (answers.get("sticking_impulses") or {}).items():
            got = [rd(x) for x in vec][:2]
            if any(not close(got[k], sticking[name][k], pscale, tol) for k in range(2)):
                raise Mismatch(f"sticking impulse at {name}: rbdsolve {fmt(got)}, oracle {fmt(sticking[name])}")
        for name, vec in (answers.get("particles") or {}).items():
            got = [rd(x) for x in vec][:2]
            want = part_after.get(name)
            if want is not None and any(not close(got[k], want[k], vscale, tol) for k in range(2)):
                raise Mismatch(f"particle at {name} after: rbdsolve {fmt(got)}, oracle {fmt(want)}")
        _energies(ctx, s, answers, out, cols, part_after, rd, tol, q, qd0)
        _generalized(ctx, s, answers, out, cols, imp, sticking, q, rd, tol, pscale)
        _implied(ctx, s, answers, out, cols, q, rd, tol)
        _percussion(ctx, question, answers, i, rd)


def _partials(s, name, q):
    f = lambda qq, tt: np.array([s.one * x for x in s.value(name, qq, tt)], dtype=object)  # noqa: E731
    return s.partials(f, q, 0)


def _generalized(ctx, s, answers, out, cols, imp, sticking, q, rd, tol, pscale):
    """I_a = Σ P·∂r_P/∂q_a over the impulses on the system (known, collisions, sticking)."""
    on = [(name, P) for name, P in imp.items()]
    for j, (kind, obj, d) in enumerate(out["columns"]):
        if kind == "collision":
            on.append((obj.point, [out["impulses"][j] * obj.normal[k] for k in range(2)]))
    for c in cols:
        if c.after is not None:
            on.append((c.point, [c.mass * (c.velocity[k] - c.after[k]) for k in range(2)]))
    on += list(sticking.items())
    coords = [c.name for c in ctx.scene.coords]
    want = [s.zero] * s.n
    for name, P in on:
        d = _partials(s, name, q)
        want = [want[a] + d[a][0] * P[0] + d[a][1] * P[1] for a in range(s.n)]
    for a, c in enumerate(coords):
        got = (answers.get("impulses") or {}).get(c)
        if got is not None and not close(rd(got), want[a], pscale * s.scale[a], tol):
            raise Mismatch(f"generalized impulse of {c}: rbdsolve {fmt(rd(got))}, oracle {fmt(want[a])}")


def _implied(ctx, s, answers, out, cols, q, rd, tol):
    """A particle brought to a given velocity: e = −n·(v_P − u) after / n·(v_P − u) before,
    n along its impulse."""
    from benchmarks.neighbours.oracle.impact import _point_jacobian, body_of_point
    for c in cols:
        got = (answers.get("restitution") or {}).get(c.point)
        if c.after is None or got is None:
            continue
        P = [c.mass * (c.velocity[k] - c.after[k]) for k in range(2)]
        n = _unit(P)
        i, _ = body_of_point(s, c.point, q)
        Jp = _point_jacobian(s, i, s.vector(c.point, q), q)
        v = lambda V: [sum(Jp[k][a] * V[3 * i + a] for a in range(3)) for k in range(2)]  # noqa: E731
        before = sum(n[k] * (v(out["V0"])[k] - c.velocity[k]) for k in range(2))
        after = sum(n[k] * (v(out["V1"])[k] - c.after[k]) for k in range(2))
        if not close(rd(got), -after / before, 1, tol):
            raise Mismatch(f"implied restitution at {c.point}: rbdsolve {fmt(rd(got))}, oracle {fmt(-after / before)}")


def _percussion(ctx, question, answers, i, rd):
    """The centre of percussion: at that value of its parameter the supports give no impulse."""
    name = question.options.get("centre_of_percussion")
    got = answers.get("centre_of_percussion")
    if not name or got is None:
        return
    value = rd(got)
    ctx.points.append({**ctx.points[i], name: value})
    try:
        j = len(ctx.points) - 1
        s, q, qd0, out, cols, imp = oracle(ctx, question, j)
        support = [s.zero, s.zero]
        for k, (kind, obj, d) in enumerate(out["columns"]):
            if kind == "support" and obj.by is None:
                support = [support[a] + out["impulses"][k] * d[a] for a in range(2)]
        size = max(abs(x) for x in out["impulses"]) + 1
        if max(abs(x) for x in support) > 1e-9 * size:
            raise Mismatch(f"at {name} = {fmt(value)} (the centre of percussion) the oracle's support impulse is {fmt(support)}")
    finally:
        ctx.points.pop()
        ctx._systems.pop((len(ctx.points), True), None)


def _energies(ctx, s, answers, out, cols, part_after, rd, tol, q, qd0):
    def kinetic(V, particles):
        T = sum(out["mass"][r] * V[r] ** 2 for r in range(len(V))) / 2
        return T + sum(c.mass * (u[0] ** 2 + u[1] ** 2) / 2 for c, u in particles if c.mass is not None and u is not None)
    before = kinetic(out["V0"], [(c, c.velocity) for c in cols])
    after = kinetic(out["V1"], [(c, part_after.get(c.point)) for c in cols])
    scale = abs(before) + abs(after) + mpmath.mpf("1e-30")
    for key, want in (("energy_before", before), ("energy_after", after), ("energy_lost", before - after)):
        if answers.get(key) is not None and not close(rd(answers[key]), want, scale, tol):
            raise Mismatch(f"{key}: rbdsolve {fmt(rd(answers[key]))}, oracle {fmt(want)}")
    support = answers.get("support_impulse")
    if support is not None:
        want = [s.zero, s.zero]
        for j, (kind, obj, d) in enumerate(out["columns"]):
            if kind == "support" and obj.by is None:  # a joint's impulses cancel in the sum
                want = [want[k] + out["impulses"][j] * d[k] for k in range(2)]
        got = [rd(x) for x in support][:2]
        pscale = max([abs(x) for x in out["impulses"]] + [mpmath.mpf(1)])
        if any(not close(got[k], want[k], pscale, tol) for k in range(2)):
            raise Mismatch(f"support impulse: rbdsolve {fmt(got)}, oracle {fmt(want)}")
