"""Whether the contacts hold on the way to a configuration: the energy question's rate
at ``to`` (T + V = h with the contact's constraint kept) is the motion's only while every
contact pushes and every string pulls on the way there. A disk rolling off a drum from
θ₀ has, by Newton–Euler along the normal,

    N = m g cos θ − m (R + r) θ̇²,   θ̇² = 4 g (cos θ₀ − cos θ)/(3 (R + r)),

so N = m g (7 cos θ − 4 cos θ₀)/3 reaches zero at cos θ = 4 cos θ₀/7; past it the disk
leaves the drum and flies free, and q̇² from the constrained energy is not its motion.

Each push and tension of the scene's contacts and strings comes from Newton–Euler with
them as the only supports (balances.py, the accelerations from Lagrange's equations), as
a function of q alone through the energy integral (motion.py); at the parameter values,
its first zero between the start and ``to`` (first_zero.first_loss) gives a warning.
Where those supports do not hold the bodies by themselves (a pivot too, not a contact),
or a value is missing that does more than scale a push (a mass), nothing is said.
"""

from __future__ import annotations

from typing import Mapping

import sympy as sp

from rbdsolve.errors import UnsolvedError
from rbdsolve.form.printers import unicode_name
from rbdsolve.model.build import Model
from rbdsolve.solvers.eom.exact import general_accelerations
from rbdsolve.solvers.lagrange.energy_integral import EnergyIntegral
from rbdsolve.solvers.reactions.balances import contact_forces
from rbdsolve.solvers.reactions.first_zero import first_loss, unscaled
from rbdsolve.solvers.reactions.motion import along
from rbdsolve.solvers.reactions.supports import How


def lost_on_the_way(model: Model, start: Mapping[sp.Symbol, sp.Expr], to: sp.Expr, e: EnergyIntegral
                    ) -> tuple[str, ...]:
    """A warning per push (tension) that reaches zero between the start state ``start``
    and q = ``to``: the rates and speeds given there are not the motion's."""
    forces = _pushes(model, e)
    if not forces:
        return ()
    q, name = model.q[0], unicode_name(model.coordinate_names()[0])
    values = dict(model.values)
    try:
        a, b = (float(x.xreplace(values)) for x in (start[q], to))
    except (TypeError, ValueError):
        return ()
    out = []
    for symbol, (push, held_as) in forces.items():
        push = unscaled(push, values, q)  # a mass left open scales N: its zeros are where they are
        if push is None:
            continue
        where = first_loss(push, q, a, b)
        if where is None:
            continue
        lost, kept = (("the string goes slack", "keeps it taut") if held_as is How.STRING
                      else ("the contact is lost (the body leaves it)", "keeps the contact"))
        place = f"already at the start, {name} = {a:.6g}" if where == a else f"at {name} = {where:.6g}"
        out.append(f"{symbol.name} = 0 {place}, before the motion gets to {name} = {b:.6g}: past it {lost}, so the "
                   f"rates and speeds given there, from an energy integral that {kept}, are not the motion's")
    return tuple(out)


def _pushes(model: Model, e: EnergyIntegral) -> dict[sp.Symbol, tuple[sp.Expr, How]]:
    """Each contact's push and each string's tension as a function of q alone; empty
    where the scene has none, a value is missing, or they do not hold it by themselves."""
    if not model.contacts or len(model.q) != 1:
        return {}
    try:
        found = general_accelerations(model)
    except (UnsolvedError, ValueError, TypeError, ZeroDivisionError):
        return {}
    if found.solved is None or found.too_long:
        return {}
    solved = contact_forces(model, zip(model.qdd, found.solved))
    if solved is None:
        return {}
    supports, forces = solved
    out = {}
    for s in supports:
        for c in s.components:
            value = along(forces[c.symbol], model, e) if c.one_sided and c.symbol in forces else None
            if value is not None:
                out[c.symbol] = (value, s.how)
    return out
