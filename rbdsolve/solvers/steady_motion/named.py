"""The names the steady motion's worked solution prints its answers by
(report/numbers.py): the rates the rolling conditions fix, ω in the triad, each
quantity solved for as written (Ω², N), the reactions' other unknowns, every solution
under its heading, and the critical values (Ω_c)."""

from __future__ import annotations

import sympy as sp

from rbdsolve.model.build import Model
from rbdsolve.report.numbers import Named
from rbdsolve.solvers.routes.naming import criticals
from rbdsolve.solvers.steady_motion.steps import omega_label


def named(question, answers, model: Model) -> tuple[Named, ...]:
    targets = {x.text: model.symbols.scalar(x) for x in question.options.solve_for}
    if hasattr(answers, "solutions"):  # the numeric route: each solution's unknowns and values
        return tuple(n for k, s in enumerate(answers.solutions) for n in _solution(
            ("solutions", k), s, targets, model, "" if len(answers.solutions) == 1 else f"Solution {k + 1}"))
    again = {x for a in answers.at_solutions for x in a.rates}  # given at each solution: not twice (spin = −6.67 Ω, then −29.9 rad/s)
    out = [Named(("rates", a), sp.Symbol(a)) for a in answers.rates if a not in again]
    out += [Named(("angular_velocity",), omega_label(model))]
    out += _solved(("solved",), answers.solved, targets)
    out += [Named(("found_along", u), sp.Symbol(u)) for u in answers.found_along]
    several = len(answers.branches) > 1
    for k, b in enumerate(answers.branches if several else ()):  # one branch is ``solved`` itself
        out += _solved(("branches", k, "solved"), b.solved, targets, f"Solution {k + 1}")
    for k, a in enumerate(answers.at_solutions):  # the solution's values put back in ω and the rates
        group = f"Solution {k + 1}" if several else ""
        out += [Named(("at_solutions", k, "values", x), targets.get(x, sp.Symbol(x)), group) for x in a.values]
        out += [Named(("at_solutions", k, "rates", x), sp.Symbol(x), group) for x in a.rates]
        out += [Named(("at_solutions", k, "angular_velocity"), omega_label(model), group)] if a.angular_velocity else []
    return tuple(out + criticals(("critical",), answers.critical))


def _solved(path, solved: dict, targets: dict, group: str = "") -> list[Named]:
    return [Named((*path, x), targets.get(x, sp.Symbol(x)), group) for x in solved]


def _solution(path, s, targets: dict, model: Model, group: str) -> list[Named]:
    out = [Named((*path, "unknowns", u), sp.Symbol(u), group) for u, v in s.unknowns.items() if v is not None]
    out += [Named((*path, "angular_velocity"), omega_label(model), group)]
    return out + _solved((*path, "solved"), s.solved, targets, group)
