"""How a question is answered: its family's routes, the choice among them, the time
budget, and a whole problem's report.

    answer(family, question, model, options) -> Solution
    report(problem, build, answer, options) -> ProblemReport

``--route auto`` runs the exact route, and the numeric route where the exact one
cannot answer and every parameter has a value. One budget caps the run
(``budget.Allowance``): the model may take all of it (nothing is answered without
one), or half on auto with every value given (its T and V can then be left out, and
the numeric route needs the rest); each question gets what is left divided by the
questions still to come; and on auto, where the numeric route could answer, the exact
route gets half of its question's share and the numeric route the rest. Each runs
within its share (``budget.within``) and is timed.
Where a family can tell from the structure of the equations, in milliseconds, that the
exact route would answer only in part (the evident roots of transcendental equilibrium
equations), ``auto`` with every value given runs the numeric route at once: the route
is chosen by what the equations are, never by how long the exact route took, so a file
takes the same route on any machine.
"""

from __future__ import annotations

import importlib
import math
import time
from dataclasses import dataclass, replace
from typing import Callable

from rbdsolve.errors import NUMERIC_REMEDY, UnsolvedError
from rbdsolve.model.build import Model
from rbdsolve.problem.schema import Problem, Question, QuestionKind
from rbdsolve.report import steps as st
from rbdsolve.report.steps import ModelSummary, ProblemReport, Route, Solution
from rbdsolve.solvers.routes.budget import Allowance, OutOfTime, within
from rbdsolve.solvers.routes.checks import CheckFailed, Residuals, verify
from rbdsolve.solvers.lagrange.frames import frame_of, model_in_frame, solve_in_frame
from rbdsolve.solvers.routes.options import Options, RouteChoice
from rbdsolve.model.summary.scene import radian_warnings, swing_warnings, unused_warnings
from rbdsolve.model.summary.summary import coordinates_only, summarize_model
from rbdsolve.model.values.answers import valued
from rbdsolve.solvers.routes.needed import missing_for, missing_values, with_irrelevant_filled

Solver = Callable[[Question, Model, Options], Solution]  # a route, or a question's answer
Check = Callable[[Question, Model], "str | None"]  # why the exact route's answer would be partial, or None


Names = Callable[[Question, object, Model], tuple]  # (question, answers, model) -> tuple[Named, ...]


@dataclass(frozen=True)
class Family:
    """A solver family's routes: each a pure function (question, model, options) ->
    Solution; what its answers must satisfy, checked before they are printed
    (``checks.py``): a function (question, model, answers) -> residuals, or None;
    where the family has one, the check that reads from the structure of the equations
    whether the exact route would answer only in part (and why); and ``named``: which
    answers the worked solution prints under which name (report/numbers.py), for the
    numeric block and for grading."""

    exact: Solver
    numeric: Solver
    residuals: Residuals | None = None
    partial: Check | None = None
    named: Names | None = None


def later(module: str, function: str = "solve"):
    """A route whose module (``rbdsolve.solvers.<family>.<route>``) is imported when first
    asked: numpy, scipy and the numeric machinery stay out of a process that only takes
    the exact route. ``function``: the module's function to call (a family's ``named``)."""

    def solve(*args):
        return getattr(importlib.import_module(f"rbdsolve.solvers.{module}"), function)(*args)

    solve.__qualname__ = f"{module}.{function}"
    return solve


def later_residuals(module: str) -> Residuals:
    """A family's ``residuals`` (``rbdsolve.solvers.<family>.check``), imported when first asked."""

    def residuals(question: Question, model: Model, answers: object):
        return importlib.import_module(f"rbdsolve.solvers.{module}").residuals(question, model, answers)

    residuals.__qualname__ = f"{module}.residuals"
    return residuals


def checked(solver: Solver, residuals: Residuals | None) -> Solver:
    """The route, its answers checked (checks.verify) on the model it answered on (the
    model seen from a moving frame, for a question asked in one): CheckFailed where one
    fails."""
    if residuals is None:
        return solver

    def solve(question: Question, model: Model, options: Options) -> Solution:
        solution = solver(question, model, options)
        if solution.answers is not None:
            verify(residuals(question, model, solution.answers), model, (*model.q, *model.qd))
        return solution

    solve.__qualname__ = getattr(solver, "__qualname__", "solve")
    return solve


def later_check(module: str) -> Check:
    """A family's ``partial`` check (``rbdsolve.solvers.<module>.partial``), imported
    when first asked, like its routes."""

    def partial(question: Question, model: Model) -> str | None:
        return importlib.import_module(f"rbdsolve.solvers.{module}").partial(question, model)

    partial.__qualname__ = f"{module}.partial"
    return partial


def answer(family: Family, question: Question, model: Model, options: Options) -> Solution:
    """Run one question's solver on the route asked for, each route within its own time
    budget; an unanswerable question, or one past its budget, becomes a Solution with an
    error (exit code 1), not an exception, so the other questions still run. The
    answers' numbers, units and numeric block come from model/values/ in one call; the
    warnings follow the route's: the scene's (``scene.py``, on the questions it bears
    on), then those on answers without a number, then an estimate that is not finite."""
    start = time.perf_counter()
    solution = _routed(family, question, model, options)
    estimate, unsure = _finite_estimate(solution.error_estimate)
    named = None if family.named is None else lambda: family.named(question, solution.answers, model)
    found = valued(solution.answers, model, question.kind.value, named)
    swing = swing_warnings(model) if question.kind in USES_T and not model.instant else ()
    warnings = (*solution.warnings, *swing, *unused_warnings(model), *radian_warnings(model), *found.warnings,
                *unsure,
                *_not_for(question, solution.answers, model))
    return replace(solution, warnings=warnings, error_estimate=estimate, values=found.values, units=found.units,
                   numbers=found.lines, seconds=time.perf_counter() - start)


def _not_for(question: Question, answers: object, model: Model) -> tuple[str, ...]:
    """A warning where the question names the parameter its conditions are to be written
    in (``for: M``) and none of its critical values is in it: that parameter splits none
    of them over its whole range (a critical value there not positive for every value of
    the others: M_c = k L/(g sin α) − m/2), so another was taken; never silently. One of
    either sign is split only in its size where an answer exists
    (|Ω| ≥ Ω_c, conditions.by_size): a warning too where others split the rest."""
    name = getattr(question.options, "for_parameter", None)
    critical = getattr(answers, "critical", None)
    others = ", ".join(dict.fromkeys(c.parameter for c in critical or () if c.parameter != name))
    if name is None or not others:
        return ()
    if any(c.parameter == name for c in critical):  # some in it: one of either sign is split only as |Ω| ≥ Ω_c
        return () if model.symbols.parameters[name].is_positive else (
            f"for: {name}: not every condition here is written in {name}: some are in {others} (of either sign, "
            f"{name} is split only where an answer exists, |{name}| ≥ its critical value, not yet where a stability "
            "or a mode changes)",)
    return (f"for: {name}: no condition here is written in {name} (it is not in them, or it splits none of them "
            f"over its whole range for every value of the others: an assumption that keeps its critical value "
            f"positive, or values for the others, may let it); they are written in {others}",)


USES_T = frozenset({QuestionKind.EOM, QuestionKind.MODES, QuestionKind.IMPACT, QuestionKind.ENERGY,
                    QuestionKind.REACTIONS})


def _finite_estimate(estimate: float | None) -> tuple[float | None, tuple[str, ...]]:
    """``error_estimate`` is a number or None (docs/json.md): a route whose estimate is not
    finite (a singular matrix in it) gives none, and a warning says so, rather than an
    infinity that strict JSON cannot hold. The estimate to keep, and that warning."""
    if estimate is None or math.isfinite(estimate):
        return estimate, ()
    return None, (f"no error estimate: the route's estimate is not finite ({estimate}), e.g. a singular Hessian "
                  "where the equilibria form a continuum",)


def _routed(family: Family, question: Question, model: Model, options: Options) -> Solution:
    """The routes' Solution (``_route_choice``); an answer that fails its check is not
    printed and no other route is tried: the question is unanswered, its error says
    what failed (a bug in rbdsolve)."""
    try:
        return _route_choice(family, question, model, options)
    except CheckFailed as exc:
        return _failed(question, exc.route, str(exc))


def _route_choice(family: Family, question: Question, model: Model, options: Options) -> Solution:
    """exact, numeric, or auto: exact, and numeric where exact cannot answer and no
    parameter lacks a value. The question's share of the budget (``options.budget``) is
    the route's; on auto, where the numeric route could follow, the exact route gets
    half of it and the numeric route what is left. The Solution's route is the route
    that ran last; when both fail, its error gives both routes' reasons."""
    filled = with_irrelevant_filled(model, question) if options.route is not RouteChoice.EXACT else model
    exact_route, numeric_route = checked(family.exact, family.residuals), checked(family.numeric, family.residuals)
    if options.route is RouteChoice.NUMERIC:
        return _attempt(Route.NUMERIC, numeric_route, question, filled, options)
    chosen = _numeric_first(family, numeric_route, question, model, filled, options)
    if chosen is not None:
        return chosen
    share = Allowance(options.budget)
    missing = missing_for(model, question, _solved_for(question))
    fallback = options.route is RouteChoice.AUTO and not missing
    exact = _attempt(Route.EXACT, exact_route, question, model,
                     replace(options, budget=share.share(2)) if fallback else options)
    if not fallback or exact.solved:
        return _naming(exact, missing)
    solution = _attempt(Route.NUMERIC, numeric_route, question, filled, replace(options, budget=share.left()),
                        " (numeric route)")
    if not solution.solved:
        return replace(solution, error=_both_failed(exact.error, solution.error))
    reason = exact.error.removesuffix(f"; {exact.remedy}")  # the numeric route has answered: no remedy needed
    note = f"the exact route could not answer ({reason}); these are the numeric route's answers"
    return replace(solution, warnings=(note, *solution.warnings))


def _naming(exact: Solution, missing: tuple[str, ...]) -> Solution:
    """The exact route's failure, its remedy ("give values for the parameters to solve
    it numerically") naming the parameters that lack one: a rod on a side spring with
    only m open was told to give values for the parameters it had."""
    if exact.solved or not missing or exact.remedy != NUMERIC_REMEDY:
        return exact
    named = f"give {', '.join(missing)} a value ('values:' in the file, or --set NAME=VALUE) to solve it numerically"
    return replace(exact, error=exact.error.removesuffix(NUMERIC_REMEDY) + named, remedy=named)


def _numeric_first(family: Family, numeric_route: Solver, question: Question, model: Model, filled: Model,
                   options: Options):
    """On ``auto`` with every value given, the numeric route's Solution where the
    structure shows the exact route would answer only in part; None otherwise, or where
    the numeric route cannot answer (the exact route's part is then better than none)."""
    if options.route is not RouteChoice.AUTO or family.partial is None:
        return None
    if missing_for(model, question, _solved_for(question)):
        return None
    why = partial_reason(family.partial, question, model, options)
    if why is None:
        return None
    solution = _attempt(Route.NUMERIC, numeric_route, question, filled, options, " (numeric route)")
    if not solution.solved:
        return None
    note = (f"the exact route would answer only in part: {why}; these are the numeric route's answers, the "
            "route chosen from the structure of the equations")
    return replace(solution, warnings=(note, *solution.warnings))


def partial_reason(check: Check, question: Question, model: Model, options: Options) -> str | None:
    """The family's check, on the model as the question sees it (in its frame), within
    the budget; a check that cannot decide says nothing."""
    try:
        with within(options.budget, f"'{question.kind.value}' (its structure)"):
            return check(question, model if frame_of(question) is None else model_in_frame(question, model))
    except (UnsolvedError, OutOfTime):
        return None


def _both_failed(exact: str, numeric: str) -> str:
    """Why neither route answered: one reason said once where both give it (a scene
    that depends on time is refused by both alike), else each route's."""
    if exact == numeric:
        return f"{exact} (the exact and the numeric route alike)"
    return f"the exact route could not answer ({exact}); nor could the numeric route ({numeric})"


def _solved_for(question: Question) -> tuple[str, ...]:
    """The parameters a question solves for (steady_motion's ``solve_for: theta``): the
    numeric route needs no value for them."""
    return tuple(sorted({n for e in getattr(question.options, "solve_for", ()) for n in e.names()}))


def _attempt(route: Route, solver, question: Question, model: Model, options: Options, label: str = "") -> Solution:
    """The solver's Solution within the budget, or a Solution on ``route`` with the
    reason it could not answer."""
    try:
        return _run(solver, question, model, options, label)
    except CheckFailed as exc:
        raise CheckFailed(str(exc), route) from None
    except UnsolvedError as exc:
        return _failed(question, route, str(exc), exc.remedy)
    except OutOfTime as exc:
        return _failed(question, route, str(exc))


def _failed(question: Question, route: Route, error: str, remedy: str = "") -> Solution:
    return Solution(question.kind.value, route, None, (), error=error, remedy=remedy)


def _run(solver, question: Question, model: Model, options: Options, route: str = "") -> Solution:
    with within(options.budget, f"'{question.kind.value}'{route}", options.budget_total):
        if frame_of(question) is None:
            return solver(question, model, options)
        return solve_in_frame(solver, question, model, options)


def report(problem: Problem, build: Callable[[], Model], answer: Solver, options: Options) -> ProblemReport:
    """The model section (T, V, the parameter values), then each question, all within
    the run's one budget, each stage within its share of what is left (module
    docstring). A model past its share is an UnsolvedError for the whole file (exit
    code 1), said in one line, except on auto with every value given when only the
    expansion of T and V ran out: the section then shows the coordinates only, as on
    the numeric route, and says why."""
    run = Allowance(options.budget)
    total = options.budget if options.budget_total is None else options.budget_total
    questions = problem.questions
    model = None  # set once built: only the summary is left then
    _stage(options, "the model (T and V)")
    try:
        with within(run.share(2) if _numeric_may_follow(problem, options) else run.left(), "the model (T and V)",
                    total):
            model = build()
            summary = coordinates_only(model) if options.route is RouteChoice.NUMERIC else summarize_model(model)
    except OutOfTime as exc:
        if model is None or options.route is not RouteChoice.AUTO or missing_values(model):
            raise UnsolvedError(f"{problem.file}: {exc}") from None
        summary = _coordinates_instead(model, exc)
    solutions = tuple(_staged(answer, q, model, replace(options, budget=run.share(len(questions) - i + 1),
                                                        budget_total=total),
                              f"question {i} of {len(questions)}: {q.kind.value}")
                      for i, q in enumerate(questions, start=1))
    values = {str(k): float(v) for k, v in model.values.items()}
    symbols = tuple(p.name for p in problem.parameters) + problem.unknowns
    units = _units(model, values)
    angles = problem.angle_values().intersection(values)
    return ProblemReport(problem.file, problem.title, problem.source, problem.statement,
                         summary, solutions, values, symbols, units, angles)


def _units(model: Model, values: dict[str, float]) -> dict[str, str]:
    """The SI unit of each parameter with a value; without values there are none to
    give, and the units' machinery is not loaded (model/values/units.py)."""
    if not values:
        return {}
    from rbdsolve.model.values.units import parameter_units

    return {k: u for k, u in parameter_units(model).items() if k in values}


def _numeric_may_follow(problem: Problem, options: Options) -> bool:
    """On auto, does every parameter have a value (the file's or given on the command
    line: ``Problem.with_values``), so that the numeric route may answer where the exact
    one cannot?"""
    given = {name for name, _ in problem.values}
    return options.route is RouteChoice.AUTO and all(p.name in given for p in problem.parameters)


def _stage(options: Options, what: str) -> None:
    if options.on_stage is not None:
        options.on_stage(what)


def _staged(answer: Solver, question: Question, model: Model, options: Options, what: str) -> Solution:
    _stage(options, what)
    return answer(question, model, options)


def _coordinates_instead(model: Model, exc: OutOfTime) -> ModelSummary:
    """The numeric route's model section, with a note that T and V ran out of time."""
    summary = coordinates_only(model)
    why = st.note(f"warning: {exc}; T and V are not expanded, as on the numeric route "
                  "(every parameter has a value)")
    return replace(summary, steps=(why, *summary.steps))
