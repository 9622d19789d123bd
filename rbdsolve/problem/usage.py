"""Which declared parameters the problem uses: a parameter no expression of the scene or
of a question names changes no answer, and is most likely a line left out (a pendulum
whose ``gravity:`` was forgotten has g declared and used nowhere: V = 0, a "neutral"
equilibrium, λ = 0). The solvers warn of it (``model/summary/summary.py``).

Used means named by an expression anywhere but ``parameters:`` themselves, ``values:``
(a value uses nothing) and ``assumptions:`` (a bound on a parameter that nothing else
holds decides nothing): points, bodies, springs, gravity, frames, prescribed motions,
contacts, coordinate ranges and every question's options; and `Omega` where a steady spin's
answers are written in it.
"""

from __future__ import annotations

import dataclasses

from rbdsolve.problem import expr as ex
from rbdsolve.problem.schema import Parameter, Problem, QuestionKind

NOT_USES = frozenset({"parameters", "values", "ranges", "assumptions", "dimensions"})


def unused_parameters(problem: Problem) -> tuple[Parameter, ...]:
    """The declared parameters no expression of the scene or of a question names, in
    the file's order."""
    used: set[str] = set()
    for field in dataclasses.fields(problem):
        if field.name not in NOT_USES:
            _collect(getattr(problem, field.name), used)
    if any(q.kind is QuestionKind.STEADY_SPIN for q in problem.questions):
        used.add(SPIN_SIZE)
    return tuple(p for p in problem.parameters if p.name not in used)


SPIN_SIZE = "Omega"  # a steady spin's size Ω in its answers (solvers/steady_spin), named by no expression


def _collect(value: object, used: set[str]) -> None:
    """Every name in the expressions held by ``value`` (a dataclass of the schema, a
    tuple of them, an expression), added to ``used``."""
    if isinstance(value, ex.Expr):
        used.update(value.names())
    elif isinstance(value, (tuple, list)):
        for item in value:
            _collect(item, used)
    elif dataclasses.is_dataclass(value) and not isinstance(value, type):
        for field in dataclasses.fields(value):
            _collect(getattr(value, field.name), used)
