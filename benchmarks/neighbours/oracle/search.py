"""Every equilibrium of a scene in a box, found by the oracle itself: with one
coordinate, a scan of the generalized force Q(q) for sign changes and near-zero
minima; with more, Newton from a grid of starts; every root then polished in 40
digits by Newton's method on Q with the oracle's K = −∂Q/∂q, kept when |Q| is at
rounding level of its terms and the mass matrix is regular there (a singular point of
the coordinates is not an equilibrium of the bodies)."""

from __future__ import annotations

import itertools
import math

import mpmath
import numpy as np
from scipy import optimize

from benchmarks.neighbours.expr import FLOAT, MP, constant
from benchmarks.neighbours.oracle.mechanics import System
from benchmarks.neighbours.oracle.newton import newton_runs


def box(system: System) -> list[tuple[float, float, bool]]:
    """Per coordinate (low, high, periodic) at the system's parameter values."""
    out = []
    for c in system.scene.coords:
        if c.periodic:
            out.append((-math.pi, math.pi, True))
        else:
            lo = float(constant(c.low, MP, system.fp)) if c.low else -10 * system.length
            hi = float(constant(c.high, MP, system.fp)) if c.high else 10 * system.length
            out.append((lo, hi, False))
    return out


def _force(fs: System, q) -> np.ndarray:
    return np.array([float(x) for x in fs.generalized_force(list(map(float, q)))])


def _forces(fs: System, qs: list) -> list[np.ndarray]:
    """_force at each of ``qs``. In a still scene Q = −∂V/∂q (System._static_residual): V
    at the stencils of all of them in one evaluation on arrays, the same differences."""
    if not fs.static or fs.scene.forces:
        return [_force(fs, q) for q in qs]
    points = [p for q in qs for p in fs.stencil(list(map(float, q)), 0)]
    V = fs.at(fs.potential, points, arrays=True)
    m = 4 * fs.n
    return [np.array([float(-e) for e in fs.differences(V[m * j:m * j + m])]) for j in range(len(qs))]


def equilibria(ms: System, fs: System, starts: int | None = None) -> list[list]:
    """The roots of Q in the box, each polished in 40 digits (a list of mpf)."""
    b = box(ms)
    n = ms.n
    cands: list[np.ndarray] = []
    if n == 1:
        lo, hi, per = b[0]
        xs = np.linspace(lo, hi, 721)
        fv = np.array([Q[0] for Q in _forces(fs, [[x] for x in xs])])
        scale = np.max(np.abs(fv)) + 1e-300
        for i in range(len(xs) - 1):
            if fv[i] == 0:
                cands.append(np.array([xs[i]]))
            elif fv[i] * fv[i + 1] < 0:
                cands.append(np.array([optimize.brentq(lambda x: _force(fs, [x])[0], xs[i], xs[i + 1], xtol=1e-14)]))
        for i in range(1, len(xs) - 1):  # a double root touches 0 without a sign change
            if abs(fv[i]) <= abs(fv[i - 1]) and abs(fv[i]) <= abs(fv[i + 1]) and abs(fv[i]) < 1e-4 * scale:
                cands.append(np.array([xs[i]]))
        cands.append(np.array([hi])) if per else None
    else:
        per_axis = starts or {2: 10, 3: 5}.get(n, 3)
        grids = [np.linspace(lo, hi, per_axis + (0 if per else 1), endpoint=not per) for lo, hi, per in b]
        starts = [np.array(start) for start in itertools.product(*grids)]
        for sol in newton_runs(lambda q: _force(fs, q), lambda qs: _forces(fs, qs), starts):
            if sol.success:
                cands.append(sol.x)
    unique: list[np.ndarray] = []
    for c in cands:  # one polish per root: starts that converged alike are one candidate
        w = wrap([mpmath.mpf(float(x)) for x in c], b)
        if w is not None and not any(same(w, u, b, 1e-5) for u in unique):
            unique.append(w)
    roots: list[list] = []
    for c in unique:
        r = polish(ms, [mpmath.mpf(x) for x in c])
        if r is None:
            continue
        r = wrap(r, b)
        if r is None:
            continue
        if not any(same(r, s, b) for s in roots):
            roots.append(r)
    return roots


def polish(ms: System, q: list, steps: int = 30):
    """Newton on Q in 40 digits; the root, or None where it does not converge to one."""
    floor = ms.force_scale()
    for _ in range(steps):
        Q, S = ms.residual(q, [ms.zero] * ms.n, [ms.zero] * ms.n, sizes=True)
        if all(abs(x) <= mpmath.mpf("1e-28") * (s + floor) for x, s in zip(Q, S)):
            return q if regular(ms, q) else None
        if any(abs(x) > mpmath.mpf("1e-3") * (s + floor) for x, s in zip(Q, S)) and _ > 8:
            return None
        K, _k = ms.stiffness(q, gyroscopic=False)
        try:
            dq = mpmath.lu_solve(mpmath.matrix(K), mpmath.matrix(Q))
        except ZeroDivisionError:
            break
        q = [a - b for a, b in zip(q, dq)]
        if any(abs(x) > 1e6 for x in q):
            return None
    Q, S = ms.residual(q, [ms.zero] * ms.n, [ms.zero] * ms.n, sizes=True)
    if all(abs(x) <= mpmath.mpf("1e-14") * (s + floor) for x, s in zip(Q, S)):
        return q if regular(ms, q) else None  # a double root: Newton converges slowly
    return None


def regular(ms: System, q) -> bool:
    """The mass matrix is regular at q (the coordinates are not singular there)."""
    M = np.array(ms.mass_matrix(q), float)
    ev = np.linalg.eigvalsh((M + M.T) / 2)
    return ev[0] > 1e-10 * max(ev[-1], 1e-300)


def wrap(q: list, b) -> list | None:
    """A periodic angle into (−π, π]; None where another coordinate left its box."""
    out = []
    for x, (lo, hi, per) in zip(q, b):
        if per:
            x = x - 2 * mpmath.pi * mpmath.floor((x + mpmath.pi) / (2 * mpmath.pi))
            if x <= -mpmath.pi + mpmath.mpf("1e-20"):
                x += 2 * mpmath.pi
        elif not (lo - 1e-9 * max(1, abs(lo)) <= x <= hi + 1e-9 * max(1, abs(hi))):
            return None
        out.append(x)
    return out


def same(a, b, bx, tol: float = 1e-7) -> bool:
    """Two configurations alike (periodic angles modulo 2π)."""
    for x, y, (lo, hi, per) in zip(a, b, bx):
        d = abs(float(x - y))
        if per:
            d = min(d, abs(2 * math.pi - d))
        if d > tol * max(1.0, abs(float(x)), abs(float(y))):
            return False
    return True


def _zero_stiffness(ms: System, K: np.ndarray) -> bool:
    """K has an eigenvalue that is zero within the rounding of its 40-digit differences:
    with each coordinate at its scale (K_ij s_i s_j, an energy), one below 10⁻¹⁸ of the
    scene's energy scale. The λ themselves have no scale of their own: a bead on a hoop
    at the critical rate has the one λ = −3.8e-25, all rounding, which their relative
    test called negative."""
    scaled = K * np.outer([float(s) for s in ms.scale], [float(s) for s in ms.scale])
    return bool(np.abs(np.linalg.eigvalsh(scaled)).min() <= 1e-18 * float(ms.force_scale()))


def stability(ms: System, q) -> tuple[str, list[float]]:
    """stable (K positive definite on M), unstable (a negative eigenvalue) or singular,
    with the eigenvalues λ of K a = λ M a (K symmetrized: conservative at rest)."""
    from scipy.linalg import eigh
    K, _ = ms.stiffness(q, gyroscopic=False)
    M = np.array(ms.mass_matrix(q), float)
    K = np.array(K, float)
    K = (K + K.T) / 2
    lam = eigh(K, (M + M.T) / 2, eigvals_only=True)
    top = max(abs(lam).max(), 1e-300)
    if _zero_stiffness(ms, K):
        return "singular", list(lam)
    if lam.min() > 1e-9 * top:
        return "stable", list(lam)
    if lam.min() < -1e-9 * top:
        return "unstable", list(lam)
    return "singular", list(lam)


def simulated_frequency(fs: System, q0: list[float], shape: list[float], periods: float = 3.0,
                        omega_guess: float = 1.0) -> float | None:
    """ω of the motion released at rest from q₀ + A a (A a thousandth of the coordinates'
    scale, at most of π; a the mode's shape), from the zero crossings of the modal coordinate of the
    oracle's own nonlinear equations (floats, RK45 at rtol 1e-8); None where it does not
    oscillate about q₀. A tighter tolerance only chases the rounding noise of the oracle's
    finite-difference accelerations: on the half ring with a particle, rtol 1e-9 took 25,000
    evaluations and 1e-8 took 2,000, for the same ω to 5e-9, far inside the checks' 1e-4."""
    from scipy.integrate import solve_ivp
    n = fs.n
    a = np.array(shape, float)
    a = a / np.abs(a).max()
    # (a scale past π, an angle's range of ±24 rad, would make it a swing whose frequency
    # is already off √λ by 2e-4: small means small against a turn too)
    amp = 1e-3 * np.minimum(np.array(fs.scale, float), np.pi)
    y0 = np.concatenate([np.array(q0, float) + amp * a, np.zeros(n)])

    def rhs(_, y):
        qdd = fs.accelerations(list(y[:n]), list(y[n:]))
        return np.concatenate([y[n:], np.array(qdd, float)])

    T = 2 * np.pi / omega_guess
    sol = solve_ivp(rhs, (0, periods * T), y0, rtol=1e-8, atol=1e-14 * max(amp), dense_output=True)
    if not sol.success:
        return None
    t = np.linspace(0, periods * T, int(200 * periods))
    u = (sol.sol(t)[:n].T - np.array(q0, float)) @ (a * amp) / (amp @ amp)
    crossings = [t[k] - u[k] * (t[k + 1] - t[k]) / (u[k + 1] - u[k]) for k in range(len(t) - 1) if u[k] * u[k + 1] < 0]
    if len(crossings) < 3:
        return None
    half = np.diff(crossings).mean()
    return float(np.pi / half)
