"""equilibria: at each parameter point, every equilibrium rbdsolve lists that exists
there (its ``exists_when``, and each of its ``conditions`` ≥ 0) must zero the oracle's
generalized force and have the oracle's stability (K = −∂Q/∂q on M); every equilibrium
the oracle finds in its box must be listed (or be one of the listed ones' ``equivalent``
forms)."""

from __future__ import annotations

import mpmath

from benchmarks.neighbours.check.context import Context, Mismatch, Partial, boundary_points, fmt, points_for
from benchmarks.neighbours.expr import FLOAT
from benchmarks.neighbours.oracle.search import box, equilibria, regular, same, stability, wrap
from benchmarks.neighbours.read import NotANumber


def listed(ctx: Context, answers: dict, i: int):
    """rbdsolve's equilibria at point i: (q, stability there or None, its equivalents, entry)."""
    coords = [c.name for c in ctx.scene.coords]
    p = ctx.points[i]
    out = []
    for e in answers.get("equilibria") or []:
        exists = ctx.reader.truth(e.get("exists_when", "True"), p)
        if exists is not False and not _conditions_hold(ctx, e, p):
            exists = False
        if exists is False:
            continue
        q = [ctx.reader.value(e["at"][c], p) for c in coords]
        if any(isinstance(x, mpmath.mpc) for x in q):
            if exists:
                raise Mismatch(f"equilibrium {e['at']} exists (exists_when {e.get('exists_when')}) but is not real "
                               f"at {_params(ctx, i)}")
            continue
        stab = e.get("stability")
        if stab == "depends":
            stab = None
            for case in e.get("stability_cases", []):
                if ctx.reader.truth(case["when"], p):
                    stab = case["stability"]
        equivalents = [[ctx.reader.value(alt[c], p) for c in coords] for alt in e.get("equivalent", [])]
        out.append((q, stab, equivalents, e, exists))
    return out


def _conditions_hold(ctx: Context, entry: dict, p) -> bool:
    """Each of the equilibrium's ``conditions`` ≥ 0 at the point (docs/json.md: it exists
    only where each is): False where one is negative beyond rounding, or not real (the
    reader gives an mpc only past rounding)."""
    for text in entry.get("conditions") or []:
        try:
            value = ctx.reader.value(text, p)
        except NotANumber:  # infinite at the point: it decides nothing there
            continue
        if isinstance(value, mpmath.mpc) or value < -mpmath.mpf("1e-20") * (1 + abs(value)):
            return False
    return True


def _hessian(ctx, ms, q, entry, i):
    """The Hessian printed with an equilibrium against the oracle's K = ∂E/∂q at rest."""
    hessian = entry.get("hessian")
    curvatures = entry.get("curvatures")
    if not hessian and not curvatures:
        return
    K, _ = ms.stiffness(q, gyroscopic=False)
    if curvatures:
        import numpy as np
        Kf = np.array(K, float)
        mine = np.linalg.eigvalsh((Kf + Kf.T) / 2)
        scale = np.abs(mine).max() + float(ms.force_scale()) * 1e-6
        if len(mine) != len(curvatures) or np.abs(np.sort(curvatures) - mine).max() > 1e-6 * scale:
            raise Mismatch(f"curvatures at {entry['at']}: rbdsolve {fmt(curvatures)}, oracle {fmt(list(mine))}")
        return
    top = max(abs(x) for row in K for x in row) + ms.force_scale() * mpmath.mpf("1e-6")
    for a, row in enumerate(hessian):
        for b, text in enumerate(row):
            got = ctx.reader.value(text, ctx.points[i], q)
            if got is not None and abs(got - K[a][b]) > 1e-7 * top:
                raise Mismatch(f"Hessian at {entry['at']}: entry [{a + 1}][{b + 1}] rbdsolve {fmt(got)}, "
                               f"oracle {fmt(K[a][b])} at {_params(ctx, i)}")


def _along_continuum(ms, r, k, bx) -> bool:
    """r and a listed k differ only along directions where every point is an equilibrium
    too (K singular there: a coordinate V does not depend on, listed once)."""
    import numpy as np
    K, _ = ms.stiffness(r, gyroscopic=False)
    K = np.array(K, float)
    lam, vec = np.linalg.eigh((K + K.T) / 2)
    null = vec[:, np.abs(lam) <= 1e-9 * max(np.abs(lam).max(), 1e-300)]
    if null.shape[1] == 0:
        return False
    d = np.array([float(a - b) for a, b in zip(r, k)])
    for j, (lo, hi, per) in enumerate(bx):
        if per:
            d[j] = (d[j] + np.pi) % (2 * np.pi) - np.pi
    rest = d - null @ (null.T @ d)
    return bool(np.abs(rest).max() < 1e-6 * max(1.0, np.abs(d).max()))


def _params(ctx: Context, i: int) -> str:
    return "{" + ", ".join(f"{k}={fmt(v)}" for k, v in ctx.points[i].items()) + "}"


def check(ctx: Context, question, result: dict) -> list[str]:
    notes: list[str] = []
    answers = result["answers"]
    warnings = [w for w in result.get("warnings", []) if "may miss" in w or "may exist" in w]
    for i in points_for(ctx, result) + boundary_points(ctx, result):
        ms, fs = ctx.system(i), ctx.system(i, FLOAT)
        bx = box(ms)
        rb = listed(ctx, answers, i)
        floor = ms.force_scale()
        zero = [ms.zero] * ms.n
        for q, stab, _, entry, exists in rb:
            Q, S = ms.residual(q, zero, zero, sizes=True)
            if any(abs(x) > 1e-7 * (sz + floor) for x, sz in zip(Q, S)):
                raise Mismatch(f"listed equilibrium {entry['at']} = {fmt(q)} is not one: Q = {fmt(Q)} "
                               f"at {_params(ctx, i)}")
            _hessian(ctx, ms, q, entry, i)
            if not regular(ms, q) or stab is None or exists is None:
                continue
            kind, lam = stability(ms, q)
            if stab in ("stable", "unstable") and kind != "singular" and stab != kind:
                raise Mismatch(f"equilibrium {entry['at']} = {fmt(q)}: rbdsolve {stab}, oracle {kind} "
                               f"(λ = {fmt(lam)}) at {_params(ctx, i)}")
            if stab in ("undetermined", "neutral") and kind != "singular":
                notes.append(f"{stab} where the oracle finds it {kind}")
        if "equilibria" not in answers:
            continue
        found = [r for r in equilibria(ms, fs) if not ms.polar_negative(r)]  # (−r, θ) is (r, θ + π)
        known = []
        for q, _, eq, _, _ in rb:
            known += [x for x in [wrap(q, bx)] + [wrap(e, bx) for e in eq] if x is not None]
        for r in found:
            if not any(same(r, k, bx, 1e-6) or _along_continuum(ms, r, k, bx) for k in known):
                kind, _ = stability(ms, r)
                missed = (f"missed the equilibrium {dict(zip([c.name for c in ctx.scene.coords], fmt(r)[1:-1].split(', ')))} "
                          f"({kind}) at {_params(ctx, i)}")
                if warnings:
                    raise Partial(warnings[0], missed + " (rbdsolve warned that its list is not complete)")
                raise Mismatch(missed)
    return notes

