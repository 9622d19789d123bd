"""Which parameter a condition is solved for, and in what order the others are tried:
the one a question names (``for:``), the problem's only parameter without a value, then
by kind — a rate before a stiffness, a length, a mass (docs/format.md, "Conditions"):
exams ask "above which rate", then "how stiff a spring"."""

from __future__ import annotations

from fractions import Fraction

import sympy as sp

from rbdsolve.problem.quantities.dimensions import STIFFNESS, TORQUE
from rbdsolve.problem.quantities.quantity import LENGTH, MASS, Dimension

RATE_WORDS = ("omega", "spin", "rate", "speed", "angular")  # exams ask "above which rate"
STIFFNESS_WORDS = ("stiff", "spring", "torsion")  # then "how stiff a spring"
RATE = Dimension(time=Fraction(-1))


def asked(model, question) -> sp.Symbol | None:
    """The parameter a question's ``for:`` names, as a symbol (None: none named, or no
    question)."""
    name = getattr(getattr(question, "options", None), "for_parameter", None)
    return model.symbols.parameters[name] if name is not None else None


def candidates(f: sp.Expr, model, angles: dict, first: sp.Symbol | None = None) -> list[sp.Symbol]:
    """The positive parameters and the angles in f, the one the question is about
    first: ``first`` (a question's ``for:``), then the problem's only parameter without
    a value, then those without a value before those with one (a coin rolling round a
    circle of radius a left open: a > a_c, not r < r_c with r given), then by kind
    (``_kind``), each kind in the file's order."""
    order = [model.symbols.parameters[p.name] for p in model.problem.parameters]
    held = [p for p in order if p in f.free_symbols and (p.is_positive or p in angles)]
    open_ = [p for p in order if p not in model.values]
    lone = open_[0] if len(open_) == 1 else None
    kinds = {model.symbols.parameters[p.name]: _kind(p, model.problem.dimension_map())
             for p in model.problem.parameters}
    return sorted(held, key=lambda p: (p != first, p != lone, p in model.values, kinds[p]))


def _kind(parameter, dimensions: dict) -> int:
    """0 a rate or a spin, 1 a stiffness, 2 a length, 3 a mass, 4 any other (an
    acceleration, an angle): by its dimension where the file makes it known, else by
    its name and description (docs/format.md, "Conditions")."""
    dimension = dimensions.get(parameter.name)
    words = f"{parameter.name} {parameter.description}".lower()
    if dimension == RATE or any(w in words for w in RATE_WORDS):
        return 0
    if dimension in (STIFFNESS, TORQUE) or any(w in words for w in STIFFNESS_WORDS):
        return 1
    return {LENGTH: 2, MASS: 3}.get(dimension, 4)
