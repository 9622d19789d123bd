"""The model section of a report: coordinates, T and V, term by term, as in the seed's
problem 1: T₁, T₂, then T = T₁ + T₂ with its common scale pulled out."""

from __future__ import annotations

import sympy as sp

from rbdsolve.form.arrange import arranged, subscript
from rbdsolve.form.display import Relation
from rbdsolve.form.printers import to_unicode, unicode_name
from rbdsolve.model.build import Model
from rbdsolve.problem.schema import CoordinateKind
from rbdsolve.model.energies.energy import Energy, kinetic_energy, mass_matrix, potential_energy
from rbdsolve.report import steps as st
from rbdsolve.report.steps import ModelSummary
from rbdsolve.model.summary.large_energy import (SCAN_TERMS, kinetic_from_matrix, kinetic_steps,
                                                  potential_steps, quadratic_products, terms)
from rbdsolve.model.summary.scene import scene_notes


def coordinates_only(model: Model) -> ModelSummary:
    """The model section of the numeric route: the coordinates; T and V are not
    expanded (the solvers take M and K at a configuration, not T and V in full)."""
    if not model.q:
        return ModelSummary((), None, None, ())
    q = sp.ImmutableMatrix([model.state.functions()])
    return ModelSummary(model.state.functions(), None, None,
                        (st.given("Generalized coordinates (T and V are not expanded on the numeric route):",
                                  Relation(sp.Symbol("q"), q)), *rolling_steps(model)))


KINETIC = "Kinetic energy, ½ m v·v + ½ ω·J ω per body (v and J at its centre of mass)"
POTENTIAL = "Potential energy, −m g·r per body in gravity and ½ k s² per spring of stretch s"
LOADED = ("Potential energy, −m g·r per body in gravity, ½ k s² per spring of stretch s, and the applied loads' "
          "(−F·r_P for a constant force at P, −M α for a constant couple turning a body by α)")


def summarize_model(model: Model) -> ModelSummary:
    if not model.q:
        return ModelSummary((), None, None, ())
    q = sp.ImmutableMatrix([model.state.functions()])
    steps = [st.given("Generalized coordinates:", Relation(sp.Symbol("q"), q)), *rolling_steps(model)]
    T, kinetic = _kinetic(model)
    steps += kinetic
    if model.instant:  # velocities at one instant: no positions, so no V
        return ModelSummary(model.state.functions(), model.to_time(T), None, tuple(steps))
    V = potential_energy(model)
    steps += _potential_steps(V, model)
    steps += _free_force_steps(model)
    steps += scene_notes(model)
    return ModelSummary(model.state.functions(), model.to_time(T), model.to_time(V.total), tuple(steps))


def _kinetic(model: Model) -> tuple[sp.Expr, list[st.Step]]:
    """T and its steps: body by body, or, past SCAN_TERMS products q̇ᵢq̇ⱼ, as ½ q̇ᵀ M(q) q̇
    (large_energy.py; T then built from M, not expanded and collected)."""
    products = quadratic_products(model)
    if products is not None and products > SCAN_TERMS:
        M = mass_matrix(model)
        return kinetic_from_matrix(M, model.qd), kinetic_steps(KINETIC, products, M, model)
    T = kinetic_energy(model)
    return T.total, _energy_steps(KINETIC, "T", T, model)


def _potential_steps(V: Energy, model: Model) -> list[st.Step]:
    """V term by term, or, past SCAN_TERMS terms in all (or twice that in its parts
    together: a chain's bodies each repeat the links above them), as ½ qᵀ K q or one sum."""
    text = LOADED if any(x.potential is not None for x in model.loads) else POTENTIAL
    if V.terms and (terms(V.total) > SCAN_TERMS or sum(terms(t.value) for t in V.terms) > 2 * SCAN_TERMS):
        return potential_steps(text, V, model)
    return _energy_steps(text, "V", V, model)


def _free_force_steps(model: Model) -> list[st.Step]:
    """The generalized forces of the loads without a potential (a force given as a
    function of t), Q_i = Σ F·∂v_P/∂q̇_i + M·∂ω/∂q̇_i: Lagrange's equations keep them."""
    free = [x for x in model.loads if x.potential is None]
    if not free:
        return []
    from rbdsolve.model.energies.loads import free_forces

    names = ", ".join(f"{x.kind} '{x.name}'" for x in free)
    return [st.definition(f"Generalized forces of the loads without a potential ({names}), from their virtual "
                          "work, Q_i = Σ F·∂v_P/∂q̇_i + M·∂ω/∂q̇_i (v_P the velocity of the body's point where F "
                          "acts):", *[Relation(sp.Symbol(f"Q_{n}"), model.to_time(Q))
                                      for n, Q in zip(model.coordinate_names(), free_forces(model))])]


def _wheel_steps(model: Model, c) -> list[st.Step]:
    """A pulley with mass turns with the string (its rim does not slip): its angle,
    ψ = ±l/R (model/constraints/strings.py, ``wheel_turn``)."""
    wheel = c.source.pulley.wheel
    if wheel is None:
        return []
    spec = model.problem.body(wheel)
    turn = model.to_time(model.symbols.scalar(spec.angle))
    return [st.equation(f"Pulley {wheel} turns with the string, its rim not slipping: its radius times ψ̇ is ±l̇, "
                        "the sign the way the string bends over it ⇒", Relation(sp.Symbol(f"psi_{wheel}"), turn))]


def rolling_steps(model: Model) -> list[st.Step]:
    """Each contact's rolling condition, as a worked solution writes it: the contact
    point's velocity is zero (or the moving surface's there), which relates the rates,
    and integrated from the reference configuration places the body (model/constraints/contacts.py)."""
    out = []
    for c in model.contacts:
        source = c.source
        if source.pulley is not None:
            pulley = source.pulley
            how = (f"over pulley '{pulley.wheel}', which it turns" if pulley.wheel is not None else
                   "over a light pulley" if pulley.over is not None else f"straight from its {pulley.side} side")
            out.append(st.equation(f"String at {c.name} ({pulley.drum} to {c.body}, {how}): "
                                   f"inextensible, so the hanging part lengthens as fast as the string leaves "
                                   f"{pulley.drum} at {c.name} (v_{c.name}·d, along the string) ⇒",
                                   Relation(c.lhs, c.rhs), Relation(c.dependent, c.integrated, lead="⇒")))
            out += _wheel_steps(model, c) + _implied_notes(c)
            continue
        surface = source.surface
        on = ("its string" if source.string else _edge(surface, model) if surface.body else f"the {surface.kind.value}")
        rest = (f"v_{c.name} equals the velocity of the surface's point at {c.name}" if c.moving_surface
                else f"v_{c.name} = 0")
        out.append(st.equation(f"Rolling without slipping at {c.name} ({c.body} on {on}): {rest} ⇒",
                               Relation(c.lhs, c.rhs),
                               Relation(c.dependent, c.integrated, lead="⇒")))
        out += _implied_notes(c) + _rolled_note(model, c)
    return out


def _rolled_note(model: Model, c) -> list[st.Step]:
    """A coordinate declared an angle that the rolling makes non-periodic (model/build.py
    ``_angles``): said, with what that changes."""
    declared = {qi: k for k, qi in zip(model.problem.coordinates, model.q)}
    k = declared.get(c.coordinate)
    if k is None or k.kind is not CoordinateKind.ANGLE or k.periodic is False or c.coordinate in model.angles:
        return []
    name = unicode_name(k.name)
    where = " and its equilibria are searched where the contact holds" if c.span is not None else ""
    return [st.note(f"{name} is declared an angle, but body '{c.body}' rolls by it: the arc it lays off enters the "
                    f"positions outside sin and cos, so the scene does not repeat after a turn of {name}. It is "
                    f"taken as an angle that does not repeat (periodic: false){where}")]


def _implied_notes(c) -> list[st.Step]:
    """What the contact's geometry needs of the parameters (R > r inside a circle), as
    the model assumes it (model/constraints/contacts.py)."""
    return [st.note(f"{a.implied_by[0].upper()}{a.implied_by[1:]}, so {a.source.text} (assumed in what follows)")
            for a in c.requires]


def _energy_steps(text: str, name: str, energy: Energy, model: Model) -> list[st.Step]:
    if not energy.terms:
        return [st.definition(text, Relation(sp.Symbol(name), sp.Integer(0)))]
    reading = model.reading()
    parts = [
        Relation(sp.Symbol(f"{name}_{i}"), arranged(term.value, reading))
        for i, term in enumerate(energy.terms, start=1)
    ]
    legend = ", ".join(f"{name}{subscript(i)} {term.name}" for i, term in enumerate(energy.terms, start=1))
    total = arranged(energy.total, reading)
    if len(parts) == 1:
        return [st.definition(f"{text}; {legend}.", Relation(sp.Symbol(name), total))]
    sum_name = sp.Add(*[p.lhs for p in parts], evaluate=False)
    return [
        st.definition(f"{text}; {legend}.", *parts),
        st.equation("", Relation(sp.Symbol(name), sum_name, more=(total,))),
    ]


def _edge(surface, model: Model) -> str:
    """A body's edge as read: "cart's rim", or for a circle at a radius given on it (edge
    ``axle``), which side: "the inside of cart's circle of radius R" (a track cut in a
    cart read as "cart's axle")."""
    if surface.edge != "axle" or surface.radius is None:
        return f"{surface.body}'s {surface.edge}"
    side = "the inside of " if surface.inside else ""
    return f"{side}{surface.body}'s circle of radius {to_unicode(model.symbols.scalar(surface.radius))}"
