"""steady_motion: each solution rbdsolve gives (where it exists), put into the scene,
must be a motion of the body: Newton–Euler about its centre with the one support's
force F = m (a_G − g) at the support point P (a pivot, or the contact) gives
J ω̇ + ω × J ω − (P − G) × F = 0 at every instant (two instants checked), and at a
rolling contact the body's point there is at rest (v_G + ω × (P − G) = 0)."""

from __future__ import annotations

import mpmath
import numpy as np

from benchmarks.neighbours.check.context import Context, Mismatch, fmt
from benchmarks.neighbours.oracle.mechanics import System, _cross
from benchmarks.neighbours.read import NotANumber


def _solutions(answers: dict) -> list[tuple[dict, str]]:
    branches = answers.get("branches") or []
    if branches:
        return [(b["solved"], b.get("exists_when", "True")) for b in branches]
    return [(answers.get("solved") or {}, "True")]


def check(ctx: Context, question, result: dict) -> list[str]:
    answers = result["answers"]
    notes: list[str] = []
    if result.get("route") == "numeric":
        return _numeric(ctx, question, result)
    for i in range(len(ctx.points)):
        p = dict(ctx.points[i])
        for solved, exists in _solutions(answers):
            truth = ctx.reader.truth(exists, p)
            if truth is not True:
                continue
            point = dict(p)
            for expr, text in solved.items():
                try:
                    value = ctx.reader.value(text, p)
                except NotANumber:
                    notes.append(f"{expr} = {text} has no value at {fmt(p)} (a division by zero)")
                    break
                if isinstance(value, mpmath.mpc):
                    raise Mismatch(f"steady motion: {expr} = {text} is not real where it exists ({exists})")
                name = expr.split("**")[0]
                point[name] = mpmath.sqrt(value) if expr.endswith("**2") else value
            else:
                for name, text in (answers.get("rates") or {}).items():
                    point[name] = ctx.reader.value(text, point)
                _balance(ctx, point, question)
    return notes


def _numeric(ctx, question, result):
    for sol in (result["answers"].get("solutions") or []):
        point = dict(ctx.points[0])
        point.update({k: mpmath.mpf(v) for k, v in (sol.get("unknowns") or {}).items() if v is not None})
        _balance(ctx, point, question)


def _balance(ctx, point: dict, question) -> None:
    s = System(ctx.scene, point)
    for t in (mpmath.mpf(0), mpmath.mpf("0.37")):
        (r, v, a, R, w, wd), = s.motion([], [], [], t)
        J = s.spatial_inertia(0, R)
        P = s.vector("_P", [], t)
        F = s.bodies[0].mass * (a - s.g)
        res = J.dot(wd) + _cross(w, J.dot(w)) - _cross(P - r, F)
        scale = sum(abs(x) for x in _cross(w, J.dot(w))) + sum(abs(x) for x in _cross(P - r, s.bodies[0].mass * s.g))
        if max(abs(x) for x in res) > 1e-8 * scale:
            raise Mismatch(f"steady motion with {fmt({k: point[k] for k in point if k not in ctx.points[0]})}: "
                           f"Newton–Euler about G is off by {fmt(list(res))} (scale {fmt(scale)})")
        slip = v + _cross(w, P - r)
        if question.options.get("about") == "C" and max(abs(x) for x in slip) > 1e-8 * (sum(abs(x) for x in v) + 1):
            raise Mismatch(f"steady motion: the body slips at the contact ({fmt(list(slip))})")
