"""energy: the oracle's own T = Σ ½ m v² + ½ ω·J ω and V = −Σ m g·r_G + ½ Σ k s²: the
integral T + V at random states and at the start, and with one coordinate
q̇²(q) = 2 (T₀ + V₀ − V(q))/M(q), each point's v² = |∂r/∂q|² q̇², and the rates and
speeds at the configuration asked (reached, and reached_when, where q̇² ≥ 0)."""

from __future__ import annotations

import mpmath
import numpy as np

from benchmarks.neighbours.check.context import Context, Mismatch, close, fmt, points_for, random_state, rtol


def rate_squared(s, start, q):
    """q̇² at q from T + V constant, one coordinate, from the start state (q₀, q̇₀)."""
    q0, qd0 = start
    # T₀ + V₀ once per start: a scan or a bisection along the motion asks at every point
    energies = s.__dict__.setdefault("_start_energy", {})
    key = (tuple(q0), tuple(qd0))
    if key not in energies:
        energies[key] = s.kinetic(q0, qd0) + s.potential(q0)
    e0 = energies[key]
    M = s.mass_matrix(q)[0][0]
    return 2 * (e0 - s.potential(q)) / M


def point_speed2(s, text, q, rate2):
    f = lambda qq, tt: np.array([s.one * x for x in s.value(text, qq, tt)], dtype=object)  # noqa: E731
    d = s.partials(f, q, 0)[0]
    return d.dot(d) * rate2


def check(ctx: Context, question, result: dict) -> None:
    answers = result["answers"]
    tol = rtol(result)
    opts = question.options
    coords = [c.name for c in ctx.scene.coords]
    numeric = result.get("route") == "numeric"
    for i in points_for(ctx, result):
        s = ctx.system(i)
        p = ctx.points[i]
        q0, qd0, _ = ctx.state(opts, i)
        e0 = s.kinetic(q0, qd0) + s.potential(q0)
        scale = abs(e0) + abs(s.potential([x * 0 for x in q0])) + s.force_scale() * s.length
        if not numeric and answers.get("integral") == "T + V" and "constant" in answers:
            q, qd, _ = random_state(ctx, i)
            want = s.kinetic(q, qd) + s.potential(q)
            got = ctx.reader.value(answers["constant"], p, q, qd)
            if not close(got, want, scale, tol):
                raise Mismatch(f"T + V at q={fmt(q)}, q̇={fmt(qd)}: rbdsolve {fmt(got)}, oracle {fmt(want)}")
            got = ctx.reader.value(answers["start"], p)
            if not close(got, e0, scale, tol):
                raise Mismatch(f"T + V at the start: rbdsolve {fmt(got)}, oracle {fmt(e0)}")
        if len(coords) != 1 or answers.get("integral", "T + V") != "T + V" and not numeric:
            continue
        if not numeric:
            for frac in (0.3, 0.8):
                q = [q0[0] * (1 - frac) + frac * 0.1 * s.scale[0]]
                want = rate_squared(s, (q0, qd0), q)
                # a floor for a q̇² that is 0 (a wheel on a level floor): the oracle's own
                # rounding of T + V, over the inertia, is ~1e-14 there, not 0
                floor = scale / max(abs(float(s.mass_matrix(q)[0][0])), 1e-300) + 1e-6
                got = (answers.get("rate_squared") or {}).get(coords[0])
                got = ctx.reader.value(got, p, q) if got is not None else want
                if not close(got, want, abs(want) + floor, tol):
                    raise Mismatch(f"q̇² at {coords[0]} = {fmt(q[0])}: rbdsolve {fmt(got)}, oracle {fmt(want)}")
                for name, text in (answers.get("speed_squared") or {}).items():
                    want_v = point_speed2(s, name, q, want)
                    got = ctx.reader.value(text, p, q)
                    if not close(got, want_v, abs(want_v) + 1e-6, tol):
                        raise Mismatch(f"v² of {name} at {fmt(q[0])}: rbdsolve {fmt(got)}, oracle {fmt(want_v)}")
        there = answers.get("there")
        if there and opts.get("to"):
            q = [ctx.const(opts["to"][c], i) for c in coords]
            want = rate_squared(s, (q0, qd0), q)
            rs = (there.get("rate_squared") or {}).get(coords[0]) if isinstance(there.get("rate_squared"), dict) else there.get("rate_squared")
            if rs is not None:
                got = ctx.reader.value(rs, p)
                if not close(got, want, abs(e0) / max(float(s.mass_matrix(q)[0][0]), 1e-300) * 1e-6 + 1e-12, tol):
                    raise Mismatch(f"q̇² at {opts['to']}: rbdsolve {fmt(got)}, oracle {fmt(want)}")
            reached = there.get("reached")
            decided = abs(want) > 1e-9 * (abs(e0) + 1)
            if reached is not None and decided and reached != (want >= 0):
                raise Mismatch(f"reached {reached} at {opts['to']}, but the oracle's q̇² there is {fmt(want)}")
            when = ctx.reader.truth(there.get("reached_when", "True"), p)  # where the parameters decide it
            if when is not None and decided and when != (want >= 0):
                raise Mismatch(f"reached_when {there.get('reached_when')} is {when} at {opts['to']}, but the "
                               f"oracle's q̇² there is {fmt(want)}")
            if want > 0:
                for name, text in (there.get("speed") or {}).items():
                    if text is None:
                        continue
                    got = ctx.reader.value(text, p)
                    v = mpmath.sqrt(point_speed2(s, name, q, want))
                    if not close(got, v, 1e-9, tol):
                        raise Mismatch(f"speed of {name} at {opts['to']}: rbdsolve {fmt(got)}, oracle {fmt(v)}")
