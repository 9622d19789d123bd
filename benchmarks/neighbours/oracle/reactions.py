"""The forces the supports exert, from each body's Newton–Euler balance at a state:
with the accelerations known, every body's m (a − g) − F_applied and J ω̇ + ω × J ω −
M_applied (about its centre) must be made up by its supports, each a force along the
directions it can push (a pivot: any in the plane; a guide: its normal; rolling: the
normal and e_z × normal; a string: along itself) at its point, and a moment where the
body cannot turn on its holder. The components are the least-squares solution of
those balances; the balances' residual says whether the supports listed can hold the
motion at all (they must, for the scene the generator describes)."""

from __future__ import annotations

import mpmath
import numpy as np

from benchmarks.neighbours.expr import evaluate
from benchmarks.neighbours.oracle.mechanics import System, _cross


def _vec(s: System, text: str, q, t=0):
    v = evaluate(text, s.env(q, t))
    return np.array([s.one * x for x in v], dtype=object)


def directions(s: System, support, q, t=0) -> list:
    """The unit directions a support pushes along (scene axes)."""
    if support.kind == "pivot":
        if s.scene.planar:
            return [np.array([s.one, s.zero, s.zero], dtype=object), np.array([s.zero, s.one, s.zero], dtype=object)]
        return [np.array(row, dtype=object) * s.one for row in np.eye(3)]
    n = _vec(s, support.normal, q, t)
    n = n / mpmath.sqrt(n.dot(n))
    if support.kind == "rolling":
        return [n, np.array([-n[1], n[0], s.zero], dtype=object)]  # t = e_z × n
    return [n]


def applied_on_bodies(s: System, q, t=0):
    """Per body: the force and the moment about its centre of its springs and applied forces."""
    names = [b.name for b in s.bodies]
    F = [np.zeros(3, dtype=object) * s.one for _ in names]
    M = [np.zeros(3, dtype=object) * s.one for _ in names]
    P = s.pose(q, t)
    centre = [P[12 * i:12 * i + 3] for i in range(len(names))]
    env = s.env(q, t)
    for sp in s.scene.springs:
        k = evaluate(sp.stiffness, env)
        if sp.angle is not None:
            x = evaluate(sp.angle, env) - evaluate(sp.rest, env)
            for body, c in sp.turns.items():
                M[names.index(body)][2] += -k * x * c
            continue
        a, b = _vec(s, sp.ends[0], q, t), _vec(s, sp.ends[1], q, t)
        d = a - b
        length = s.ns.table["sqrt"](d.dot(d))
        e = d / length
        f = -k * (length - evaluate(sp.natural_length, env)) * e  # on the first end
        for body, point, force in ((sp.on[0], a, f), (sp.on[1], b, -f)):
            if body is not None:
                i = names.index(body)
                F[i] = F[i] + force
                M[i] = M[i] + _cross(point - centre[i], force)
    for fo in s.scene.forces:
        i = names.index(fo.body)
        if fo.force is not None:
            f = _vec(s, fo.force, q, t)
            F[i] = F[i] + f
            M[i] = M[i] + _cross(_vec(s, fo.at, q, t) - centre[i], f)
        if fo.couple is not None:
            M[i][2] += evaluate(fo.couple, env)
    return F, M


def support_forces(s: System, q, qd, qdd=None, t=0):
    """Per support (by name): (force on its body, moment about z or None, the components
    along its directions); and the balances' largest relative residual."""
    if qdd is None:
        qdd = s.accelerations(q, qd, t)
    names = [b.name for b in s.bodies]
    mot = s.motion(q, qd, qdd, t)
    Fa, Ma = applied_on_bodies(s, q, t)
    rows = 3 if s.scene.planar else 6
    need = []
    for i, (r, v, a, R, w, wd) in enumerate(mot):
        J = s.spatial_inertia(i, R)
        lin = s.bodies[i].mass * (a - s.g) - Fa[i]
        ang = J.dot(wd) + _cross(w, J.dot(w)) - Ma[i]
        need += [lin[0], lin[1], ang[2]] if s.scene.planar else list(lin) + list(ang)
    columns, labels = [], []
    for sup in s.scene.supports:
        point = _vec(s, sup.at, q, t)
        for j, d in enumerate(directions(s, sup, q, t)):
            col = [s.zero] * (rows * len(names))
            for body, sign in ((sup.body, 1), (sup.by, -1)):
                if body is None:
                    continue
                i = names.index(body)
                m = _cross(point - mot[i][0], d) * sign
                f = d * sign
                vals = [f[0], f[1], m[2]] if s.scene.planar else list(f) + list(m)
                for k, x in enumerate(vals):
                    col[rows * i + k] += x
            columns.append(col)
            labels.append((sup.name, "force", d))
        if sup.moment:
            col = [s.zero] * (rows * len(names))
            for body, sign in ((sup.body, 1), (sup.by, -1)):
                if body is not None:
                    col[rows * names.index(body) + (2 if s.scene.planar else 5)] += sign
            columns.append(col)
            labels.append((sup.name, "moment", None))
    A = mpmath.matrix([[columns[c][r] for c in range(len(columns))] for r in range(len(need))])
    b = mpmath.matrix(need)
    x = mpmath.lu_solve(A.T * A, A.T * b) if columns else mpmath.matrix(0, 1)  # least squares (normal equations)
    res = A * x - b if columns else b
    size = max([abs(v) for v in need] + [s.force_scale() / s.length])
    worst = max([abs(v) for v in res] + [0]) / size
    out = {}
    for (name, what, d), value in zip(labels, x):
        force, moment, comps = out.get(name, (np.zeros(3, dtype=object) * s.one, None, []))
        if what == "force":
            force = force + d * value
            comps = comps + [value]
        else:
            moment = value
        out[name] = (force, moment, comps)
    return out, worst
