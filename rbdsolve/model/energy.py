"""Kinetic and potential energy of a model, body by body.

T = Σ_bodies (T_translation + T_rotation),
    T_translation = ½ m v_G · v_G,   T_rotation = ½ ω · J_G ω     (König's theorem)
V = V_gravity + V_springs,
    V_gravity = −Σ m g·r_G,   V_spring = ½ k s²  (s: the spring's stretch)

The mass matrix comes from the velocity Jacobians, never from differentiating T twice:
with v_G = J_v q̇ + v_t and ω = J_ω q̇ + ω_t (J_v = ∂r_G/∂q when r_G is known),

    M(q) = Σ_bodies (m J_vᵀ J_v + J_ωᵀ J_G J_ω)         (so T = ½ q̇ᵀ M q̇ + …)
"""

from __future__ import annotations

import functools
import weakref
from dataclasses import dataclass

import sympy as sp

from rbdsolve.model.build import Model, RigidBody
from rbdsolve.model.state import State
from rbdsolve.form.tidy import collect_in, tidy, tidy_matrix


@dataclass(frozen=True)
class EnergyTerm:
    """One named contribution (a body's T, gravity on a body, a spring's V)."""

    name: str
    value: sp.Expr


@dataclass(frozen=True)
class Energy:
    terms: tuple[EnergyTerm, ...]
    total: sp.Expr


def body_kinetic_energy(body: RigidBody, state: State) -> sp.Expr:
    """T_body = ½ m v_G·v_G + ½ ω·(R J_G Rᵀ) ω."""
    v = body.velocity(state)
    omega = body.angular_velocity(state)
    T_translation = body.mass * v.dot(v) / 2
    T_rotation = (omega.T * body.inertia_in_scene() * omega)[0, 0] / 2 if omega != sp.zeros(3, 1) else 0
    return T_translation + T_rotation


def memoized(compute):
    """Compute once per model object (solvers ask for T, V and ∂V/∂q repeatedly)."""
    cache: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()

    @functools.wraps(compute)
    def wrapper(model: Model):
        if model not in cache:
            cache[model] = compute(model)
        return cache[model]

    return wrapper


@memoized
def kinetic_energy(model: Model) -> Energy:
    terms = tuple(
        EnergyTerm(b.name, tidy_quadratic(body_kinetic_energy(b, model.state), model.qd))
        for b in model.bodies
    )
    return Energy(terms, tidy_quadratic(sum((x.value for x in terms), sp.Integer(0)), model.qd))


@memoized
def potential_energy(model: Model) -> Energy:
    terms = [EnergyTerm(name, tidy(value)) for name, value in potential_terms(model)]
    terms += model.inertial  # centrifugal and translation potentials in a moving frame
    return Energy(tuple(terms), tidy(sum((x.value for x in terms), sp.Integer(0))))


def potential_terms(model: Model) -> list[tuple[str, sp.Expr]]:
    """(name, value) of each gravity and spring term, as built (not tidied):
    V_gravity = −m g·r_G per body, V_spring = ½ k s² per spring."""
    terms = []
    if model.gravity is not None:
        for body in model.bodies:
            V_gravity = -body.mass * model.gravity.dot(body.position)
            if V_gravity != 0:
                terms.append((f"gravity on {body.name}", V_gravity))
    for spring in model.springs:
        terms.append((f"spring {spring.name}", spring.stiffness * spring.stretch**2 / 2))
    return terms


def tidy_quadratic(T: sp.Expr, qd: tuple[sp.Expr, ...]) -> sp.Expr:
    """T written as Σ c_ij q̇_i q̇_j with each coefficient tidied on its own."""
    return sp.Add(*[mono * coeff for mono, coeff in collect_in(T, list(qd)).items()])


def mass_matrix(model: Model, at: dict[sp.Expr, sp.Expr] | None = None) -> sp.Matrix:
    """M(q) = Σ (m J_vᵀ J_v + J_ωᵀ J_G J_ω), optionally evaluated at a configuration.

    Substituting the configuration into the Jacobians first keeps the work small: a
    modes question never builds M(q) for general q.
    """
    n = len(model.q)
    M = sp.zeros(n, n)
    for body in model.bodies:
        J_v = body.velocity(model.state).jacobian(model.qd)
        J_w = body.angular_velocity(model.state).jacobian(model.qd)
        J_G = body.inertia_in_scene()
        if at:
            J_v, J_w, J_G = (x.xreplace(at) for x in (J_v, J_w, J_G))
        M += body.mass * J_v.T * J_v + J_w.T * J_G * J_w
    return tidy_matrix(M)


def stiffness_matrix(V: sp.Expr, q: tuple[sp.Expr, ...], at: dict[sp.Expr, sp.Expr]) -> sp.Matrix:
    """K = ∂²V/∂q∂q evaluated at the configuration ``at``."""
    return tidy_matrix(hessian(V, q).xreplace(at))


@functools.lru_cache(maxsize=64)
def hessian(V: sp.Expr, q: tuple[sp.Expr, ...]) -> sp.ImmutableMatrix:
    """∂²V/∂q_i∂q_j (cached: every equilibrium of a model uses the same one)."""
    grad = [sp.diff(V, qi) for qi in q]
    return sp.ImmutableMatrix(len(q), len(q), lambda i, j: sp.diff(grad[i], q[j]))
