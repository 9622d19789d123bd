"""The momentum integrals of cyclic coordinates, which with the energy integral fix the
rates of a scene with one coordinate left.

A coordinate c is cyclic when the Lagrangian L = T − V holds its rate ċ but not c
itself (a cart's position x on a smooth floor); Lagrange's equation for it then reads
d/dt ∂L/∂ċ = 0, so its momentum

    p_c = ∂L/∂ċ = ∂T/∂ċ

is constant along every motion, its value that at the start (0 when released from
rest). T is quadratic in the rates, so the p_c are linear in them: A ċ + b = p_c(start),
with A = ∂²T/∂ċ∂ċ, b the part holding the other rate. Where every coordinate but one, s,
is cyclic, each ċ is solved from them in terms of q and ṡ, and the energy integral
h(q, ṡ, ċ) = h₀ becomes one equation for ṡ alone (Routh's reduction: Goldstein,
Classical Mechanics, ch. 8.3; Landau & Lifshitz, Mechanics, §41):

    a₂(q) ṡ² + a₀(q) = h₀,   so   ṡ² = (h₀ − a₀)/a₂.

For T = T₂ the part linear in ṡ cancels (with ċ = A⁻¹(p − M_cs ṡ), T = ½ (M_ss − M_sc A⁻¹ M_cs) ṡ²
+ ½ pᵀ A⁻¹ p); where it does not (Jacobi's integral with terms of T linear in the
rates), ṡ is a root of a quadratic and no reduction is offered. A scene with contacts
kept as constraints (rolling on a plane in 3D), or with a turning frame's Coriolis terms,
is not reduced: its momenta are not those of L alone.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from rbdsolve.form.display import Relation
from rbdsolve.form.printers import unicode_name
from rbdsolve.form.tidy import by_monomials, tidy
from rbdsolve.model.build import Model
from rbdsolve.model.derivative import derivative
from rbdsolve.report import steps as st
from rbdsolve.solvers.lagrange.accelerations import clean_fraction
from rbdsolve.solvers.lagrange.energy_integral import EnergyIntegral


@dataclass(frozen=True)
class Reduction:
    """The momentum integrals of the cyclic coordinates and what they leave: the one
    coordinate ``kept`` (an index into the model's coordinates), each cyclic rate in
    terms of q and its rate, and its rate squared as a function of q."""

    kept: int
    cyclic: tuple[int, ...]
    momenta: tuple[sp.Expr, ...]  # p_c = ∂T/∂ċ, functions of the state
    start: tuple[sp.Expr, ...]  # each p_c at the start state: its constant value
    rates: tuple[sp.Expr, ...]  # each ċ in terms of q and the kept coordinate's rate
    rate_squared: sp.Expr  # the kept coordinate's q̇² as a function of q


def cyclic_coordinates(model: Model, e: EnergyIntegral) -> tuple[int, ...]:
    """The indices of the coordinates L = T − V does not hold (their rates it does)."""
    L = e.T - e.V
    return tuple(k for k, (q, qd) in enumerate(zip(model.q, model.qd)) if not L.has(q) and L.has(qd))


def reduce(model: Model, e: EnergyIntegral, start: dict[sp.Symbol, sp.Expr]) -> Reduction | str:
    """The reduction where every coordinate but one is cyclic, or why there is none (a
    sentence that follows "the energy integral is one equation for several rates: ")."""
    if model.plane_contacts or model.gyroscopic:
        return "its rolling contacts (or the turning frame) make no momentum constant by itself"
    cyclic = cyclic_coordinates(model, e)
    kept = [k for k in range(len(model.q)) if k not in cyclic]
    if len(kept) != 1:
        names = model.coordinate_names()
        if not cyclic:
            return f"no coordinate is cyclic (L holds each of {', '.join(names)}), so no momentum is constant"
        return (f"{len(kept)} coordinates ({', '.join(names[k] for k in kept)}) are not cyclic (L holds them), "
                "so the momentum integrals of the others do not fix every rate")
    s, cd = model.qd[kept[0]], [model.qd[k] for k in cyclic]
    momenta = [derivative(e.T, x) for x in cd]
    A = sp.Matrix(len(cd), len(cd), lambda i, j: derivative(momenta[i], cd[j]))
    if sp.simplify(A.det()) == 0:
        return "the momenta of the cyclic coordinates do not fix their rates (∂²T/∂ċ² is singular)"
    values = tuple(tidy(sp.simplify(p.xreplace(start))) for p in momenta)
    b = sp.Matrix(momenta).xreplace({x: 0 for x in cd})
    rates = tuple(clean_fraction(x) for x in A.LUsolve(sp.Matrix(values) - b))
    h = sp.expand(e.h.xreplace(dict(zip(cd, rates))))
    a2, a1, a0 = (h.coeff(s, n) for n in (2, 1, 0))
    if sp.simplify(a1) != 0:
        return "with the momenta put in, the integral holds the rate itself, not only its square"
    rate_squared = clean_fraction((e.start - a0) / a2)
    return Reduction(kept[0], tuple(cyclic), tuple(map(tidy, momenta)), values, rates, rate_squared)


def momentum_step(model: Model, r: Reduction):
    """"x is cyclic …: p_x = ∂L/∂ẋ = … = 0, so ẋ = …", as an exam reduces it."""
    names = model.coordinate_names()
    one = len(r.cyclic) == 1
    which = ", ".join(unicode_name(names[k]) for k in r.cyclic)
    momenta = [Relation(sp.Symbol(f"p_{names[k]}"), model.to_time(by_monomials(p, list(model.qd))), more=(v,))
               for k, p, v in zip(r.cyclic, r.momenta, r.start)]
    rates = [Relation(model.to_time(model.qd[k]), model.to_time(x)) for k, x in zip(r.cyclic, r.rates)]
    return st.equation(f"{which} {'is' if one else 'are'} cyclic (L = T − V holds {'its rate' if one else 'their rates'}"
                       f", not {'itself' if one else 'them'}), so {'its momentum' if one else 'each momentum'} "
                       "p = ∂L/∂q̇ is constant along the motion, its value at the start; solved for the rate"
                       f"{'' if one else 's'}:", *momenta, *rates)
