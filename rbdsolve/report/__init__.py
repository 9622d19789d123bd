"""The vocabulary of a solution: typed steps, display values, answers and solutions.

Solvers build these as data; renderers turn them into text. Nothing here prints.
"""

from rbdsolve.report.math import Scaled, Terms
from rbdsolve.report.steps import (
    ProblemReport,
    Relation,
    Route,
    Solution,
    Step,
    StepKind,
)

__all__ = ["ProblemReport", "Relation", "Route", "Scaled", "Solution", "Step", "StepKind", "Terms"]
