"""Load and solve: the steps of ``rbdsolve solve`` for one problem (cli/batch.py's
``solve_source``: load, check the given values, solve_file), with its errors raised
as the located exceptions the CLI turns into exit codes instead of said and counted."""

from __future__ import annotations

import math
import os
from typing import Mapping

from rbdsolve.api.result import Result
from rbdsolve.errors import InputError, did_you_mean
from rbdsolve.problem import load_file
from rbdsolve.problem.data import load_data, load_string
from rbdsolve.problem.quantities.overrides import checked_values, given_values
from rbdsolve.problem.schema import Problem

ROUTES = ("auto", "exact", "numeric")
DEFAULT_BUDGET = 60.0  # processor seconds for the whole solve, as the CLI's --budget
MIN_BUDGET, MAX_BUDGET = 0.001, 1e6  # as the CLI's --budget: a timer's resolution; eleven days
SAID = "values[{!r}]"  # a value given in Python, as a message names it


def load(path: str | os.PathLike) -> Problem:
    """A problem file -> Problem (validated; nothing is solved)."""
    if not isinstance(path, (str, os.PathLike)):
        raise InputError(f"expected the path of a problem file, found {type(path).__name__}"
                         " (loads() reads YAML text, load_dict() a dict)")
    if isinstance(path, str) and "\n" in path:
        raise InputError("expected the path of a problem file, found text of several lines; "
                         "rbdsolve.loads(text) reads a problem's YAML text")
    return load_file(os.fspath(path))


def loads(text: str, name: str = "<string>") -> Problem:
    """A problem's YAML text -> Problem; messages name it ``name``."""
    return load_string(text, name)


def load_dict(data: Mapping, name: str = "<dict>") -> Problem:
    """A problem as Python data (what ``yaml.safe_load`` gives for a file) -> Problem."""
    return load_data(data, name)


def solve(problem: Problem | str | os.PathLike | Mapping, *, route: str = "auto",
          budget: float | None = DEFAULT_BUDGET, values: Mapping[str, object] | None = None) -> Result:
    """Solve every question of ``problem`` (a Problem, a file's path, or a dict), as
    ``rbdsolve solve --route ROUTE --budget SECONDS --set NAME=VALUE…`` does.

    ``values`` give parameters numbers (9.81, Fraction(1, 2), 'pi/6', '30 cm'); they
    override the file's. A question that cannot be answered is in the Result with its
    error (``Result.exit_code`` 1); bad input raises InputError (exit code 2)."""
    from rbdsolve.solvers import Options, RouteChoice, solve_file

    problem = _as_problem(problem)
    given = checked_values(given_values(values, SAID), problem, SAID)
    options = Options(budget=_budget(budget), route=RouteChoice(_route(route)))
    return Result(problem, solve_file(problem.with_values(given), options))


def _as_problem(problem: object) -> Problem:
    if isinstance(problem, Problem):
        return problem
    if isinstance(problem, Mapping):
        return load_dict(problem)
    return load(problem)


def _route(route: object) -> str:
    name = getattr(route, "value", route)  # a RouteChoice, or its name
    if name not in ROUTES:
        raise InputError(f"route: expected one of {', '.join(ROUTES)}, found {route!r}{did_you_mean(str(name), ROUTES)}")
    return name


def _budget(budget: object) -> float | None:
    if budget is None:
        return None
    if isinstance(budget, bool) or not isinstance(budget, (int, float)) or \
            not (math.isfinite(budget) and MIN_BUDGET <= budget <= MAX_BUDGET):
        raise InputError(f"budget: expected seconds from {MIN_BUDGET:g} to {MAX_BUDGET:g}, or None, found {budget!r}")
    return float(budget)
