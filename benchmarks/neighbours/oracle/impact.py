"""An impact by impulse and momentum on the bodies, in the plane.

Each body's velocity V_b = (v_x, v_y, ω) jumps by the impulses on it:
m Δv = Σ P and J_G Δω = Σ (r_P − r_G) × P. The unknowns are every body's V after, the
supports' impulses (along each direction a support pushes) and the collisions'
impulses; the equations are the jumps, each support's velocity condition after (its
point at rest along its directions, relative to its holder), and each collision's law:
n·(v_P − u) after = −e n·(v_P − u) before for a particle or a surface (the particle's
own jump m Δu = −λ n), or u after = v_P after for a particle that sticks. The
generalized velocities after are then read off by least squares from V = J q̇, J the
bodies' partial velocities (its residual says the supports hold every constraint)."""

from __future__ import annotations

from dataclasses import dataclass

import mpmath
import numpy as np

from benchmarks.neighbours.oracle.mechanics import System
from benchmarks.neighbours.oracle.reactions import directions


@dataclass
class Collision:
    point: str
    normal: list | None          # unit normal (towards the body), or None for a sticking particle
    restitution: object | None
    mass: object | None          # a particle's mass, or None (a surface)
    velocity: list | None        # the particle's velocity before
    after: list | None = None    # a particle's given velocity after
    sticks: bool = False


def _point_jacobian(s: System, i: int, point, q):
    """v_P = v_G + ω × (P − G) as a 2×3 map of (v_x, v_y, ω) of body i."""
    P = s.pose(q, 0)
    G = P[12 * i:12 * i + 3]
    d = [point[0] - G[0], point[1] - G[1]]
    return [[s.one, s.zero, -d[1]], [s.zero, s.one, d[0]]]


def body_of_point(s: System, text: str, q):
    """The body a point belongs to: the one whose material point it is (the point moves
    with the body as the coordinates change), by comparing ∂r_P/∂q with each body's
    ∂v/∂q̇ at that point."""
    f = lambda qq, tt: np.array([s.one * x for x in s.value(text, qq, tt)], dtype=object)  # noqa: E731
    dP = s.partials(f, q, 0)
    pv = s.partial_velocities(q, 0)
    point = f(q, 0)
    best, err = None, None
    for i, _ in enumerate(s.bodies):
        Jp = _point_jacobian(s, i, point, q)
        e = 0
        for k in range(s.n):
            v = pv[k][i][0]
            w = pv[k][i][1][2]
            vx = Jp[0][0] * v[0] + Jp[0][2] * w
            vy = Jp[1][1] * v[1] + Jp[1][2] * w
            e += abs(vx - dP[k][0]) + abs(vy - dP[k][1])
        if err is None or e < err:
            best, err = i, e
    return best, err


def solve(s: System, q, qd_before, collisions: list[Collision], impulses: dict[str, list]):
    names = [b.name for b in s.bodies]
    nb = len(names)
    pv = s.partial_velocities(q, 0)
    V0 = []
    for i in range(nb):
        v = sum((pv[k][i][0] * qd_before[k] for k in range(s.n)), np.zeros(3, dtype=object) * s.one)
        w = sum((pv[k][i][1][2] * qd_before[k] for k in range(s.n)), s.zero)
        V0 += [v[0], v[1], w]
    unknowns = 3 * nb
    cols: list[tuple] = []
    for sup in s.scene.supports:
        for d in directions(s, sup, q):
            cols.append(("support", sup, d))
    for c in collisions:
        if c.sticks:
            cols += [("stick", c, 0), ("stick", c, 1)]
        elif c.after is None:
            cols.append(("collision", c, None))
    N = unknowns + len(cols)
    rows, rhs = [], []
    mass = []
    for i, mb in enumerate(s.bodies):
        mass += [mb.mass, mb.mass, mb.inertia[2][2]]

    def wrench(point: str, force):
        """Per body coordinate, the jump an impulse ``force`` at the named point gives."""
        i, _ = body_of_point(s, point, q)
        out = [s.zero] * unknowns
        Jp = _point_jacobian(s, i, s.vector(point, q), q)
        for a in range(3):
            out[3 * i + a] = Jp[0][a] * force[0] + Jp[1][a] * force[1]
        return out

    known = [s.zero] * unknowns
    for point, P in impulses.items():
        w = wrench(point, P)
        known = [a + b for a, b in zip(known, w)]
    for c in collisions:
        if c.after is not None:
            P = [c.mass * (c.velocity[k] - c.after[k]) for k in range(2)]
            w = wrench(c.point, P)
            known = [a + b for a, b in zip(known, w)]
    # momentum: M (V⁺ − V⁻) − Σ columns = known; a support's column is the jump its unit
    # impulse along d gives, which is also the map of its velocity condition (J_Pᵀ d)
    colw = []
    for kind, obj, d in cols:
        if kind == "support":
            point = s.vector(obj.at, q)
            w = [s.zero] * unknowns
            for body, sign in ((obj.body, 1), (obj.by, -1)):
                if body is None:
                    continue
                i = names.index(body)
                Jp = _point_jacobian(s, i, point, q)
                for a in range(3):
                    w[3 * i + a] += sign * (Jp[0][a] * d[0] + Jp[1][a] * d[1])
            colw.append(w)
        elif kind == "collision":
            colw.append(wrench(obj.point, obj.normal))
        else:
            e = [s.one if k == d else s.zero for k in range(2)]
            colw.append(wrench(obj.point, e))
    for r in range(unknowns):
        row = [s.zero] * N
        row[r] = mass[r]
        for j, w in enumerate(colw):
            row[unknowns + j] = -w[r]
        rows.append(row)
        rhs.append(mass[r] * V0[r] + known[r])
    # velocity conditions after
    for j, (kind, obj, d) in enumerate(cols):
        row = [s.zero] * N
        if kind == "support":  # d·(v_P − v_P of its holder) = 0: the same map as its impulse's
            row[:unknowns] = colw[j]
            rows.append(row)
            rhs.append(s.zero)
        elif kind == "collision":
            i, _ = body_of_point(s, obj.point, q)
            Jp = _point_jacobian(s, i, s.vector(obj.point, q), q)
            n = obj.normal
            vbefore = sum(n[k] * sum(Jp[k][a] * V0[3 * i + a] for a in range(3)) for k in range(2))
            for a in range(3):
                row[3 * i + a] += n[0] * Jp[0][a] + n[1] * Jp[1][a]
            ub = s.zero
            if obj.mass is not None:
                # u⁺ = u⁻ − λ n / m_p
                ub = n[0] * obj.velocity[0] + n[1] * obj.velocity[1]
                row[unknowns + j] += (n[0] * n[0] + n[1] * n[1]) / obj.mass
            rows.append(row)
            rhs.append(-obj.restitution * (vbefore - ub) + ub)
        else:
            # u⁺ = u⁻ − P/m_p equals v_P⁺: component d
            i, _ = body_of_point(s, obj.point, q)
            Jp = _point_jacobian(s, i, s.vector(obj.point, q), q)
            for a in range(3):
                row[3 * i + a] += Jp[d][a]
            if obj.mass is not None:
                row[unknowns + j] += 1 / obj.mass
                rhs.append(obj.velocity[d])
            else:  # a body's point that sticks to a fixed point: at rest after
                rhs.append(s.zero)
            rows.append(row)
    x = mpmath.lu_solve(mpmath.matrix(rows), mpmath.matrix(rhs))
    V1 = [x[r] for r in range(unknowns)]
    lam = [x[unknowns + j] for j in range(len(cols))]
    # q̇ after, by least squares on V = J q̇
    J = mpmath.matrix(unknowns, s.n)
    for i in range(nb):
        for k in range(s.n):
            J[3 * i, k], J[3 * i + 1, k], J[3 * i + 2, k] = pv[k][i][0][0], pv[k][i][0][1], pv[k][i][1][2]
    qd = mpmath.lu_solve(J.T * J, J.T * mpmath.matrix(V1))
    res = J * qd - mpmath.matrix(V1)
    worst = max([abs(v) for v in res] + [0]) / max([abs(v) for v in V1] + [mpmath.mpf(1)])
    return {"V0": V0, "V1": V1, "qd": [qd[k] for k in range(s.n)], "columns": cols, "impulses": lam,
            "residual": worst, "mass": mass}

