"""The names the equilibria's worked solution prints its answers by (report/numbers.py):
each equilibrium's place (θ, φ) and its Hessian K (or, on the numeric route, the
eigenvalues eig(H) of it), under its heading, and the critical values (Ω_c)."""

from __future__ import annotations

import sympy as sp

from rbdsolve.model.build import Model
from rbdsolve.report.numbers import Named
from rbdsolve.solvers.routes.labels import labels_for
from rbdsolve.solvers.routes.naming import criticals, state


def named(question, answers, model: Model) -> tuple[Named, ...]:
    K = labels_for(model, "stiffness_matrix").symbol("stiffness_matrix")
    out: list[Named] = []
    for i, eq in enumerate(answers.equilibria):
        group = f"Equilibrium {i + 1}"
        out.append(Named(("equilibria", i, "at"), state(model, eq.at), group))
        out.append(Named(("equilibria", i, "hessian"), K, group) if hasattr(eq, "hessian")
                   else Named(("equilibria", i, "curvatures"), sp.Symbol("eig(H)"), group))
    return tuple(out + criticals(("critical",), getattr(answers, "critical", ())))
