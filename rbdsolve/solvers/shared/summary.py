"""The model section of a report: coordinates, T and V, term by term, as in the seed's
problem 1: T₁, T₂, then T = T₁ + T₂ with its common scale pulled out."""

from __future__ import annotations

import sympy as sp

from rbdsolve.form.arrange import subscript
from rbdsolve.form.display import Relation
from rbdsolve.model.build import Model
from rbdsolve.model.energy import Energy, kinetic_energy, potential_energy
from rbdsolve.report import steps as st
from rbdsolve.report.steps import ModelSummary
from rbdsolve.solvers.shared.present import present


def coordinates_only(model: Model) -> ModelSummary:
    """The model section of the numeric route: the coordinates; T and V are not
    expanded (the solvers take M and K at a configuration, not T and V in full)."""
    if not model.q:
        return ModelSummary((), None, None, ())
    q = sp.ImmutableMatrix([model.state.functions()])
    return ModelSummary(model.state.functions(), None, None,
                        (st.given("Generalized coordinates (T and V are not expanded on the numeric route):",
                                  Relation(sp.Symbol("q"), q)),))


def summarize_model(model: Model) -> ModelSummary:
    if not model.q:
        return ModelSummary((), None, None, ())
    T = kinetic_energy(model)
    q = sp.ImmutableMatrix([model.state.functions()])
    steps = [st.given("Generalized coordinates:", Relation(sp.Symbol("q"), q))]
    steps += _energy_steps("Kinetic energy, ½ m v·v + ½ ω·J ω per body (v and J at its centre of "
                           "mass)", "T", T, model)
    if model.instant:  # velocities at one instant: no positions, so no V
        return ModelSummary(model.state.functions(), model.to_time(T.total), None, tuple(steps))
    V = potential_energy(model)
    steps += _energy_steps("Potential energy, −m g·r per body in gravity and ½ k s² per spring of "
                           "stretch s", "V", V, model)
    steps += _unturned(model)
    return ModelSummary(model.state.functions(), model.to_time(T.total), model.to_time(V.total),
                        tuple(steps))


def _unturned(model: Model) -> list[st.Step]:
    """A body with rotational inertia that moves with an angle but has no ``angle`` does
    not turn, and its rotational energy is zero: say so, in case that was not meant."""
    out = []
    for body in model.bodies:
        moves = [n for q, n in zip(model.q, model.coordinate_names())
                 if q in model.angles and body.position.has(q)]
        if body.angle is None and not body.turns_3d and moves and body.inertia != sp.zeros(3, 3):
            out.append(st.note(f"Note: {body.name} has no 'angle', so it moves with {', '.join(moves)} "
                               "without turning (no rotational energy). If it turns, give its angle."))
    return out


def _energy_steps(text: str, name: str, energy: Energy, model: Model) -> list[st.Step]:
    if not energy.terms:
        return [st.definition(text, Relation(sp.Symbol(name), sp.Integer(0)))]
    parts = [
        Relation(sp.Symbol(f"{name}_{i}"), present(term.value, model))
        for i, term in enumerate(energy.terms, start=1)
    ]
    legend = ", ".join(f"{name}{subscript(i)} {term.name}" for i, term in enumerate(energy.terms, start=1))
    total = present(energy.total, model)
    if len(parts) == 1:
        return [st.definition(f"{text}; {legend}.", Relation(sp.Symbol(name), total))]
    sum_name = sp.Add(*[p.lhs for p in parts], evaluate=False)
    return [
        st.definition(f"{text}; {legend}.", *parts),
        st.equation("", Relation(sp.Symbol(name), sum_name, more=(total,))),
    ]
