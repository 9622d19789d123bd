"""reactions: each support's force (and moment) against the oracle's Newton–Euler
balances of the bodies (oracle/reactions.py), at random states (the forces as functions
of the state), at the state asked for, and along the motion from rest (q̇² from the
oracle's T + V); where a push or tension vanishes along the motion (contact_lost)
against the oracle's own scan of it; the least friction |F|/N; and each ``holds_when``
at the values, with the friction coefficient drawn on both sides of |F|/N."""

from __future__ import annotations

import mpmath
import numpy as np

from benchmarks.neighbours.check.context import Context, Mismatch, Partial, close, fmt, points_for, random_state, rtol
from benchmarks.neighbours.check.energy import rate_squared
from benchmarks.neighbours.expr import FLOAT
from benchmarks.neighbours.oracle.reactions import directions, support_forces


def _components(s, sup, force, moment, q):
    """The support's components as rbdsolve names them (R_Px, R_Py; N_P, F_P; T_P; M_P)."""
    n = sup.name
    if sup.kind == "pivot":
        out = {f"R_{n}x": force[0], f"R_{n}y": force[1]}
        if not s.scene.planar:
            out[f"R_{n}z"] = force[2]
    else:
        dirs = directions(s, sup, q)
        first = {"guide": "N", "rolling": "N", "string": "T"}[sup.kind]
        out = {f"{first}_{n}": force.dot(dirs[0])}
        if sup.kind == "rolling":
            out[f"F_{n}"] = force.dot(dirs[1])
    if moment is not None:
        out[f"M_{n}"] = moment
    return out


def _compare(ctx, s, listed: dict, q, qd, i, where: str, tol: float, scale):
    forces, worst = support_forces(s, q, qd)
    if worst > 1e-12:
        raise AssertionError(f"the oracle's supports do not hold the motion (residual {fmt(worst)})")
    p = ctx.points[i]
    for name, entry in listed.items():
        if name not in forces:
            raise Mismatch(f"reaction at {name}: the oracle has no support there")
        force, moment, _ = forces[name]
        got = [ctx.reader.value(x, p, q, qd) for x in entry.get("force", [])]
        for k in range(len(got)):
            if not close(got[k], force[k], scale, tol):
                raise Mismatch(f"force at {name} {where}: rbdsolve {fmt(got)}, oracle {fmt(list(force))}")
        sup = next(x for x in ctx.scene.supports if x.name == name)
        comps = _components(s, sup, force, moment, q)
        for key, text in (entry.get("components") or {}).items():
            if key in comps:
                got = ctx.reader.value(text, p, q, qd)
                if not close(got, comps[key], scale, tol):
                    raise Mismatch(f"{key} {where}: rbdsolve {fmt(got)}, oracle {fmt(comps[key])}")
    return forces


def check(ctx: Context, question, result: dict) -> list[str]:
    answers = result["answers"]
    tol = rtol(result)
    opts = question.options
    coords = [c.name for c in ctx.scene.coords]
    numeric = result.get("route") == "numeric"
    notes: list[str] = []
    for i in points_for(ctx, result):
        s = ctx.system(i)
        scale = s.force_scale() / s.length
        if not numeric:
            q, qd, _ = random_state(ctx, i)
            _compare(ctx, s, answers.get("reactions") or {}, q, qd, i, f"at q={fmt(q)}, q̇={fmt(qd)}", tol, scale)
        if opts.get("from_rest") or opts.get("at"):
            q, qd, _ = ctx.state(opts, i)
            at = answers.get("at") or {}
            if numeric:
                _numeric_at(ctx, s, at, q, qd, scale)
            else:
                forces = _compare(ctx, s, at, q, qd, i, "at the state asked", tol, scale)
                _holds(ctx, s, answers.get("holds_when") or {}, forces, q, i, notes)
        if numeric or len(coords) != 1 or not opts.get("from_rest"):
            continue
        q0 = [ctx.const(opts["from_rest"][coords[0]], i)]
        zero = [mpmath.mpf(0)]
        rs = answers.get("rate_squared") or {}
        along = answers.get("along") or {}
        for frac in (0.25, 0.7):
            q = [q0[0] * (1 - frac)]
            w2 = rate_squared(s, (q0, zero), q)
            if rs.get(coords[0]) is not None:
                got = ctx.reader.value(rs[coords[0]], ctx.points[i], q)
                if not close(got, w2, abs(w2) + 1e-9, tol):
                    raise Mismatch(f"q̇² at {fmt(q[0])}: rbdsolve {fmt(got)}, oracle {fmt(w2)}")
            if w2 < 0 or not along:
                continue
            qd = [mpmath.sqrt(w2)]
            forces, _ = support_forces(s, q, qd)
            for name, comps in along.items():
                sup = next(x for x in ctx.scene.supports if x.name == name)
                mine = _components(s, sup, *forces[name][:2], q)
                for key, text in comps.items():
                    got = ctx.reader.value(text, ctx.points[i], q)
                    if key in mine and not close(got, mine[key], scale, tol):
                        raise Mismatch(f"{key} along the motion at {coords[0]} = {fmt(q[0])}: rbdsolve {fmt(got)}, "
                                       f"oracle {fmt(mine[key])}")
        _lost(ctx, s, answers, q0, i, scale, result.get("warnings") or [])
    return notes


def _numeric_at(ctx, s, at: dict, q, qd, scale):
    forces, _ = support_forces(s, q, qd)
    for name, comps in at.items():
        sup = next(x for x in ctx.scene.supports if x.name == name)
        mine = _components(s, sup, *forces[name][:2], q)
        for key, value in comps.items():
            if key in mine and value is not None and not close(mpmath.mpf(value), mine[key], scale, 1e-6):
                raise Mismatch(f"{key} at the state asked (numeric route): rbdsolve {value}, oracle {fmt(mine[key])}")


def _holds(ctx, s, holds: dict, forces, q, i, notes):
    """Each holds_when at the values: a push N ≥ 0 (a tension T ≥ 0) and, rolling, μ ≥ |F|/N."""
    for name, cond in holds.items():
        sup = next(x for x in ctx.scene.supports if x.name == name)
        if sup.kind == "pivot" or sup.two_sided:
            got = ctx.reader.truth(cond, ctx.points[i])
            if got is False:
                raise Mismatch(f"holds_when at {name} ({cond}) is False for a support held both ways")
            continue
        comps = _components(s, sup, *forces[name][:2], q)
        push = list(comps.values())[0]
        scale = s.force_scale() / s.length
        if abs(push) < 1e-9 * scale:
            continue
        if sup.kind == "rolling":
            need = abs(comps[f"F_{name}"]) / push if push > 0 else None
            for mu, want in ((need * 2 + 0.01, push > 0), (need / 2, False)) if need else ((1.0, False),):
                if need is not None and need < 1e-12 and mu == need / 2:
                    continue
                got = ctx.reader.truth(cond, ctx.points[i], extra={f"mu_{name}": mu})
                if got is not None and got != want:
                    raise Mismatch(f"holds_when at {name} ({cond}) is {got} with μ = {fmt(mu)}, but N = {fmt(push)}, "
                                   f"|F|/N = {fmt(need)}")
        else:
            got = ctx.reader.truth(cond, ctx.points[i])
            if got is not None and got != (push > 0):
                raise Mismatch(f"holds_when at {name} ({cond}) is {got}, but the oracle's push is {fmt(push)}")


def _lost(ctx, s, answers, q0, i, scale, warnings=()):
    """Where a push or tension vanishes along the motion from rest at q₀ (the part the
    motion reaches, q̇² ≥ 0, from q₀ to the first turning point): the oracle's zeros
    against the listed equations. A zero of a force that rbdsolve says has no closed
    form ('N_C = 0 along the motion has no closed-form solution') is a part not
    answered, with that reason, not a mismatch."""
    lost = answers.get("contact_lost") or {}
    if not lost:
        return
    zero = [mpmath.mpf(0)]
    side = -1 if float(s.generalized_force(q0)[0]) < 0 else 1
    qs = [q0[0] + side * k * mpmath.pi / 720 for k in range(0, 1441)]
    fs = ctx.system(i, FLOAT)  # the scan in floats, the zeros in 40 digits
    start = (list(map(float, q0)), [0.0])
    reach = []
    for q in qs:
        w2 = rate_squared(fs, start, [float(q)])
        if w2 < 0:
            break
        reach.append((q, w2))
    exists = answers.get("lost_exists_when") or {}
    two_sided = {x.name for x in ctx.scene.supports if x.two_sided}
    for key, eqs in lost.items():
        if key.split("_", 1)[1] in two_sided:
            if eqs:
                raise Mismatch(f"{key}: a support held both ways is never lost, rbdsolve lists {eqs}")
            continue
        conds = exists.get(key) or ["True"] * len(eqs)
        truth = [ctx.reader.truth(c, ctx.points[i]) for c in conds]
        if None in truth:
            continue  # too near a boundary to say
        eqs = [e for e, t in zip(eqs, truth) if t]
        name = key.split("_", 1)[1]
        sup = next(x for x in ctx.scene.supports if x.name == name)
        values = []
        for q, w2 in reach[::8]:
            # at the scan's last point the float q̇² ≥ 0 may be a rounding below 0 in 40 digits
            forces, _ = support_forces(s, [q], [mpmath.sqrt(max(rate_squared(s, (q0, zero), [q]), 0))])
            values.append((q, list(_components(s, sup, *forces[name][:2], [q]).values())[0]))
        zeros = [_bisect(s, sup, name, q0, a, b) for (a, fa), (b, fb) in zip(values, values[1:]) if fa * fb < 0]
        if values and abs(values[0][1]) < 1e-12 * scale:
            zeros.insert(0, q0[0])  # lost at the very start
        residual = lambda text, z: abs(ctx.reader.value(_side(ctx, text), ctx.points[i], [z]))  # noqa: E731
        unsolved = [w for w in warnings if w.startswith(f"{key} = 0") and "no closed-form" in w]
        for z in zeros:
            if not any(residual(text, z) < 1e-6 for text in eqs):
                if unsolved:
                    raise Partial(unsolved[0], f"{key} vanishes along the motion at {ctx.scene.coords[0].name} = "
                                               f"{fmt(z)} (the oracle), where rbdsolve said it has no closed form")
                raise Mismatch(f"{key} vanishes along the motion at {ctx.scene.coords[0].name} = {fmt(z)} (the oracle), "
                               f"which no listed equation {eqs} gives")
        if len(reach) > 20 and reach[-1][0] != qs[-1]:  # the motion turns back: every zero is in the scan
            # an equation left whole, P(cos q) = 0 (degree ≥ 3), says where N may vanish, its
            # roots not given: with open parameters, which of them is reached is not claimed
            for text in (t for t in eqs if not _implicit(ctx, t)):
                if not any(residual(text, z) < 1e-6 for z in zeros):
                    raise Mismatch(f"{key}: rbdsolve says it vanishes where {text}, but the oracle's zeros along the "
                                   f"motion are {fmt(zeros)}")


def _implicit(ctx, text: str) -> bool:
    """Eq(P(cos q), 0), not cos q = c, sin q = c nor q = c."""
    e = ctx.reader.parse(text)
    return e.rhs == 0 and not e.lhs.is_Function


def _side(ctx, text: str) -> str:
    e = ctx.reader.parse(text)
    return str(e.lhs - e.rhs)


def _bisect(s, sup, name, q0, a, b):
    """The zero of the support's push between a and b along the motion from rest at q₀."""
    zero = [mpmath.mpf(0)]
    def push(q):
        w2 = rate_squared(s, (q0, zero), [q])
        forces, _ = support_forces(s, [q], [mpmath.sqrt(max(w2, 0))])
        return list(_components(s, sup, *forces[name][:2], [q]).values())[0]
    fa = push(a)
    for _ in range(40):
        c = (a + b) / 2
        fc = push(c)
        if fa * fc <= 0:
            b = c
        else:
            a, fa = c, fc
    return (a + b) / 2


def coords_fmt(z):
    return fmt(z)
