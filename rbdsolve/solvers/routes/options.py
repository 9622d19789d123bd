"""How to solve: the route a question takes and the options every route receives."""

from __future__ import annotations

from dataclasses import dataclass, field
from enum import Enum
from typing import Callable


class RouteChoice(Enum):
    """Which route a question takes: ``exact`` (sympy, rational arithmetic), ``numeric``
    (floating point: numpy and scipy, every parameter needs a value) or ``auto`` (exact,
    and numeric where the exact route cannot answer and the values allow it)."""

    EXACT = "exact"
    NUMERIC = "numeric"
    AUTO = "auto"


@dataclass(frozen=True)
class Options:
    """How to solve: the route, and the time budget in processor seconds for the whole
    run (None: none); each stage of it is given its share as ``budget``, with the run's
    whole budget as ``budget_total`` (solvers/routes/budget.py). What is solved, values
    from the command line included, is the problem's (``Problem.with_values``) or the
    model's (``Model.with_values``)."""

    route: RouteChoice = RouteChoice.AUTO
    budget: float | None = None
    budget_total: float | None = None  # the run's budget of which ``budget`` is a share (None: budget is the whole)
    # Told each stage as it starts ('the model (T and V)', 'question 2 of 3: modes'), for
    # a progress display: solvers never print, the CLI shows it (cli/progress.py).
    on_stage: Callable[[str], None] | None = field(default=None, compare=False, repr=False)
