"""What the oracle expects for a failing scene, saved beside it (NAME.oracle.json): at
its first parameter point, per question, the oracle's own numbers — equilibria with
their stability, the eigenvalues at the equilibrium asked about, the accelerations at
the state asked, the supports' forces there, q̇² at the configuration asked, an
impact's velocities after, an inertia tensor — so that the scene is ready to turn into
a test once the bug is fixed."""

from __future__ import annotations

import mpmath
import numpy as np

from benchmarks.neighbours.expr import FLOAT


def _f(x):
    return float(x) if not isinstance(x, (list, tuple)) else [_f(y) for y in x]


def expected(ctx, question) -> dict:
    kind = question.kind
    s = ctx.system(0)
    opts = question.options
    coords = [c.name for c in ctx.scene.coords]
    out: dict = {"parameters": {k: float(v) for k, v in ctx.points[0].items()}}
    if kind in ("equilibria", "modes"):
        from benchmarks.neighbours.oracle.search import equilibria, stability
        eq = []
        for r in equilibria(s, ctx.system(0, FLOAT)):
            word, lam = stability(s, r)
            eq.append({"at": dict(zip(coords, _f(r))), "stability": word, "eigenvalues": [float(x) for x in lam]})
        out["equilibria"] = eq
    if kind in ("eom", "reactions", "energy") and ("from_rest" in opts or "at" in opts):
        q, qd, _ = ctx.state(opts, 0)
        out["state"] = {"q": _f(q), "qd": _f(qd)}
        out["accelerations"] = dict(zip(coords, _f(s.accelerations(q, qd))))
        if kind == "reactions":
            from benchmarks.neighbours.oracle.reactions import support_forces
            forces, _ = support_forces(s, q, qd)
            out["forces"] = {name: _f(list(f[0])) for name, f in forces.items()}
        if kind == "energy" and opts.get("to") and len(coords) == 1:
            from benchmarks.neighbours.check.energy import rate_squared
            to = [ctx.const(opts["to"][c], 0) for c in coords]
            out["rate_squared_at_to"] = float(rate_squared(s, (q, qd), to))
    if kind == "impact":
        from benchmarks.neighbours.check.impact import oracle
        _, _, _, res, _, _ = oracle(ctx, question, 0)
        out["velocities_after"] = dict(zip(coords, _f(res["qd"])))
    if kind == "inertia":
        out["J_G_body_axes"] = [[float(x) for x in row] for row in s.bodies[0].inertia]
    if kind == "steady_spin":
        out["principal_moments"] = [float(x) for x in np.linalg.eigvalsh(s.bodies[0].inertia)]
    return out
