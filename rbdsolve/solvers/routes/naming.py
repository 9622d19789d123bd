"""Names the worked solutions print, for the families' ``named`` (report/numbers.py):
a coordinate as θ, its rates θ̇ and θ̈, a configuration (θ, φ), a critical value Ω_c."""

from __future__ import annotations

import re
from typing import Iterable, Sequence

import sympy as sp

from rbdsolve.model.build import Model
from rbdsolve.model.state import t
from rbdsolve.report.numbers import Named
from rbdsolve.report.numbers import Path
from rbdsolve.solvers.conditions.present_conditions import critical_names

_RATE = re.compile(r"(d?dot)\((\w+)\)")


def coordinate(model: Model, key: str) -> sp.Basic:
    """θ for 'theta', θ̇ for 'dot(theta)', θ̈ for 'ddot(theta)' (a coordinate as a
    function of time, as the steps print it); a plain symbol for any other key."""
    rate = _RATE.fullmatch(key)
    name = rate.group(2) if rate else key
    names = model.coordinate_names()
    if name not in names:
        return sp.Symbol(key)
    q = model.state.functions()[names.index(name)]
    return sp.Derivative(q, t, 1 if rate.group(1) == "dot" else 2) if rate else q


def state(model: Model, keys: Iterable[str]) -> sp.Tuple:
    """(θ, φ): the names of a configuration's (or a state's) keys, in order."""
    return sp.Tuple(*[coordinate(model, k) for k in keys])


def per_coordinate(model: Model, path: Path, keys: Iterable[str], name, group: str = "", **more) -> list[Named]:
    """One Named per coordinate key under ``path``, each named ``name(q)`` from the
    coordinate as printed (I_θ, ẋ_f)."""
    return [Named((*path, k), name(k, coordinate(model, k)), group, **more) for k in keys]


def criticals(path: Path, critical: Sequence, group: str = "") -> list[Named]:
    """The critical values that the solution names (Ω_c, Ω_c1 …), at path[i].value; one
    that is another parameter or a number (r < R, θ < π/2) is printed in its condition.
    Without a heading of their own they go under 'Critical values', not under the last
    equilibrium's."""
    named = critical_names(critical)
    names = dict((id(c), name) for c, name in named)
    group = group or "Critical values"
    order = {id(c): k for k, (c, _) in enumerate(named)}  # the steps' order: k_c1 before k_c2
    return [Named((*path, i, "value"), names[id(c)], group)
            for i, c in sorted(enumerate(critical), key=lambda ic: order.get(id(ic[1]), 0)) if id(c) in names]
