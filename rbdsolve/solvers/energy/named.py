"""The names the energy question's worked solution prints its answers by
(report/numbers.py): the integral's value at the start, h, and at the configuration
asked: q̇², the rate |q̇| and each point's speed v_P, and the critical values of where
it is reached (ω₀,c)."""

from __future__ import annotations

import sympy as sp

from rbdsolve.model.build import Model
from rbdsolve.report.numbers import Named
from rbdsolve.solvers.lagrange.energy_integral import energy_constant
from rbdsolve.solvers.routes.naming import coordinate, criticals


def named(question, answers, model: Model) -> tuple[Named, ...]:
    there = getattr(answers, "there", answers)  # the numeric route keeps them at the top
    if there is None:
        return (Named(("start",), energy_constant(model)),)
    path = ("there",) if hasattr(answers, "there") else ()
    group = "At the configuration asked"
    out = [Named(("start",), energy_constant(model))]
    out += [Named((*path, "rate_squared", k), coordinate(model, f"dot({k})") ** 2, group) for k in there.rate_squared]
    out += [Named((*path, "rate", k), coordinate(model, f"dot({k})"), group) for k in there.rate]
    out += [Named((*path, "speed", p), sp.Symbol(f"v_{p}"), group) for p in there.speed]
    return tuple(out + criticals(("critical",), getattr(answers, "critical", ())))
