"""What the reactions must satisfy, for the check before they are printed
(solvers/routes/checks.py): with the accelerations answered, Lagrange's equations vanish; with
them and the forces answered, every row of every held body's balances (Newton–Euler:
m a_G = m g + Σ R, dL_G/dt = Σ M) does too, as functions of the state (the
coordinates and rates drawn at random) and at the state asked for."""

from __future__ import annotations

import sympy as sp

from rbdsolve.model.build import Model
from rbdsolve.problem.schema import Question
from rbdsolve.solvers.eom.exact import lagrange_equations
from rbdsolve.solvers.reactions.answers import Reaction, ReactionsAnswers
from rbdsolve.solvers.reactions.balances import balances, with_strings
from rbdsolve.solvers.reactions.supports import held, planar
from rbdsolve.solvers.lagrange.accelerations import state_values
from rbdsolve.solvers.routes.checks import Residual, Vanishes


def residuals(question: Question, model: Model, answers: object) -> tuple[Residual, ...]:
    if not isinstance(answers, ReactionsAnswers) or not isinstance(next(iter(answers.accelerations.values()), None),
                                                                     sp.Basic):
        return ()
    plain = _plain(model)
    qdd = {a: answers.accelerations[n].xreplace(plain) for n, a in zip(model.coordinate_names(), model.qdd)}
    out: list[Residual] = [Vanishes(f"Lagrange's equation of {n}", E.xreplace(qdd))
                           for n, E in zip(model.coordinate_names(), lagrange_equations(model))]
    supports = with_strings(model, tuple(held(model, s) for s in question.options.supports), question.options.loc)
    rows = balances(model, supports, 2 if planar(model) else 3)
    symbols = {str(c.symbol): c.symbol for s in supports for c in s.components}
    out += _rows(rows, qdd, _forces(answers.reactions, symbols, plain), {}, "")
    if answers.at is not None and question.options.instant is not None:
        table = state_values(model, question.options.instant)
        out += _rows(rows, qdd, _forces(answers.at, symbols, plain), table, " at the state")
    return tuple(out)


def _rows(rows, qdd: dict, forces: dict, table: dict, where: str) -> list[Residual]:
    return [Vanishes(f"body {r.body}'s {r.label} balance{where}",
                     (r.lhs - r.rhs).xreplace(qdd).xreplace(forces).xreplace(table)) for r in rows]


def _forces(reactions: dict[str, Reaction], symbols: dict, plain: dict) -> dict:
    """{component's symbol: its answer}, the state back as plain symbols."""
    return {symbols[k]: v.xreplace(plain) for r in reactions.values() for k, v in r.components.items() if k in symbols}


def _plain(model: Model) -> dict:
    """q(t), dq/dt and d²q/dt² back to the model's plain symbols (answers are in time form)."""
    return {model.to_time(x): x for x in (*model.qdd, *model.qd, *model.q)}
