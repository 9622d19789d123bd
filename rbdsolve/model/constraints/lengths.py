"""Lengths the geometry needs positive: a circle's radius that a body rolls on, the
radius a string is wound at, a hanging string's length, a body's dimensions.

A drum of radius −R under a rolling ring, a string of length 0, would be solved as if
nothing were wrong (θ̈ = g sin θ/(2(r − R)) for the ring). Each such length is refused,
located at its expression and naming it, when it is zero or negative

- by the parameters' signs (−R with R positive; 0; −1),
- at the file's values (R − 2 with R: 1), or
- under the file's assumptions, put in as substitutions (R − r with R < r: r = R + δ);

and where none of these decides it (R − r, nothing said), the contact assumes it
positive (an implied assumption, model/assumptions.py), so that values given later
(``--set``) that break it are refused, and sign decisions never take the other side.
"""

from __future__ import annotations

import functools
from typing import Mapping, TYPE_CHECKING

import sympy as sp

from rbdsolve.errors import InputError
from rbdsolve.model.assumptions import assumed, substitutions
from rbdsolve.model.symbols import Symbols, exact_number
from rbdsolve.problem.expr import Expr
from rbdsolve.problem.schema import Problem
from rbdsolve.problem.surfaces import SurfaceKind

if TYPE_CHECKING:
    from rbdsolve.problem.scene import Contact


def contact_lengths(c: Contact, problem: Problem, names: Symbols) -> tuple[tuple[sp.Expr, str], ...]:
    """What contact ``c`` needs positive (a circle's radius, a winding radius, a hanging
    length): an InputError where it cannot be; otherwise each length whose sign nothing
    decides, with why it must be positive, for the contact to assume (value > 0)."""
    lengths = [(c.radius, "the radius the string is wound at")]
    if c.surface.kind is SurfaceKind.CIRCLE:
        lengths.append((c.surface.radius, "the radius of the circle it rolls on"))
    if c.pulley is not None:
        lengths.append((c.pulley.length, "the hanging length of the string"))
    out, assumptions = [], _assumed(problem, names)
    for expr, what in lengths:
        if expr is not None:
            value = positive(expr, f"contact '{c.name}': {what}", problem, names, assumptions)
            if not value.is_positive and value.free_symbols:
                out.append((value, f"contact '{c.name}': {what} is positive"))
    return tuple(out)


def positive(expr: Expr, what: str, problem: Problem, names: Symbols, assumptions=None) -> sp.Expr:
    """``expr`` read, where it may be positive; an InputError located at it where the
    signs, the values or the assumptions (``_assumed``'s, made here if not given) make
    it zero or negative (module docstring)."""
    value = names.scalar(expr)
    why = nonpositive(value, _values(problem, names), assumptions or _assumed(problem, names))
    if why is not None:
        raise InputError(f"{what} must be positive, found {expr.text}{why}", expr.loc)
    return value


def nonpositive(value: sp.Expr, values: Mapping[sp.Symbol, sp.Expr], assumptions) -> str | None:
    """Why ``value`` is zero or negative ('' for a number, else how it is known), or
    None where that is not known (``assumptions`` called for their substitutions only
    when the signs and the values do not tell)."""
    if value.is_positive:  # the common case: a length r, l/2, R + r
        return None
    if value.is_nonpositive:
        return ", zero or negative for any values of the parameters" if value.free_symbols else ""
    at_values = value.xreplace(dict(values))
    if at_values.is_number and at_values.is_nonpositive:
        given = ", ".join(f"{k} = {v}" for k, v in values.items() if k in value.free_symbols)
        return f", which is {sp.sstr(at_values)} at the values given ({given})"
    if not value.free_symbols:
        return None
    substituted = assumptions()
    if substituted and sp.factor(value.xreplace(substituted)).is_nonpositive:
        return ", zero or negative under the file's assumptions"
    return None


def _values(problem: Problem, names: Symbols) -> dict[sp.Symbol, sp.Expr]:
    return {names.parameters[k]: exact_number(v) for k, v in problem.values}


def _assumed(problem: Problem, names: Symbols):
    """The file's assumptions as substitutions (R = r + δ under R > r; {} without any),
    made on the first call and kept for the next ones."""
    return functools.cache(lambda: substitutions(assumed(problem, names), names) if problem.assumptions else {})


def body_dimensions(problem: Problem, names: Symbols) -> None:
    """Each body's lengths (a radius, a length, a width …) positive at the file's values
    and under its assumptions too (their signs alone are checked as the body is built)."""
    if not problem.values and not problem.assumptions:
        return
    from rbdsolve.problem.sections.bodies import POSITIONS

    assumptions = _assumed(problem, names)
    for body in problem.bodies:
        for part in body.parts:
            for key, expr in part.dimensions:
                if key not in POSITIONS:
                    positive(expr, f"body '{body.name}': its {key}", problem, names, assumptions)
