"""The energy integral: what stays constant along a motion, and the speed it gives.

Where the Lagrangian L = T − V holds no t explicitly (no prescribed motion that does
work), Jacobi's integral is constant along every motion:

    h = Σ q̇ᵢ ∂L/∂q̇ᵢ − L = T₂ − T₀ + V,

with T = T₂ + T₁ + T₀ split by degree in q̇. A scene at rest in space (T = T₂) has
h = T + V: energy is conserved ("T + V is constant"). With one coordinate,
T₂ = ½ M(q) q̇², so from a start state (q₀, q̇₀)

    q̇² = 2 (h₀ + T₀(q) − V(q)) / M(q),      h₀ = h at the start,

the speed at every configuration the motion reaches. Ideal supports (pivots, smooth
guides, rolling without slip, inextensible strings) do no work, so they do not enter.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from rbdsolve.form.display import Relation
from rbdsolve.form.printers import unicode_name
from rbdsolve.form.tidy import tidy
from rbdsolve.model.build import Model
from rbdsolve.model.energies.energy import kinetic_energy, potential_energy
from rbdsolve.model.state import t
from rbdsolve.report import steps as st
from rbdsolve.solvers.lagrange.accelerations import clean_fraction
from rbdsolve.solvers.routes.labels import labels_for


@dataclass(frozen=True)
class EnergyIntegral:
    T: sp.Expr
    V: sp.Expr
    h: sp.Expr  # the constant: T + V where T = T₂, else T₂ − T₀ + V
    plain: bool  # h is T + V (T quadratic in the rates)
    start: sp.Expr  # h at the start state
    rate_squared: sp.Expr | None  # q̇² as a function of q (one coordinate), else None
    kept: int = 0  # the coordinate rate_squared is of (several: the one left by the momentum integrals)


def not_conserved(model: Model) -> str | None:
    """Why no energy integral holds, or None."""
    if model.instant:
        return "the scene is given at one instant (velocities, not positions): there is no motion to follow"
    free = [x for x in model.loads if x.potential is None]
    if free:
        what = ", ".join(f"{x.kind} '{x.name}'" for x in free)
        return (f"{what} has no potential (it changes with t, or its work depends on the path), so the work it "
                "does is not a difference of V along every motion, and T + V is not constant")
    L = kinetic_energy(model).total - potential_energy(model).total
    if L.has(t):
        return ("the Lagrangian depends on time explicitly (a prescribed motion or a moving support does work), "
                "so neither T + V nor Jacobi's integral is constant")
    return None


def energy_integral(model: Model, start: dict[sp.Symbol, sp.Expr]) -> EnergyIntegral:
    """h and h₀ at the start state (q and q̇ values), and q̇²(q) with one coordinate.
    Call only where ``not_conserved`` is None."""
    T, V = kinetic_energy(model).total, potential_energy(model).total
    rates = {qd: 0 for qd in model.qd}
    T0 = tidy(T.xreplace(rates))
    T2 = sp.expand(sum(qi * qj * sp.diff(T, qi, qj) for qi in model.qd for qj in model.qd) / 2)
    plain = sp.expand(T - T2) == 0
    h = T + V if plain else tidy(T2 - T0) + V
    h0 = sp.simplify(h.xreplace(start))
    rate_squared = None
    if len(model.q) == 1:
        M = sp.diff(T2, model.qd[0], 2)
        if not M.has(model.qd[0]):
            rate_squared = clean_fraction(2 * (h0 - (h - T2)) / M)
    return EnergyIntegral(T, V, h, plain, h0, rate_squared)


def energy_constant(model: Model) -> sp.Symbol:
    """The integral's name, h (H beside a parameter h: a hump's height)."""
    return labels_for(model, "energy_constant").symbol("energy_constant")


def energy_step(model: Model, e: EnergyIntegral, from_rest: bool):
    """The integral as the exam says it: "T + V = h is constant, h = V(q₀)", then q̇² (h is the
    name the numbers block gives its value: ``energy_constant``)."""
    h = unicode_name(energy_constant(model).name)
    if e.plain:
        which = "gravity, springs, the applied loads (V_F)" if model.loads else "gravity, springs"
        said = (f"Energy is conserved (the forces that do work have a potential: {which}; the "
                f"supports do none): T + V = {h} is constant, " + (f"{h} = V(q₀) at release from rest" if from_rest
                                                                   else f"{h} = its value at the state given"))
    else:
        said = (f"The Lagrangian holds no t, so Jacobi's integral {h} = T₂ − T₀ + V (T₂, T₀ the parts of T of "
                f"degree 2 and 0 in the rates) is constant, {h} = its value at the start")
    math = [Relation(model.to_time(e.h), model.to_time(e.start))]
    if e.rate_squared is not None:
        math.append(Relation(model.to_time(model.qd[e.kept]) ** 2, model.to_time(e.rate_squared)))
    so = ", and with the cyclic rates above put in, so" if len(model.q) > 1 else ", so"
    return st.result(said + (so if e.rate_squared is not None else ":"), *math)
