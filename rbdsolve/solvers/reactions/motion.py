"""Along the motion released from rest: the speed by conservation of energy, the forces
as functions of the coordinate, and the contact limits.

With one coordinate q and a Lagrangian that holds no t, the energy integral is
constant (solvers/lagrange/energy_integral.py; T + V where T = ½ M q̇²):

    ½ M(q) q̇² + V(q) = V(q₀)   ⇒   q̇² = 2 (V(q₀) − V(q)) / M(q),

and every force found by Newton–Euler, a function of q and q̇² (the accelerations of a
planar body carry q̇ only squared), becomes a function of q alone; where a contact is
lost along it and the friction it needs are limits.py's.
"""

from __future__ import annotations

import sympy as sp

from rbdsolve.form.tidy import tidied_roots
from rbdsolve.model.build import Model
from rbdsolve.model.energies.energy import memoized
from rbdsolve.solvers.lagrange.accelerations import clean_fraction
from rbdsolve.solvers.lagrange.energy_integral import EnergyIntegral, energy_integral, not_conserved


def energy(model: Model, start: dict[sp.Symbol, sp.Expr]) -> EnergyIntegral | None:
    """q̇²(q) by the energy integral, or None where it does not apply (several
    coordinates, a Lagrangian that holds t)."""
    if len(model.q) != 1 or not_conserved(model) is not None:
        return None
    e = energy_integral(model, start)
    return e if e.rate_squared is not None else None


def along(value: sp.Expr, model: Model, e: EnergyIntegral) -> sp.Expr | None:
    """A force of q and q̇ as a function of q alone, q̇² from the energy (None: q̇ left)."""
    return _along(model, value, e)


@memoized  # a reactions question and the energy question's check on the way follow the same push
def _along(model: Model, value: sp.Expr, e: EnergyIntegral) -> sp.Expr | None:
    qd = model.qd[0]
    w = sp.Dummy("w")
    replaced = sp.expand(value).subs(qd**2, w)
    if replaced.has(qd):
        return None
    return clean_fraction(tidied_roots(replaced.xreplace({w: e.rate_squared})))
