"""Kinetic and potential energy of a model, body by body.

T = Σ_bodies (T_translation + T_rotation),
    T_translation = ½ m v_G · v_G,   T_rotation = ½ ω · J_G ω     (König's theorem)
V = V_gravity + V_springs + V_loads,
    V_gravity = −Σ m g·r_G,   V_spring = ½ k s²  (s: the spring's stretch),
    V_load = −F·r_P for a constant force, … where an applied load has a potential (model/energies/loads.py)

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
from rbdsolve.model.derivative import derivative, matrix_derivative
from rbdsolve.model.state import State, t
from rbdsolve.form.tidy import collect_in, tidy, tidy_matrix


@dataclass(frozen=True)
class EnergyTerm:
    """One named contribution (a body's T, gravity on a body, a spring's V)."""

    name: str
    value: sp.Expr


@dataclass(frozen=True)
class Energy:
    """An energy term by term (a body's T, gravity on a body, a spring, a frame's
    inertial potential) and its tidied total."""

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
    """Compute once per model object, and per value of any further (hashable) arguments
    (solvers ask for T, V and ∂V/∂q repeatedly; a frame's seen model, a support's
    components, a condition's pieces are asked by a question and again by its check).
    Kept as long as the model lives; a computation that raises keeps nothing."""
    cache: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()

    @functools.wraps(compute)
    def wrapper(model: Model, *key):
        found = cache.setdefault(model, {})
        if key not in found:
            found[key] = compute(model, *key)
        return found[key]

    return wrapper


@memoized
def kinetic_energy(model: Model) -> Energy:
    """T body by body, each built first (``body_kinetic_energy``), then tidied as a
    quadratic form in the rates, and their tidied total."""
    built = [(b.name, body_kinetic_energy(b, model.state)) for b in model.bodies]
    terms = tuple(EnergyTerm(name, tidy_quadratic(T, model.qd)) for name, T in built)
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
    terms += [(f"{x.kind} {x.name}", x.potential) for x in model.loads if x.potential is not None and x.potential != 0]
    return terms


def tidy_quadratic(T: sp.Expr, qd: tuple[sp.Expr, ...]) -> sp.Expr:
    """T written as Σ c_ij q̇_i q̇_j with each coefficient tidied on its own."""
    return sp.Add(*[mono * coeff for mono, coeff in collect_in(T, list(qd)).items()])


@dataclass(frozen=True)
class BodyJacobians:
    """A body's v_G = J_v q̇ + v_t and ω = J_ω q̇ + ω_t: the Jacobians, its inertia J_G in
    scene axes, and whether it moves when every q̇ is 0 (v_t or ω_t ≠ 0: a driven
    frame, a given velocity)."""

    body: RigidBody
    J_v: sp.Matrix
    J_w: sp.Matrix
    J_G: sp.Matrix
    moves_at_rest: bool


@memoized
def jacobians(model: Model) -> tuple[BodyJacobians, ...]:
    """Each body's velocity Jacobians (once per model: M at every configuration, and the
    model section's M(q), use them)."""
    out = []
    for body in model.bodies:
        (J_v, v_t), (J_w, w_t) = _translation(body, model.state), _rotation(body, model.state)
        moves = any(x != sp.zeros(*x.shape) for x in (v_t, w_t))
        out.append(BodyJacobians(body, J_v, J_w, body.inertia_in_scene(), moves))
    return tuple(out)


def _translation(body: RigidBody, state: State) -> tuple[sp.Matrix, sp.Matrix]:
    """(J_v, v_t): from r_G(q, t) directly, J_v = ∂r_G/∂q and v_t = ∂r_G/∂t (cheaper
    than differentiating v_G = dr_G/dt again); from v_G where it is given."""
    r = body.position
    if r is not None and not r.has(*state.qd):
        return _jacobian(r, state.q), matrix_derivative(r, t)
    return _split(body.velocity(state), state)


def _jacobian(r: sp.Matrix, q: tuple[sp.Expr, ...]) -> sp.Matrix:
    """∂rᵢ/∂qⱼ = Σ ∂(term)/∂qⱼ over the terms of rᵢ that hold qⱼ: what Add's own
    derivative sums, less the terms it differentiates to zero. A chain's link k holds
    k terms, one per angle: each is differentiated once, not once per angle (n³ → n²)."""
    index = {qj: j for j, qj in enumerate(q)}
    J = sp.zeros(len(r), len(q))
    for i, r_i in enumerate(r):
        parts: dict[int, list[sp.Expr]] = {}
        for term in sp.Add.make_args(r_i):
            for qj in term.free_symbols & index.keys():
                parts.setdefault(index[qj], []).append(derivative(term, qj))
        for j, derivatives in parts.items():
            J[i, j] = sp.Add(*derivatives)
    return J


def _rotation(body: RigidBody, state: State) -> tuple[sp.Matrix, sp.Matrix]:
    """(J_ω, ω_t): for a planar angle α(q, t), ω = α̇ e_z, so J_ω's last row is ∂α/∂q."""
    angle = body.angle
    if body.given_angular_velocity is None and not body.turns_3d and angle is not None \
            and not angle.has(*state.qd):
        J = sp.zeros(3, len(state.q))
        J[2, :] = sp.Matrix([[derivative(angle, q) for q in state.q]])
        return J, sp.Matrix([0, 0, derivative(angle, t)])
    return _split(body.angular_velocity(state), state)


def _split(velocity: sp.Matrix, state: State) -> tuple[sp.Matrix, sp.Matrix]:
    """A velocity linear in q̇, J q̇ + v_t, as (J, v_t)."""
    return velocity.jacobian(state.qd), velocity.xreplace({qd: 0 for qd in state.qd})


LONG_ENTRY = 300  # operations: a half-disk's M at −asin(…) is 30 and reads better as it stands


def mass_matrix(model: Model, at: dict[sp.Expr, sp.Expr] | None = None) -> sp.Matrix:
    """M(q) = Σ (m J_vᵀ J_v + J_ωᵀ J_G J_ω), optionally evaluated at a configuration.

    Substituting the configuration into the Jacobians first keeps the work small: a
    modes question never builds M(q) for general q. Except at an angle written as
    acos(c) or asin(s) of the parameters: there cos² + sin² = c² + (1 − c²) is no longer
    seen as 1 (a rod's m l²/3 about its pivot came out as 2000 operations of c, which
    then cost the eigenvalues a minute); where an entry is that long, M(q) tidied for
    every q is put there instead, entry by entry where it is the shorter.
    """
    there = _assembled(model, at)
    if not at or not any(sp.sympify(v).has(sp.acos, sp.asin) for v in at.values()) or \
            all(sp.count_ops(x) <= LONG_ENTRY for x in there):
        return there
    general = _general_mass_matrix(model).xreplace(at)
    return sp.Matrix(there.rows, there.cols,
                     lambda i, j: min((there[i, j], tidy(general[i, j])), key=sp.count_ops))


@memoized
def _general_mass_matrix(model: Model) -> sp.Matrix:
    return _assembled(model, None)


def _assembled(model: Model, at: dict[sp.Expr, sp.Expr] | None) -> sp.Matrix:
    """M from the bodies' Jacobians, the configuration ``at`` put in them first."""
    n = len(model.q)
    terms: dict[tuple[int, int], list[sp.Expr]] = {(i, j): [] for i in range(n) for j in range(i, n)}
    for b in jacobians(model):
        J_v, J_w, J_G = b.J_v, b.J_w, b.J_G
        if at:
            J_v, J_w, J_G = (x.xreplace(at) for x in (J_v, J_w, J_G))
        _add_products(terms, b.body.mass, J_v, J_v)
        if any(x != 0 for x in J_w):
            _add_products(terms, sp.Integer(1), J_w, J_G * J_w)
    # each entry one sum over the bodies (no matrix of partial sums rebuilt per body);
    # M is symmetric: the upper triangle, mirrored
    return tidy_matrix(sp.Matrix(n, n, lambda i, j: sp.Add(*terms[(min(i, j), max(i, j))])))


def _add_products(terms: dict, factor: sp.Expr, A: sp.Matrix, B: sp.Matrix) -> None:
    """The terms of factor·(Aᵀ B)_ij, i ≤ j, skipping zero columns."""
    columns = [j for j in range(A.cols) if any(x != 0 for x in A[:, j])]
    b_columns = {j for j in range(B.cols) if any(x != 0 for x in B[:, j])}
    for i in columns:
        for j in (j for j in columns if j >= i and j in b_columns):
            terms[(i, j)] += [_product(factor, A[k, i], B[k, j]) for k in range(A.rows)
                              if A[k, i] != 0 and B[k, j] != 0]


@functools.lru_cache(maxsize=8192)
def _product(factor: sp.Expr, a: sp.Expr, b: sp.Expr) -> sp.Expr:
    """factor·a·b, made once: a chain's links share their Jacobians' columns (link k's
    ∂r/∂θⱼ is the same for every k > j), so M's n³/3 products are mostly repeats."""
    return factor * a * b


def stiffness_matrix(V: sp.Expr, q: tuple[sp.Expr, ...], at: dict[sp.Expr, sp.Expr]) -> sp.Matrix:
    """K = ∂²V/∂q∂q evaluated at the configuration ``at``."""
    return tidy_matrix(hessian(V, q).xreplace(at))


@functools.lru_cache(maxsize=64)
def hessian(V: sp.Expr, q: tuple[sp.Expr, ...]) -> sp.ImmutableMatrix:
    """∂²V/∂q_i∂q_j (cached: every equilibrium of a model uses the same one)."""
    grad = [derivative(V, qi) for qi in q]
    return sp.ImmutableMatrix(len(q), len(q), lambda i, j: derivative(grad[i], q[j]))
