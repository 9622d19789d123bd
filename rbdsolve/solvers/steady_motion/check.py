"""What a steady motion must satisfy, for the check before it is printed
(solvers/routes/checks.py): each solution, put into the balances it was solved from
(``relations``, each = 0), makes every one of them vanish wherever it is real."""

from __future__ import annotations

import sympy as sp

from rbdsolve.model.build import Model
from rbdsolve.problem.schema import Question
from rbdsolve.solvers.routes.checks import Residual, Vanishes
from rbdsolve.solvers.steady_motion.answers import SteadyMotionAnswers


def residuals(question: Question, model: Model, answers: object) -> tuple[Residual, ...]:
    """Each relation at each solution (the reactions' other unknowns found put in too);
    a relation that still holds an unknown no solution fixes is not checked."""
    if not isinstance(answers, SteadyMotionAnswers):
        return ()
    asked = [(x.text, model.symbols.scalar(x)) for x in question.options.solve_for]
    solutions = [(b.solved, b.exists_when) for b in answers.branches]
    if not solutions and answers.solved:
        solutions = [(answers.solved, sp.true)]
    unknowns = {model.symbols.parameters[u] for u in model.problem.unknowns}
    found = {model.symbols.parameters[u]: v for u, v in {**answers.rates, **answers.found_along}.items()}
    out = []
    for k, (solved, where) in enumerate(solutions, 1):
        name = f" at solution {k}" if len(solutions) > 1 else ""
        for i, relation in enumerate(answers.relations, 1):
            value = relation.xreplace(found)
            for text, target in asked:  # a symbol replaced as it is; a square (omega0**2) by subs
                if text in solved and target.is_Symbol:
                    value = value.xreplace({target: solved[text]})
                elif text in solved:
                    value = value.subs(target, solved[text])
            if not value.free_symbols & unknowns:
                out.append(Vanishes(f"balance {i}{name}", value, where))
    return tuple(out)
