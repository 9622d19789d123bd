"""YAML text -> Problem: located nodes, a declarative schema and safe expressions.

Nothing in this package imports sympy, so ``rbdsolve check`` stays fast.
"""

from rbdsolve.problem.loader import load_file, load_text
from rbdsolve.problem.schema import Problem

__all__ = ["Problem", "load_file", "load_text"]
