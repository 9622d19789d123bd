"""A state of the motion as a problem file gives it: every coordinate's value and
every rate's (``at:``), or the coordinates alone, released from rest (``from_rest:``);
and one entry of a state, a coordinate, its rate or its acceleration with its value
(problem/sections/states.py and context.Reading.state read them).
"""

from __future__ import annotations

from dataclasses import dataclass

from rbdsolve.errors import Location
from rbdsolve.problem.expr import Expr


@dataclass(frozen=True)
class Instant:
    """A state of the motion: every coordinate's value and every rate's (``at:``), or
    every coordinate's with the rates zero (``from_rest:``, just after release)."""

    coordinates: tuple[tuple[str, Expr], ...]  # coordinate -> value, in the coordinates' order
    rates: tuple[tuple[str, Expr], ...]  # coordinate -> its rate's value; () when from rest
    from_rest: bool
    loc: Location


@dataclass(frozen=True)
class StateValue:
    """One entry of a state ``at:``: a coordinate (order 0), its rate dot(q) (1) or its
    acceleration ddot(q) (2), and its constant value."""

    coordinate: str
    order: int
    value: Expr
