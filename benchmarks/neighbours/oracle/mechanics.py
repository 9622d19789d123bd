"""Newton–Euler for the generator's scenes, in the bodies' own terms.

Each body b has its centre r_b(q, t) and its turn R_b(q, t) (body axes to the scene's),
from the generator's placement; its mass and inertia from the quadrature of its shape
(oracle/shapes.py). Along a motion q(s) = q + s q̇ + s²/2 q̈, t(s) = t + s the path
derivatives give v = r′, a = r″, ω× = Ṙ Rᵀ and ω̇× = R̈ Rᵀ + Ṙ Ṙᵀ; the partial
velocities are ∂r/∂q_k and W_k (∂R/∂q_k Rᵀ = W_k×). The balance of each body,
m a − m g − F and J ω̇ + ω × J ω − M, projected on the motions the supports allow
(d'Alembert), gives the generalized residual

    E_k = Σ_b [m_b ∂r_b/∂q_k · (a_b − g) + W_k · (J ω̇ + ω × J ω)] + ∂V_springs/∂q_k − Q_k,

which is d/dt ∂L/∂q̇_k − ∂L/∂q_k for the same scene (so it is compared with rbdsolve's
equations term for term) but is formed without T, V or Lagrange's equations.
Derivatives are finite differences of fourth order, in 40 digits (mpmath) for the
answers and in floats for searches and simulation; in floats the points of one
derivative are evaluated together, on arrays (oracle/poses.py)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import mpmath
import numpy as np

from benchmarks.neighbours.expr import ARRAYS, FLOAT, MP, Env, Namespace, Vec, evaluate, names_in
from benchmarks.neighbours.oracle.poses import at_points, poses
from benchmarks.neighbours.oracle.shapes import Cloud, cloud
from benchmarks.neighbours.scene import Body, Scene

_AXES = {"x": (1, 0, 0), "y": (0, 1, 0), "z": (0, 0, 1), "-x": (-1, 0, 0), "-y": (0, -1, 0), "-z": (0, 0, -1)}


def _rot(axis: str, a, ns: Namespace):
    """The rotation by ``a`` about a coordinate axis (Rodrigues for ±x, ±y, ±z)."""
    c, s = ns.table["cos"](a), ns.table["sin"](a)
    dtype = ns.dtype
    if axis == "z":
        z, o = 0 * c, 0 * c + 1
        return np.array([[c, -s, z], [s, c, z], [z, z, o]], dtype=dtype)
    u = _AXES[axis]
    one = c * 0 + 1
    K = np.array([[0, -u[2], u[1]], [u[2], 0, -u[0]], [-u[1], u[0], 0]], dtype=dtype) * one
    return np.eye(3, dtype=dtype) * one + s * K + (1 - c) * K.dot(K)


@dataclass
class MassBody:
    """A body's mass, its centre in body axes (from its origin) and J_G in body axes."""

    name: str
    mass: float
    centre: np.ndarray
    inertia: np.ndarray
    spec: Body


def mass_body(body: Body, p: dict[str, float]) -> MassBody:
    """Mass properties from the quadrature of the shape or parts (or the given inertia)."""
    value = lambda text: float(evaluate(text, Env(FLOAT, p, {})))  # noqa: E731
    if body.parts:
        total = None
        given = np.zeros((3, 3))
        for part in body.parts:
            at = [value(x) for x in part.at] + [0.0] * (3 - len(part.at))
            if part.shape is None:  # a given inertia: a point mass plus its J about its centre
                c = Cloud(np.array([(-1 if part.hole else 1) * value(part.mass)]), np.array([at]))
                given[2, 2] += (-1 if part.hole else 1) * value(part.inertia)
            else:
                c = cloud(part.shape, value(part.mass), {k: value(v) for k, v in part.dims.items()},
                          part.axis, at, part.hole)
            total = c if total is None else total + c
        return MassBody(body.name, total.mass, total.centre, total.inertia() + given, body)
    m = value(body.mass)
    if body.inertia is not None:
        if isinstance(body.inertia, str):
            J = np.diag([0.0, 0.0, value(body.inertia)])
        else:
            J = np.diag([value(x) for x in body.inertia])
        return MassBody(body.name, m, np.zeros(3), J, body)
    c = cloud(body.shape, m, {k: value(v) for k, v in body.dims.items()}, body.axis)
    return MassBody(body.name, m, c.centre, c.inertia(), body)


def _axial(S) -> np.ndarray:
    """The vector w of the antisymmetric part of S (S ≈ w×)."""
    return np.array([(S[2, 1] - S[1, 2]) / 2, (S[0, 2] - S[2, 0]) / 2, (S[1, 0] - S[0, 1]) / 2], dtype=object)


def _cross(a, b):
    return np.array([a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]], dtype=object)


class System:
    """A scene at given parameter values, in one arithmetic (``MP``: 40 digits; ``FLOAT``)."""

    def __init__(self, scene: Scene, values: dict[str, float], ns: Namespace = MP):
        self.scene = scene
        self.ns = ns
        self.fp = {k: float(v) for k, v in values.items()}
        conv = (lambda x: mpmath.mpf(x)) if ns is MP else float
        self.p = {k: (v if ns is MP and isinstance(v, mpmath.mpf) else conv(v)) for k, v in values.items()}
        self.coords = [c.name for c in scene.coords]
        self.n = len(self.coords)
        self.bodies = [mass_body(b, self.fp) for b in scene.bodies]
        self.zero = conv(0)
        self.one = conv(1)
        self.centres = [np.array([conv(float(x)) for x in mb.centre], dtype=ns.dtype) for mb in self.bodies]
        self.inertias = [np.array([[conv(float(x)) for x in row] for row in mb.inertia], dtype=ns.dtype)
                         for mb in self.bodies]
        g = evaluate(scene.gravity, self.env([0] * self.n, 0)) if scene.gravity else Vec(0, 0, 0)
        self.g = np.array([self.one * x for x in g], dtype=ns.dtype)
        self.h1 = conv("1e-9") if ns is MP else 1e-4   # first derivatives (4th order)
        self.h2 = conv("1e-7") if ns is MP else 1e-3   # path: first and second derivatives
        lengths = [self.fp[q.name] for q in scene.params if q.kind == "length" and q.name in self.fp]
        self.length = max(lengths) if lengths else 1.0
        self.scale = [1.0 if c.kind == "angle" else self.length for c in scene.coords]
        self.static = not any("t" in names_in(x) for x in _texts(scene))

    # --- evaluation -------------------------------------------------------------------
    def env(self, q, t) -> Env:
        """The values at (q, t); with t an array, at many points at once (floats on arrays)."""
        values = dict(self.p)
        values.update(zip(self.coords, q))
        values["t"] = t
        return Env(ARRAYS if isinstance(t, np.ndarray) else self.ns, values, self.scene.points)

    def value(self, text: str, q, t=0):
        return evaluate(text, self.env(q, t))

    def vector(self, text: str, q, t=0) -> np.ndarray:
        v = self.value(text, q, t)
        return np.array([self.one * x for x in v], dtype=self.ns.dtype)

    def rotation(self, body: Body, env: Env):
        if body.turns:
            R = np.eye(3, dtype=self.ns.dtype) * self.one
            for axis, angle in body.turns:
                R = R.dot(_rot(axis, evaluate(angle, env), self.ns))
            return R
        angle = evaluate(body.angle, env) if body.angle else self.zero
        return _rot("z", angle, self.ns)

    def pose(self, q, t) -> np.ndarray:
        """Every body's centre and turn, flattened: [r (3), R (9)] per body (with t an
        array: one column per point)."""
        env = self.env(q, t)
        if isinstance(t, np.ndarray):
            return poses(self, env, len(t))
        out = []
        for mb, c in zip(self.bodies, self.centres):
            R = self.rotation(mb.spec, env)
            o = evaluate(mb.spec.origin, env)
            r = np.array([self.one * x for x in o], dtype=self.ns.dtype) + R.dot(c)
            out.append(r)
            out.append(R.reshape(9))
        return np.concatenate(out) if out else np.zeros(0, dtype=self.ns.dtype)

    # --- derivatives ------------------------------------------------------------------
    def at(self, f, points: list, arrays: bool) -> list:
        """f at each (q, t) of ``points``; in floats, where f takes arrays (the pose, the
        potential, the springs' energy), in one evaluation for all (``poses.at_points``)."""
        if arrays and self.ns is FLOAT:
            return at_points(f, self.n, points)
        return [f(q, t) for q, t in points]

    def stencil(self, q, t) -> list:
        """The points of the differences in every coordinate: q + s e_k, s = −2h, −h, h, 2h."""
        out = []
        for k in range(self.n):
            h = self.h1 * self.scale[k]
            for s in (-2 * h, -h, h, 2 * h):
                qq = list(q)
                qq[k] = qq[k] + s
                out.append((qq, t))
        return out

    def differences(self, values: list) -> list:
        """∂f/∂q_k = (f(−2h) − 8 f(−h) + 8 f(h) − f(2h)) / 12h, the central difference of
        fourth order, from f at the ``stencil``."""
        out = []
        for k in range(self.n):
            fm2, fm1, fp1, fp2 = values[4 * k:4 * k + 4]
            out.append((fm2 - 8 * fm1 + 8 * fp1 - fp2) / (12 * (self.h1 * self.scale[k])))
        return out

    def partials(self, f, q, t, arrays: bool = False) -> list:
        """∂f/∂q_k for every k (``arrays``: f takes arrays of points, see ``at``)."""
        return self.differences(self.at(f, self.stencil(q, t), arrays))

    def path(self, f, q, qd, qdd, t, arrays: bool = False):
        """f and its first and second derivatives along q + s q̇ + s²/2 q̈, t + s."""
        h = self.h2
        def at(s):
            return [a + s * b + s * s / 2 * c for a, b, c in zip(q, qd, qdd)], t + s
        fm2, fm1, f0, fp1, fp2 = self.at(f, [at(-2 * h), at(-h), at(0 * h), at(h), at(2 * h)], arrays)
        d1 = (fm2 - 8 * fm1 + 8 * fp1 - fp2) / (12 * h)
        d2 = (-fm2 + 16 * fm1 - 30 * f0 + 16 * fp1 - fp2) / (12 * h * h)
        return f0, d1, d2

    # --- kinematics of the bodies -------------------------------------------------------
    def motion(self, q, qd, qdd, t):
        """Per body: r, v, a, R, ω, ω̇ (scene axes)."""
        P, dP, ddP = self.path(self.pose, q, qd, qdd, t, arrays=True)
        out = []
        for i, _ in enumerate(self.bodies):
            r, v, a = P[12 * i:12 * i + 3], dP[12 * i:12 * i + 3], ddP[12 * i:12 * i + 3]
            R = P[12 * i + 3:12 * i + 12].reshape(3, 3)
            Rd = dP[12 * i + 3:12 * i + 12].reshape(3, 3)
            Rdd = ddP[12 * i + 3:12 * i + 12].reshape(3, 3)
            w = _axial(Rd.dot(R.T))
            wd = _axial(Rdd.dot(R.T) + Rd.dot(Rd.T))
            out.append((r, v, a, R, w, wd))
        return out

    def partial_velocities(self, q, t):
        """Per coordinate k, per body: (∂r/∂q_k, W_k). In floats the last state's are kept:
        the accelerations ask at one state for M and for the residual (a simulation's
        right-hand side, twice the same differences)."""
        key = (tuple(q), t)
        last = self.__dict__.get("_last_partial_velocities")
        if self.ns is FLOAT and last is not None and last[0] == key:
            return last[1]
        out = self._partial_velocities(q, t)
        if self.ns is FLOAT:
            self._last_partial_velocities = (key, out)
        return out

    def _partial_velocities(self, q, t):
        P = self.pose(q, t)
        dPs = self.partials(self.pose, q, t, arrays=True)
        out = []
        for dP in dPs:
            row = []
            for i, _ in enumerate(self.bodies):
                R = P[12 * i + 3:12 * i + 12].reshape(3, 3)
                row.append((dP[12 * i:12 * i + 3], _axial(dP[12 * i + 3:12 * i + 12].reshape(3, 3).dot(R.T))))
            out.append(row)
        return out

    def spatial_inertia(self, i, R):
        return R.dot(self.inertias[i]).dot(R.T)

    # --- energies ----------------------------------------------------------------------
    def spring_energy(self, q, t=0):
        env = self.env(q, t)
        V = self.zero
        sqrt = env.ns.table["sqrt"]  # env's: numpy's on arrays of points
        for s in self.scene.springs:
            k = evaluate(s.stiffness, env)
            if s.angle is not None:
                x = evaluate(s.angle, env) - evaluate(s.rest, env)
            else:
                a, b = evaluate(s.ends[0], env), evaluate(s.ends[1], env)
                d = a - b
                x = sqrt(sum(c * c for c in d)) - evaluate(s.natural_length, env)
            V = V + k * x * x / 2
        return V

    def spring_crossed(self, q, t=0) -> bool:
        """Has a spring that lies along one axis passed through zero length between the
        reference configuration (every coordinate 0) and q? rbdsolve writes such a
        spring's length √(u²) as u or −u by its sign there (issue 38, item 8), true on
        that side only; an exam's spring never passes through zero length, so states
        beyond are not asked about."""
        here, ref = self.env(q, t), self.env([self.zero] * self.n, t)
        for s in self.scene.springs:
            if s.angle is not None:
                continue
            d0 = [float(x) for x in evaluate(s.ends[1], ref) - evaluate(s.ends[0], ref)]
            d = [float(x) for x in evaluate(s.ends[1], here) - evaluate(s.ends[0], here)]
            size = max(abs(x) for x in d0 + d) or 1.0
            axes0 = [k for k, x in enumerate(d0) if abs(x) > 1e-12 * size]
            axes = [k for k, x in enumerate(d) if abs(x) > 1e-12 * size]
            if len(axes0) == 1 and axes == axes0 and d0[axes0[0]] * d[axes0[0]] < 0:
                return True
        return self.polar_negative(q, t)

    def polar_negative(self, q, t=0) -> bool:
        """Is a spring's polar distance (``_polar_distances``) negative at q? The same
        point as one with it positive, which an exam writes instead."""
        return any(q[i] < 0 for s in self.scene.springs if s.angle is None for i in self._polar_distances(s, t))

    def _polar_distances(self, s, t=0) -> list[int]:
        """The coordinates r with the spring's end-to-end vector r e, e a unit vector that
        another coordinate θ turns to −e at θ + π (the elastic pendulum, P = r (sin θ,
        −cos θ) on a spring from O): a distance from the anchor, which an exam takes ≥ 0
        ((−r, θ) is the point (r, θ + π)). Checked at a few states: |d| = |r|, and d
        reversed by a half turn of θ. Once per spring."""
        cache = self.__dict__.setdefault("_polar_cache", {})
        if id(s) not in cache:
            cache[id(s)] = [i for i in range(self.n) if self._is_polar(s, i, t)]
        return cache[id(s)]

    def _is_polar(self, s, i: int, t) -> bool:
        rng = np.random.default_rng(7)
        turned_by = set(range(self.n)) - {i}
        for _ in range(3):
            q = [self.zero + float(x) for x in rng.uniform(-1.5, 1.5, self.n)]
            for r in (0.7, -1.3):
                q[i] = self.zero + r
                d = self._end_to_end(s, q, t)
                if abs(math.sqrt(sum(x * x for x in d)) - abs(r)) > 1e-9 * (1 + abs(r)):
                    return False
                for j in list(turned_by):
                    half = list(q)
                    half[j] = half[j] + math.pi
                    if any(abs(a + b) > 1e-9 * (1 + abs(r)) for a, b in zip(d, self._end_to_end(s, half, t))):
                        turned_by.discard(j)
        return bool(turned_by)

    def _end_to_end(self, s, q, t) -> list[float]:
        env = self.env(q, t)
        return [float(x) for x in evaluate(s.ends[1], env) - evaluate(s.ends[0], env)]

    def potential(self, q, t=0):
        """V = −Σ m g·r_G + ½ Σ k s² (the oracle's own, for energy questions)."""
        P = self.pose(q, t)
        V = self.spring_energy(q, t)
        for i, mb in enumerate(self.bodies):
            V = V - mb.mass * self.g.dot(P[12 * i:12 * i + 3])
        return V

    def kinetic(self, q, qd, t=0):
        T = self.zero
        for i, (r, v, a, R, w, wd) in enumerate(self.motion(q, qd, [0 * x for x in qd], t)):
            J = self.spatial_inertia(i, R)
            T = T + self.bodies[i].mass * v.dot(v) / 2 + w.dot(J.dot(w)) / 2
        return T

    # --- the balance -----------------------------------------------------------------
    def applied(self, q, qd, t):
        """Generalized applied forces other than gravity and springs: Σ F·∂r_P/∂q_k + W_k·M."""
        Q = [self.zero] * self.n
        for f in self.scene.forces:
            i = [b.name for b in self.bodies].index(f.body)
            env = self.env(q, t)
            if f.force is not None:
                F = np.array([self.one * x for x in evaluate(f.force, env)], dtype=object)
                dr = self.partials(lambda qq, tt: self.vector(f.at, qq, tt), q, t)
                Q = [Q[k] + F.dot(dr[k]) for k in range(self.n)]
            if f.couple is not None:
                M = evaluate(f.couple, env)
                pv = self.partial_velocities(q, t)
                Q = [Q[k] + pv[k][i][1][2] * M for k in range(self.n)]
        return Q

    def residual(self, q, qd, qdd, t=0, sizes: bool = False):
        """E_k(q, q̇, q̈): the generalized form of every body's Newton–Euler balance; with
        ``sizes``, also Σ|term| per coordinate (the scale a difference is measured on)."""
        if self.static and not any(qd) and not any(qdd) and not self.scene.forces:
            return self._static_residual(q, t, sizes)
        mot = self.motion(q, qd, qdd, t)
        pv = self.partial_velocities(q, t)
        dV = self.partials(self.spring_energy, q, t, arrays=True) if self.scene.springs else [self.zero] * self.n
        Qa = self.applied(q, qd, t) if self.scene.forces else [self.zero] * self.n
        E, S = [], []
        for k in range(self.n):
            e = dV[k] - Qa[k]
            size = abs(dV[k]) + abs(Qa[k])
            for i, (r, v, a, R, w, wd) in enumerate(mot):
                J = self.spatial_inertia(i, R)
                dr, W = pv[k][i]
                m = self.bodies[i].mass
                rot = W.dot(J.dot(wd) + _cross(w, J.dot(w)))
                e = e + m * dr.dot(a) - m * dr.dot(self.g) + rot
                size = size + abs(m * dr.dot(a)) + abs(m * dr.dot(self.g)) + abs(rot) + _norm(dr) * _norm(a) * m
            E.append(e)
            S.append(size)
        return (E, S) if sizes else E

    def _static_residual(self, q, t, sizes):
        """At rest in a still scene E = ∂V/∂q (gravity and springs): a gradient of V."""
        E = self.partials(self.potential, q, t, arrays=True)
        if not sizes:
            return E
        S = []
        grav = self.partials(lambda qq, tt: self._gravity_terms(qq, tt), q, t)
        springs = self.partials(lambda qq, tt: self.spring_energy(qq, tt), q, t) if self.scene.springs else None
        for k in range(self.n):
            S.append(sum(abs(x) for x in grav[k]) + (abs(springs[k]) if springs is not None else 0) + abs(E[k]))
        return E, S

    def _gravity_terms(self, q, t):
        P = self.pose(q, t)
        return np.array([-mb.mass * self.g.dot(P[12 * i:12 * i + 3]) for i, mb in enumerate(self.bodies)], dtype=object)

    def mass_matrix(self, q, t=0):
        """M = Σ m (∂r/∂q)ᵀ ∂r/∂q + Wᵀ J W."""
        pv = self.partial_velocities(q, t)
        P = self.pose(q, t)
        M = [[self.zero] * self.n for _ in range(self.n)]
        for i, _ in enumerate(self.bodies):
            J = self.spatial_inertia(i, P[12 * i + 3:12 * i + 12].reshape(3, 3))
            for a in range(self.n):
                for b in range(self.n):
                    M[a][b] += self.bodies[i].mass * pv[a][i][0].dot(pv[b][i][0]) + pv[a][i][1].dot(J.dot(pv[b][i][1]))
        return M

    def accelerations(self, q, qd, t=0):
        M = self.mass_matrix(q, t)
        bias = self.residual(q, qd, [self.zero] * self.n, t)
        if self.ns is MP:
            return list(mpmath.lu_solve(mpmath.matrix(M), mpmath.matrix([-b for b in bias])))
        return list(np.linalg.solve(np.array(M, float), -np.array(bias, float)))

    def stiffness(self, q, t=0, gyroscopic: bool = True):
        """K_kj = ∂E_k/∂q_j at rest; G_kj = ∂E_k/∂q̇_j at rest (gyroscopic and damping).
        Kept per state (the callers read them): an equilibrium's Hessian and its stability
        ask at the same q, each at 16 n² potentials in 40 digits."""
        memo = self.__dict__.setdefault("_stiffness_memo", {})
        key = (tuple(q), t, gyroscopic)
        if key not in memo:
            memo[key] = self._stiffness(q, t, gyroscopic)
        return memo[key]

    def _stiffness(self, q, t, gyroscopic: bool):
        zero = [self.zero] * self.n
        cols = self.partials(lambda qq, tt: np.array(self.residual(qq, zero, zero, tt), dtype=object), q, t)
        K = [[cols[j][k] for j in range(self.n)] for k in range(self.n)]
        G = [[self.zero] * self.n for _ in range(self.n)]
        if not gyroscopic:
            return K, G
        h = self.one / 1000
        for j in range(self.n):
            e = list(zero)
            e[j] = h
            plus = self.residual(q, e, zero, t)
            e[j] = -h
            minus = self.residual(q, e, zero, t)
            for k in range(self.n):
                G[k][j] = (plus[k] - minus[k]) / (2 * h)
        return K, G

    def force_scale(self):
        """A size of the generalized forces of the scene: the largest Σ|term| over a few
        configurations (an absolute floor where every term vanishes, as at θ = 0)."""
        if getattr(self, "_force_scale", None) is None:
            rng = np.random.default_rng(12345)
            zero = [self.zero] * self.n
            best = self.zero
            for _ in range(3):
                q = [self.one * float(x) * s for x, s in zip(rng.uniform(-1, 1, self.n), self.scale)]
                _, S = self.residual(q, zero, zero, sizes=True)
                best = max([best] + list(S))
            weight = sum(mb.mass for mb in self.bodies) * mpmath.sqrt(sum(x * x for x in self.g)) * self.length
            springs = sum(abs(evaluate(sp.stiffness, self.env(zero, 0))) * (self.length ** 2 if sp.angle is None else 1)
                          for sp in self.scene.springs)
            self._force_scale = best + self.one * (weight + springs) + self.one * 1e-300
        return self._force_scale

    def generalized_force(self, q, t=0):
        """Q(q) = −E(q, 0, 0): zero at an equilibrium (relative, in a frame where still)."""
        zero = [self.zero] * self.n
        return [-e for e in self.residual(q, zero, zero, t)]


def _norm(v):
    return sum(abs(x) for x in v)


def _texts(scene: Scene) -> list[str]:
    """Every placement expression: the scene is still when none holds t."""
    out = list(scene.points.values())
    for body in scene.bodies:
        out += [body.origin, body.angle or "0"] + [a for _, a in (body.turns or ())]
    return out


def sample_values(scene: Scene, rng: np.random.Generator, tries: int = 200) -> dict[str, mpmath.mpf]:
    """Every parameter's value: the file's (exact, in SI) or, for a symbolic one, a draw
    in its range that keeps the scene's assumptions."""
    from benchmarks.neighbours.expr import constant
    fixed = {p.name: constant(p.si) for p in scene.params if p.si is not None}
    for _ in range(tries):
        values = dict(fixed)
        for p in scene.params:
            if p.si is None:
                x = rng.uniform(p.low, p.high)
                values[p.name] = mpmath.mpf(float(f"{x:.6g}"))
        if all(_holds(a, values) for a in scene.assumptions):
            return values
    raise ValueError(f"{scene.name}: no sample keeps the assumptions {scene.assumptions}")


def _holds(text: str, values) -> bool:
    import ast
    tree = ast.parse(text, mode="eval").body
    if not isinstance(tree, ast.Compare) or len(tree.ops) != 1:
        raise ValueError(f"an assumption is one comparison: {text!r}")
    left = float(constant_expr(ast.unparse(tree.left), values))
    right = float(constant_expr(ast.unparse(tree.comparators[0]), values))
    op = tree.ops[0]
    return {ast.Lt: left < right, ast.LtE: left <= right, ast.Gt: left > right, ast.GtE: left >= right}[type(op)]


def constant_expr(text: str, values):
    return evaluate(text, Env(MP, dict(values), {}))
