"""A state of the motion a question is asked at, shared by ``eom``, ``reactions`` and
``energy``:

    eom: {from_rest: {theta: pi/2}}                        # q̈ just after release
    eom: {at: {theta: pi/2, dot(theta): 0}}                # every coordinate and rate

A rate is keyed as in expressions, ``dot(theta)``; the state is read by the one reader of
a state (``context.Reading.state``), which ``kinematics`` uses too.
"""

from __future__ import annotations

from rbdsolve.errors import InputError
from rbdsolve.problem.context import Reading
from rbdsolve.problem.instants import Instant
from rbdsolve.problem.yamlnodes import Map, Node


def instant(reading: Reading, opts: Map | None) -> Instant | None:
    """``at: {q: value, dot(q): value, …}`` (every one) or ``from_rest: {q: value, …}``."""
    if opts is None:
        return None
    at, rest = opts.get("at"), opts.get("from_rest")
    if at is not None and rest is not None:
        raise InputError("give the state with 'at:' (coordinates and rates) or 'from_rest:' (coordinates; "
                         "the rates zero), not both", rest.loc)
    if rest is not None:
        return Instant(reading.coordinate_values(rest, "a configuration released from rest", complete=True),
                       (), True, rest.loc)
    if at is None:
        return None
    return _state(reading, at)


def _state(reading: Reading, node: Node) -> Instant:
    """Every coordinate and every rate, read by the one reader of a state."""
    values = reading.state(node, "a state", (0, 1), complete=True,
                           hint=" (or give 'from_rest:' with the coordinates alone)")
    return Instant(tuple((v.coordinate, v.value) for v in values if v.order == 0),
                   tuple((v.coordinate, v.value) for v in values if v.order == 1), False, node.loc)
