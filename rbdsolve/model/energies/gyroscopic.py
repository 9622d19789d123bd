"""The Lagrangian by its degree in the rates: the gyroscopic terms of a spinning or
turning scene.

With no t in L (a top spun at a constant rate about its axis, a scene seen from a
frame that turns with it), T splits into its parts of degree 2, 1 and 0 in q̇,

    L = T₂ + L₁ − (V − T₀),   T₂ = ½ q̇ᵀ M(q) q̇,   L₁ = Σ cᵢ(q) q̇ᵢ,

L₁ holding T₁ and the terms linear in the rates that a moving frame adds (the Coriolis
terms m v'·(ω × r') and ω_Fᵀ J' ω', ``Model.gyroscopic``). Lagrange's equations then
read M q̈ + G q̇ + ∂(V − T₀)/∂q + … = 0 with the skew gyroscopic matrix

    Gᵢⱼ = ∂cᵢ/∂qⱼ − ∂cⱼ/∂qᵢ

(d/dt ∂L₁/∂q̇ᵢ − ∂L₁/∂qᵢ = Σⱼ (∂cᵢ/∂qⱼ − ∂cⱼ/∂qᵢ) q̇ⱼ; Goldstein, ch. 6; Meirovitch,
Methods of Analytical Dynamics, ch. 6.6), so a steady state is an equilibrium of
V − T₀ and its small motions follow M ü + G u̇ + K u = 0, K the Hessian of V − T₀.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from rbdsolve.form.tidy import collect_in, tidy
from rbdsolve.model.build import Model
from rbdsolve.model.derivative import derivative
from rbdsolve.model.energies.energy import kinetic_energy, memoized, potential_energy


@dataclass(frozen=True)
class RateParts:
    """L by degree in the rates: T₂, L₁ = Σ cᵢ q̇ᵢ (its coefficients cᵢ) and T₀; V apart."""

    T2: sp.Expr
    coefficients: tuple[sp.Expr, ...]  # cᵢ(q), one per coordinate
    T0: sp.Expr


@memoized
def rate_parts(model: Model) -> RateParts:
    """T₂, the cᵢ of L₁ = T₁ + Σ the model's gyroscopic terms, and T₀."""
    T = kinetic_energy(model).total + sum((x.value for x in model.gyroscopic), sp.Integer(0))
    qd = list(model.qd)
    T2, c, T0 = sp.Integer(0), [sp.Integer(0)] * len(qd), sp.Integer(0)
    for mono, coefficient in collect_in(T, qd).items():
        degree = sp.Poly(mono, *qd).total_degree() if mono != 1 else 0
        if degree == 2:
            T2 += mono * coefficient
        elif degree == 1:
            k = qd.index(mono)
            c[k] = tidy(c[k] + coefficient)
        else:
            T0 += coefficient
    return RateParts(T2, tuple(c), tidy(T0))


def has_gyroscopic_terms(model: Model) -> bool:
    """Does L hold terms linear in the rates (a spin, a turning frame's Coriolis terms)?"""
    return any(c != 0 for c in rate_parts(model).coefficients)


def gyroscopic_matrix(model: Model, at: dict | None = None) -> sp.Matrix:
    """G with Gᵢⱼ = ∂cᵢ/∂qⱼ − ∂cⱼ/∂qᵢ, at the configuration ``at`` if given."""
    c, q = rate_parts(model).coefficients, model.q
    n = len(q)
    G = sp.Matrix(n, n, lambda i, j: derivative(c[i], q[j]) - derivative(c[j], q[i]))
    return (G.xreplace(at) if at else G).applyfunc(tidy)


def effective_potential(model: Model) -> sp.Expr:
    """V − T₀: the potential whose equilibria are the steady states, and whose Hessian is K."""
    return tidy(potential_energy(model).total - rate_parts(model).T0)
