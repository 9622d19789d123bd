"""The names the modes' worked solution prints its answers by (report/numbers.py): the
equilibrium (θ, φ), M and K, λᵢ, ωᵢ (with its period), γᵢ, the amplitudes aᵢ and the
critical values (Ω_c)."""

from __future__ import annotations

import sympy as sp

from rbdsolve.model.build import Model
from rbdsolve.report.numbers import Meaning, Named
from rbdsolve.report.numbers import Path
from rbdsolve.solvers.modes.answers import EachModesAnswers
from rbdsolve.solvers.modes.steps import mode_labels
from rbdsolve.solvers.modes.gyroscopic_steps import gyroscopic_labels
from rbdsolve.solvers.routes.naming import coordinate, criticals, state


def named(question, answers, model: Model) -> tuple[Named, ...]:
    if isinstance(answers, EachModesAnswers):
        return tuple(n for k, a in enumerate(answers.modes)
                     for n in _modes(a, model, ("modes", k), "" if len(answers.modes) == 1 else _heading(k, answers)))
    return tuple(_modes(answers, model))


def _heading(k: int, answers: EachModesAnswers) -> str:
    return f"About equilibrium {k + 1}" if not answers.skipped else f"About the {_ordinal(k + 1)} equilibrium answered"


def _ordinal(n: int) -> str:
    return {1: "first", 2: "second", 3: "third"}.get(n, f"{n}th")


def _modes(a, model: Model, path: Path = (), group: str = "") -> list[Named]:
    gyroscopic = hasattr(a, "G")  # M ü + G u̇ + K u = 0: the cyclic rates, G, no λ (gyroscopic_steps.py)
    labels = gyroscopic_labels(model) if gyroscopic else mode_labels(model)
    out = [Named((*path, "about"), state(model, a.about), group)]
    out += [Named((*path, "steady", k), coordinate(model, f"dot({k})"), group) for k in getattr(a, "steady", {})]
    out += [Named((*path, "momenta", k), sp.Symbol(f"p_{k}"), group) for k in getattr(a, "momenta", {})]
    out += [Named((*path, "M"), labels.symbol("mass_matrix"), group)]
    out += [Named((*path, "G"), labels.symbol("gyroscopic_matrix"), group)] if gyroscopic else []
    out += [Named((*path, "K"), labels.symbol("stiffness_matrix"), group)]
    eigenvalues = getattr(a, "eigenvalues", ())
    out += [Named((*path, "eigenvalues", i), labels.symbol("eigenvalue", i + 1), group)
            for i in range(len(eigenvalues))]
    shapes = getattr(a, "shapes", ())
    for i in range(max(len(eigenvalues), len(a.frequencies), len(getattr(a, "growth_rates", ())))):  # each mode
        if i < len(a.frequencies):
            out.append(Named((*path, "frequencies", i), labels.symbol("frequency", i + 1), group, Meaning.FREQUENCY))
        if i < len(getattr(a, "growth_rates", ())):
            out.append(Named((*path, "growth_rates", i), labels.symbol("growth_rate", i + 1), group))
        if i < len(shapes):
            out.append(Named((*path, "shapes", i), labels.symbol("amplitude", i + 1), group))
    out += _growth_where_it_holds(a, model, labels, path, group)
    return out + criticals((*path, "critical"), getattr(a, "critical", ()), group)


def _growth_where_it_holds(a, model: Model, labels, path: Path, group: str) -> list[Named]:
    """γ of the gyroscopic case that holds at the parameter values (a rotor on a sprung
    joint spun below its critical spin: γ = 1.81252 1/s), printed as its case is."""
    out = []
    for j, case in enumerate(getattr(a, "stability_cases", ())):
        when = case.when.xreplace(dict(model.values)) if model.values else case.when
        if case.growth_rate is not None and when is sp.true:
            out.append(Named((*path, "stability_cases", j, "growth_rate"), labels.symbol("growth_rate"), group))
    return out
