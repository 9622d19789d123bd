"""Solver families: one module per family, each a pure function

    solve(question, model, options) -> Solution

``solve_file`` builds a problem's model and runs every question, each within its time
budget (``budget.within``), and times each one.
"""

from __future__ import annotations

import time
from dataclasses import replace
from typing import Callable

from rbdsolve.errors import UnsolvedError
from rbdsolve.model.build import Model, build_model
from rbdsolve.problem.schema import Problem, Question, QuestionKind
from rbdsolve.report.steps import ProblemReport, Route, Solution
from rbdsolve.solvers import eom, equilibria, impact, inertia, modes, steady_motion, steady_spin
from rbdsolve.solvers.budget import OutOfTime, within
from rbdsolve.solvers.common import Options, numeric
from rbdsolve.solvers.energies import summarize_model
from rbdsolve.solvers.frames import frame_of, solve_in_frame

SOLVERS = {
    QuestionKind.EOM: eom.solve,
    QuestionKind.EQUILIBRIA: equilibria.solve,
    QuestionKind.MODES: modes.solve,
    QuestionKind.INERTIA: inertia.solve,
    QuestionKind.IMPACT: impact.solve,
    QuestionKind.STEADY_SPIN: steady_spin.solve,
    QuestionKind.STEADY_MOTION: steady_motion.solve,
}


def solve_question(question: Question, model: Model, options: Options) -> Solution:
    """Run one question's solver within its time budget; an unanswerable question, or
    one past its budget, becomes a Solution with an error (exit code 1), not an
    exception, so the other questions still run."""
    start = time.perf_counter()
    try:
        with within(options.budget, f"'{question.kind.value}'"):
            solution = _answer(question, model, options)
    except (UnsolvedError, OutOfTime) as exc:
        solution = Solution(question.kind.value, Route.EXACT, None, (), error=str(exc))
    return replace(solution, seconds=time.perf_counter() - start)


def _answer(question: Question, model: Model, options: Options) -> Solution:
    if frame_of(question) is None:
        solution = SOLVERS[question.kind](question, model, options)
    else:
        solution = solve_in_frame(SOLVERS[question.kind], question, model, options)
    values = numeric(solution.answers, model.values) if model.values and solution.answers else {}
    return replace(solution, values=values or {})


def solve_problem(model: Model, options: Options = Options()) -> ProblemReport:
    """Every question of a model already built, each within the budget."""
    return _solve(model.problem, lambda: model, options)


def solve_file(problem: Problem, options: Options = Options()) -> ProblemReport:
    """Build the model of ``problem``, then answer every question, each within the budget."""
    return _solve(problem, lambda: build_model(problem), options)


def _solve(problem: Problem, build: Callable[[], Model], options: Options) -> ProblemReport:
    """The model section (T, V, the parameter values) within one budget, then each
    question within its own. A model past its budget is an UnsolvedError for the whole
    file (exit code 1), said in one line."""
    try:
        with within(options.budget, "the model (T and V)"):
            model = build()
            model = model.with_values(options.values) if options.values else model
            summary = summarize_model(model)
    except OutOfTime as exc:
        raise UnsolvedError(f"{problem.file}: {exc}") from None
    solutions = tuple(solve_question(q, model, options) for q in problem.questions)
    values = {str(k): float(v) for k, v in model.values.items()}
    symbols = tuple(p.name for p in problem.parameters) + problem.unknowns
    return ProblemReport(problem.file, problem.title, problem.source, problem.statement,
                         summary, solutions, values, symbols)


__all__ = ["Options", "SOLVERS", "solve_file", "solve_problem", "solve_question"]
