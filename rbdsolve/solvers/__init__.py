"""Solver families: one module per family, each a pure function

    solve(question, model, options) -> Solution

``solve_file`` builds a problem's model and runs every question, each within its time
budget (``budget.within``), and times each one.
"""

from __future__ import annotations

import importlib
import math
import time
from dataclasses import dataclass, replace
from typing import Callable

from rbdsolve.errors import UnsolvedError
from rbdsolve.model.build import Model, build_model
from rbdsolve.problem.schema import Problem, Question, QuestionKind
from rbdsolve.report.steps import ProblemReport, Route, Solution
from rbdsolve.solvers.budget import OutOfTime, within
from rbdsolve.solvers.common import Options, RouteChoice, numeric
from rbdsolve.solvers.energies import coordinates_only, summarize_model
from rbdsolve.solvers.frames import frame_of, solve_in_frame


@dataclass(frozen=True)
class Family:
    """A solver family's routes: each a pure function (question, model, options) -> Solution."""

    exact: Callable[[Question, Model, Options], Solution]
    numeric: Callable[[Question, Model, Options], Solution] | None = None


def _later(module: str) -> Callable[[Question, Model, Options], Solution]:
    """A route whose module is imported when first asked (numpy, scipy and the numeric
    machinery stay out of a process that only takes the exact route)."""

    def solve(question: Question, model: Model, options: Options) -> Solution:
        return importlib.import_module(f"rbdsolve.solvers.{module}").solve(question, model, options)

    solve.__qualname__ = f"{module}.solve"
    return solve


FAMILIES = {
    QuestionKind.EOM: Family(_later("eom")),
    QuestionKind.EQUILIBRIA: Family(_later("equilibria"), _later("equilibria_numeric")),
    QuestionKind.MODES: Family(_later("modes"), _later("modes_numeric")),
    QuestionKind.INERTIA: Family(_later("inertia"), _later("inertia_numeric")),
    QuestionKind.IMPACT: Family(_later("impact"), _later("impact_numeric")),
    QuestionKind.STEADY_SPIN: Family(_later("steady_spin"), _later("steady_spin_numeric")),
    QuestionKind.STEADY_MOTION: Family(_later("steady_motion")),
}


def solve_question(question: Question, model: Model, options: Options) -> Solution:
    """Run one question's solver on the route asked for, within its time budget; an
    unanswerable question, or one past its budget, becomes a Solution with an error
    (exit code 1), not an exception, so the other questions still run."""
    start = time.perf_counter()
    try:
        solution = _routed(question, model, options)
    except (UnsolvedError, OutOfTime) as exc:
        solution = Solution(question.kind.value, _route_of(options), None, (), error=str(exc))
    values = numeric(solution.answers, model.values) if model.values and solution.answers else {}
    return replace(_finite_estimate(solution), values=values or {}, seconds=time.perf_counter() - start)


def _finite_estimate(solution: Solution) -> Solution:
    """``error_estimate`` is a number or None (docs/json.md): a route whose estimate is not
    finite (a singular matrix in it) gives none, and a warning says so, rather than an
    infinity that strict JSON cannot hold."""
    estimate = solution.error_estimate
    if estimate is None or math.isfinite(estimate):
        return solution
    note = (f"no error estimate: the route's estimate is not finite ({estimate}), e.g. a singular Hessian "
            "where the equilibria form a continuum")
    return replace(solution, error_estimate=None, warnings=(*solution.warnings, note))


def _routed(question: Question, model: Model, options: Options) -> Solution:
    """exact, numeric, or auto: exact, and numeric where exact cannot answer and every
    parameter has a value (the report says which ran, and why)."""
    family = FAMILIES[question.kind]
    if options.route is RouteChoice.EXACT:
        return _run(family.exact, question, model, options)
    if options.route is RouteChoice.NUMERIC:
        if family.numeric is None:
            raise UnsolvedError(f"'{question.kind.value}' has no numeric route yet; use --route exact")
        return _run(family.numeric, question, model, options)
    try:
        return _run(family.exact, question, model, options)
    except (UnsolvedError, OutOfTime) as exact_failed:
        if family.numeric is None or not _has_all_values(model):
            raise
        solution = _run(family.numeric, question, model, options, " (numeric route)")
        note = f"the exact route could not answer ({exact_failed}); these are the numeric route's answers"
        return replace(solution, warnings=(note, *solution.warnings))


def _run(solver, question: Question, model: Model, options: Options, route: str = "") -> Solution:
    with within(options.budget, f"'{question.kind.value}'{route}"):
        if frame_of(question) is None:
            return solver(question, model, options)
        return solve_in_frame(solver, question, model, options)


def _route_of(options: Options) -> Route:
    return Route.NUMERIC if options.route is RouteChoice.NUMERIC else Route.EXACT


def _has_all_values(model: Model) -> bool:
    return all(model.symbols.parameters[p.name] in model.values for p in model.problem.parameters)


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
            summary = coordinates_only(model) if options.route is RouteChoice.NUMERIC else summarize_model(model)
    except OutOfTime as exc:
        raise UnsolvedError(f"{problem.file}: {exc}") from None
    solutions = tuple(solve_question(q, model, options) for q in problem.questions)
    values = {str(k): float(v) for k, v in model.values.items()}
    symbols = tuple(p.name for p in problem.parameters) + problem.unknowns
    return ProblemReport(problem.file, problem.title, problem.source, problem.statement,
                         summary, solutions, values, symbols)


__all__ = ["FAMILIES", "Family", "Options", "RouteChoice", "solve_file", "solve_problem", "solve_question"]
