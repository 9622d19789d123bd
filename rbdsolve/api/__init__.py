"""The Python API: the CLI's pipeline (problem/ → model/ → solvers/ → report/ →
render/) called from Python, for notebooks and scripts. docs/api.md is its manual.

    >>> import rbdsolve
    >>> result = rbdsolve.solve("problems/sg2150-2015-10-29/p1-two-rods.yaml")
    >>> result["modes"].answers.eigenvalues
    (24*g/(25*r), 2*g/r)

Everything here is re-exported by ``rbdsolve`` itself, imported when first used.
"""

from rbdsolve.api.result import Answer, Result
from rbdsolve.api.solving import load, load_dict, loads, solve
from rbdsolve.errors import ExitCode, InputError, InternalError, RbdError, UnsolvedError
from rbdsolve.problem.schema import Problem

__all__ = ["Answer", "ExitCode", "InputError", "InternalError", "Problem", "RbdError", "Result", "UnsolvedError",
           "load", "load_dict", "loads", "solve"]
