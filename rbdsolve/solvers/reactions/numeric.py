"""The reactions in floating point, at a state: the same free body rows (balances.py)
with the parameter values and the state put in as floats, the accelerations solved from
M q̈ = −h and the forces from A x = b by least squares (numpy). Error: the largest
balance left over, relative to the size of its terms."""

from __future__ import annotations

import numpy as np
import sympy as sp

from rbdsolve.errors import InputError, UnsolvedError
from rbdsolve.form.display import Relation
from rbdsolve.model.build import Model
from rbdsolve.problem.schema import Question
from rbdsolve.report import steps as st
from rbdsolve.report.steps import Route, Solution
from rbdsolve.solvers.reactions.answers import NumericReactionsAnswers
from rbdsolve.solvers.reactions.balances import located, unheld
from rbdsolve.solvers.reactions.exact import setup
from rbdsolve.solvers.lagrange.accelerations import state_values
from rbdsolve.solvers.routes.options import Options
from rbdsolve.solvers.routes.needed import require_values

EPS = 2.0**-52


def solve(question: Question, model: Model, options: Options) -> Solution:
    require_values(model, "the numeric route")
    instant = question.options.instant
    if instant is None:
        raise UnsolvedError("the numeric route answers at a state: give 'at:' or 'from_rest:'")
    if question.options.to:  # the energy integral along the way is the exact route's (exact.py, _there)
        raise UnsolvedError("the forces where the motion gets to ('to') are answered on the exact route only")
    supports, solved, rows = setup(question, model)
    # sp.N, not sp.Float: a value may be exact and irrational (30 deg is pi/6); the state may
    # name a parameter (from_rest: {x: x0}), its value put in too
    given = {k: sp.N(v, 17) for k, v in model.values.items()}
    point = {**given, **{k: sp.N(v.xreplace(given), 17) for k, v in state_values(model, instant).items()}}
    qdd = {a: sp.N(v.xreplace(point), 17) for a, v in zip(model.qdd, solved)}
    unknowns = [c.symbol for s in supports for c in s.components]
    exprs = [sp.expand((r.lhs - r.rhs).xreplace(point).xreplace(qdd)) for r in rows]
    left = sorted({str(s) for e in exprs for s in e.free_symbols} - {str(x) for x in unknowns})
    if left:  # t, where a load or a support is driven: a state alone does not give numbers
        raise UnsolvedError(f"the forces at the state still depend on {', '.join(left)} (the scene changes with "
                            "time: a driven support, a force given as a function of t), which a state does not "
                            "fix; the exact route gives them as functions of it")
    A = np.array([[float(e.coeff(x)) for x in unknowns] for e in exprs])
    b = np.array([-float(e.xreplace({x: 0 for x in unknowns})) for e in exprs])
    x, *_ = np.linalg.lstsq(A, b, rcond=None)
    scale = np.abs(A) @ np.abs(x) + np.abs(b)
    residual = float(np.max(np.abs(A @ x - b) / np.where(scale > 0, scale, 1.0)))
    if residual > 1e-8:
        worst = rows[int(np.argmax(np.abs(A @ x - b) / np.where(scale > 0, scale, 1.0)))]
        raise InputError(unheld(worst.body, f"its {worst.label} balance, by {residual:.1e} of its size"),
                         located(supports, worst.body))
    values = dict(zip(unknowns, (float(v) for v in x)))
    at = {s.name: {str(c.symbol): values[c.symbol] for c in s.components} for s in supports}
    answers = NumericReactionsAnswers(at, {n: float(v) for n, v in zip(model.coordinate_names(), qdd.values())},
                                      residual)
    step = st.result("The forces at the state, from Newton–Euler per body with the values as floats (least "
                     f"squares; balances left ≤ {max(residual, EPS):.1e} of their size):",
                     *[Relation(sp.Symbol(k), sp.Float(v, 15)) for name in at for k, v in at[name].items()])
    return Solution("reactions", Route.NUMERIC, answers, (step,), error_estimate=max(residual, EPS))
