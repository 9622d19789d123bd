"""modes: at each parameter point, the equilibrium rbdsolve linearizes about must be
one for the oracle; its M and K against the oracle's (M = Σ m JᵀJ + WᵀJW, K = ∂E/∂q at
rest); its eigenvalues against the oracle's generalized eigenvalues of (K, M) as a
multiset; each shape a must satisfy K a = λ M a with the oracle's K and M; each motion
(and each case of one that depends) the sign of λ; ω = √λ and γ = √−λ."""

from __future__ import annotations

import mpmath
import numpy as np
from scipy.linalg import eigh

from benchmarks.neighbours.check.context import Context, Mismatch, boundary_points, close, fmt, points_for, rtol
from benchmarks.neighbours.check.equilibria import _params


def check(ctx: Context, question, result: dict) -> list[str]:
    answers = result["answers"]
    entries = answers["modes"] if "modes" in answers and isinstance(answers["modes"], list) else [answers]
    notes: list[str] = []
    ctx._modes_about = question.options.get("about") if isinstance(question.options.get("about"), dict) else None
    for i in points_for(ctx, result) + boundary_points(ctx, result):
        for entry in entries:
            _one(ctx, entry, result, i, notes)
    return notes


def _value(ctx, x, i):
    return ctx.reader.value(x, ctx.points[i])


def _one(ctx: Context, entry: dict, result: dict, i: int, notes: list[str]) -> None:
    coords = [c.name for c in ctx.scene.coords]
    tol = rtol(result)
    about = entry.get("about") or _about(ctx, question_about(ctx, entry), i)
    if about is None:
        return
    entry = {**entry, "about": about}
    if ctx.reader.truth(entry.get("exists_when", "True"), ctx.points[i]) is False:
        return  # rbdsolve says this equilibrium does not exist at these values (checked by the equilibria)
    q0 = [_value(ctx, about[c], i) for c in coords]
    if any(isinstance(x, mpmath.mpc) for x in q0):
        return  # this equilibrium does not exist at these values
    s = ctx.system(i)
    zero = [s.zero] * s.n
    Q, S = s.residual(q0, zero, zero, sizes=True)
    floor = s.force_scale()
    if any(abs(x) > 1e-7 * (sz + floor) for x, sz in zip(Q, S)):
        raise Mismatch(f"modes about {entry['about']} = {fmt(q0)}: not an equilibrium for the oracle, Q = {fmt(Q)} "
                       f"at {_params(ctx, i)}")
    K, G = s.stiffness(q0)
    M = s.mass_matrix(q0)
    Kf = np.array(K, float)
    Mf = np.array(M, float)
    Kf = (Kf + Kf.T) / 2
    kn, mn = np.abs(Kf).max() + 1e-300, np.abs(Mf).max()
    for name, mine, theirs, norm in (("M", M, entry.get("M"), mn), ("K", K, entry.get("K"), kn)):
        if theirs is None:
            continue
        for a in range(s.n):
            for b in range(s.n):
                got = _value(ctx, theirs[a][b], i)
                if not close(got, mine[a][b], norm, tol):
                    raise Mismatch(f"modes about {entry['about']}: {name}[{a + 1}][{b + 1}] rbdsolve {fmt(got)}, "
                                   f"oracle {fmt(mine[a][b])} at {_params(ctx, i)}")
    lam = np.sort(eigh(Kf, (Mf + Mf.T) / 2, eigvals_only=True))
    top = np.abs(lam).max() + 1e-300
    got = [_value(ctx, x, i) for x in entry.get("eigenvalues", [])]
    if any(isinstance(x, mpmath.mpc) for x in got):
        raise Mismatch(f"modes about {entry['about']}: an eigenvalue is not real: {fmt(got)} at {_params(ctx, i)}")
    if len(got) != len(lam) or any(abs(float(a) - b) > max(tol, 1e-9) * top for a, b in zip(sorted(got), lam)):
        raise Mismatch(f"modes about {entry['about']}: eigenvalues rbdsolve {fmt(sorted(got))}, oracle {fmt(list(lam))} "
                       f"at {_params(ctx, i)}")
    _kinds(ctx, entry, got, top, i)
    _simulated(ctx, q0, lam, entry, i)
    for j, shape in enumerate(entry.get("shapes") or []):
        if shape is None or j >= len(got):
            continue
        a = np.array([float(_value(ctx, x, i)) for x in shape])
        res = Kf @ a - float(got[j]) * Mf @ a
        if np.linalg.norm(res) > 1e-7 * (kn + abs(float(got[j])) * mn) * np.linalg.norm(a):
            raise Mismatch(f"modes about {entry['about']}: shape {j + 1} = {fmt(list(a))} is not a mode of λ = "
                           f"{fmt(got[j])} (residual {np.linalg.norm(res):.3g}) at {_params(ctx, i)}")


def _simulated(ctx, q0, lam, entry, i):
    """One scene in ten (by its index) with one coordinate: the oracle's nonlinear motion at a
    small amplitude oscillates at √λ (a check of the linearization by simulation)."""
    if ctx.scene.index % 10 or len(q0) != 1 or lam[0] <= 0 or i:
        return
    from benchmarks.neighbours.expr import FLOAT
    from benchmarks.neighbours.oracle.search import simulated_frequency
    w = simulated_frequency(ctx.system(i, FLOAT), [float(x) for x in q0], [1.0], omega_guess=float(np.sqrt(lam[0])))
    if w is None or abs(w / np.sqrt(lam[0]) - 1) > 1e-4:
        raise AssertionError(f"the oracle's simulation oscillates at {w}, its linearization at {np.sqrt(lam[0])}")


def question_about(ctx, entry):
    return getattr(ctx, "_modes_about", None)


def _about(ctx, given, i):
    """The equilibrium the question names, or (none named, or named by its number in the
    equilibria's list: ``{equilibrium: 1}``) the only stable one the oracle finds."""
    if isinstance(given, dict) and "equilibrium" not in given:
        return {c: str(v) for c, v in given.items()}
    from benchmarks.neighbours.expr import FLOAT
    from benchmarks.neighbours.oracle.search import equilibria, stability
    ms = ctx.system(i)
    stable = [r for r in equilibria(ms, ctx.system(i, FLOAT)) if stability(ms, r)[0] == "stable"]
    if len(stable) != 1:
        return None
    return {c.name: mpmath.nstr(x, 35) for c, x in zip(ctx.scene.coords, stable[0])}


def _kinds(ctx: Context, entry: dict, lam: list, top: float, i: int) -> None:
    """Each motion word (or its case at these values) against the sign of λ, and the
    frequencies and growth rates against √±λ."""
    p = ctx.points[i]
    for j, word in enumerate(entry.get("motions") or []):
        x = float(lam[j])
        if word == "depends":
            word = None
            for case in (entry.get("cases") or [[]] * (j + 1))[j]:
                if ctx.reader.truth(case["when"], p):
                    word = case["kind"]
        if word is None or abs(x) < 1e-9 * top:
            continue
        want = "oscillation" if x > 0 else "growth"
        if word != want:
            raise Mismatch(f"modes about {entry['about']}: mode {j + 1} with λ = {x:.6g} is {want}, rbdsolve says "
                           f"{word} at {_params(ctx, i)}")
        freq = (entry.get("frequencies") or [None] * (j + 1))[j]
        growth = (entry.get("growth_rates") or [None] * (j + 1))[j]
        if want == "oscillation" and freq is not None:
            f = _value(ctx, freq, i)
            if not close(f, mpmath.sqrt(lam[j]), 0, 1e-7):
                raise Mismatch(f"frequency {j + 1}: rbdsolve {fmt(f)}, √λ = {fmt(mpmath.sqrt(lam[j]))}")
        if want == "growth" and growth is not None:
            gr = _value(ctx, growth, i)
            if not close(gr, mpmath.sqrt(-lam[j]), 0, 1e-7):
                raise Mismatch(f"growth rate {j + 1}: rbdsolve {fmt(gr)}, √−λ = {fmt(mpmath.sqrt(-lam[j]))}")
