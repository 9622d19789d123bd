"""Along the motion released from rest: the speed by conservation of energy, the forces
as functions of the coordinate, and the contact limits.

With one coordinate q, no time in the scene and only conservative forces (gravity,
springs; ideal supports do no work), T + V is constant:

    ½ M(q) q̇² + V(q) = V(q₀)   ⇒   q̇² = 2 (V(q₀) − V(q)) / M(q),

and every force found by Newton–Euler, a function of q and q̇² (the accelerations of a
planar body carry q̇ only squared), becomes a function of q alone; where a contact is
lost along it and the friction it needs are limits.py's.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from rbdsolve.model.build import Model
from rbdsolve.model.energy import kinetic_energy, potential_energy
from rbdsolve.solvers.reactions.balances import clean


@dataclass(frozen=True)
class Energy:
    T: sp.Expr
    V: sp.Expr
    start: sp.Expr  # V(q₀)
    rate_squared: sp.Expr  # q̇² as a function of q


def energy(model: Model, start: dict[sp.Symbol, sp.Expr]) -> Energy | None:
    """q̇²(q) from T + V = V(q₀), or None where it does not apply (several coordinates,
    time in the scene, T not ½ M q̇²)."""
    if len(model.q) != 1 or model.depends_on_time():
        return None
    q, qd = model.q[0], model.qd[0]
    T, V = kinetic_energy(model).total, potential_energy(model).total
    M = sp.diff(T, qd, 2)
    if sp.expand(T - M * qd**2 / 2) != 0 or M.has(qd):
        return None
    V0 = sp.simplify(V.xreplace({q: start[q]}))
    return Energy(T, V, V0, clean(2 * (V0 - V) / M))


def along(value: sp.Expr, model: Model, e: Energy) -> sp.Expr | None:
    """A force of q and q̇ as a function of q alone, q̇² from the energy (None: q̇ left)."""
    qd = model.qd[0]
    w = sp.Dummy("w")
    replaced = sp.expand(value).subs(qd**2, w)
    if replaced.has(qd):
        return None
    return clean(replaced.xreplace({w: e.rate_squared}))
