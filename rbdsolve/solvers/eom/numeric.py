"""Lagrange's equations with floating-point coefficients: the numeric route of ``eom``.

Every parameter value is put in as a binary64 float (53 bits) before anything is
differentiated, so L = T − V is a sum of products of floats and functions of q, q̇
and t, and

    E_i = d/dt(∂L/∂q̇_i) − ∂L/∂q_i                       (e.g. Goldstein, ch. 1)

is expanded term by term: plain arithmetic, without the exact route's simplification
of T. In a moving frame the frame's Lagrangian L' (model.frames) takes L's place.

Error: the same derivation is repeated in 50-digit arithmetic, and each equation's
coefficients are compared term by term; the estimate is the largest difference
relative to that equation's largest coefficient (a normwise relative error). A term
whose 50-digit coefficient is below 1e-30 of the largest is a cancellation that exact
arithmetic makes zero: it is dropped. The equations are then shown with each
coefficient of q̈ and q̇ tidied (sin² + cos² = 1, products to sums), and a term left
below NOISE × max(error, ε) of the largest by that rounding is dropped too.
A frame's equations are the scene's when every coefficient agrees within the errors.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from rbdsolve.form.tidy import collect_in
from rbdsolve.model.build import Model
from rbdsolve.model.energies.energy import body_kinetic_energy, potential_terms
from rbdsolve.model.energies.frames import frame_lagrangian, frame_motion
from rbdsolve.model.energies.loads import free_forces
from rbdsolve.model.state import t
from rbdsolve.problem.schema import Question
from rbdsolve.report.steps import Route, Solution
from rbdsolve.solvers.eom.answers import NumericEomAnswers, NumericFrameAnswers
from rbdsolve.solvers.eom.steps import numeric_steps
from rbdsolve.solvers.lagrange.frames import refuse_loads_in_frame
from rbdsolve.solvers.routes.options import Options
from rbdsolve.solvers.configuration.singular import eom_warnings
from rbdsolve.solvers.routes.needed import require_values

FLOAT_DIGITS = 15  # sympy Float of 15 digits carries 53 bits, a binary64's precision
REFERENCE_DIGITS = 50
CANCELLED = 1e-30  # relative size below which a 50-digit coefficient is a cancellation
EPS = 2.0**-52
NOISE = 100.0  # terms below NOISE × max(error, ε) of the largest are rounding noise


@dataclass(frozen=True)
class _Rounded:
    """Equations derived in floats, checked against 50 digits: {term: coefficient}."""

    terms: tuple[dict[sp.Expr, sp.Expr], ...]
    errors: tuple[float, ...]


def solve(question: Question, model: Model, options: Options) -> Solution:
    require_values(model, "the numeric route")
    scene = _derive(model, lambda digits: _scene_lagrangian(model, digits), lambda digits: _free_forces(model, digits))
    names = question.options.frames if question.options else ()
    frames = [_in_frame(model, model.problem.frame(name), scene) for name in names]
    errors = scene.errors + tuple(e for _, r in frames for e in r.errors)
    answers = NumericEomAnswers(_equations(scene, model), scene.errors,
                                tuple(answer for answer, _ in frames))
    return Solution("eom", Route.NUMERIC, answers, numeric_steps(answers, model, max(errors, default=0.0), REFERENCE_DIGITS),
                    warnings=eom_warnings(model), error_estimate=max(errors, default=0.0))


def _scene_lagrangian(model: Model, digits: int) -> sp.Expr:
    """L = T − V from the bodies, gravity and springs as built, values as floats."""
    T = sum((body_kinetic_energy(b, model.state) for b in model.bodies), sp.Integer(0))
    V = sum((value for _, value in potential_terms(model)), sp.Integer(0))
    V += sum((x.value for x in model.inertial), sp.Integer(0))
    return _floats(T - V, model, digits)


def _free_forces(model: Model, digits: int) -> tuple[sp.Expr, ...] | None:
    """Q_i of the loads without a potential (model/energies/loads.py), values as floats."""
    Q = free_forces(model)
    return None if Q is None else tuple(_floats(x, model, digits) for x in Q)


def _floats(expr: sp.Expr, model: Model, digits: int) -> sp.Expr:
    """The values put in: exactly inside functions (cos(3 t), not cos(3.0 t), so the
    two precisions' terms match), as floats of ``digits`` digits everywhere else."""
    inside = {f: f.xreplace(model.values) for f in expr.atoms(sp.Function)}
    return sp.expand(expr.xreplace(inside).xreplace({s: sp.Float(sp.N(v, digits + 5), digits) for s, v in model.values.items()}))


def _derive(model: Model, lagrangian, forces=lambda digits: None) -> _Rounded:
    """E_i (less Q_i, the generalized forces ``forces`` gives) in floats and in 50
    digits, compared term by term."""
    pairs = [_compare(a, b) for a, b in zip(_lagrange(model, lagrangian(FLOAT_DIGITS), forces(FLOAT_DIGITS)),
                                          _lagrange(model, lagrangian(REFERENCE_DIGITS), forces(REFERENCE_DIGITS)))]
    return _Rounded(tuple(t for t, _ in pairs), tuple(e for _, e in pairs))


def _lagrange(model: Model, L: sp.Expr, Q: tuple[sp.Expr, ...] | None = None) -> list[sp.Expr]:
    """E_i − Q_i, E_i from L's parts by their degree in q̇ (``_quadratic``), or by
    differentiating L whole where L is not a polynomial of degree ≤ 2 in q̇."""
    Q = Q or (0,) * len(model.q)
    parts = _quadratic(L, model.qd)
    if parts is None:
        return [sp.expand(model.state.d_dt(sp.diff(L, qd)) - sp.diff(L, q) - Qi)
                for q, qd, Qi in zip(model.q, model.qd, Q)]
    return [sp.expand(E - Qi) for E, Qi in zip(_from_parts(model, *parts), Q)]


def _quadratic(L: sp.Expr, qd: tuple) -> tuple[list[list[sp.Expr]], list[sp.Expr], sp.Expr] | None:
    """L = ½ q̇ᵀ M q̇ + bᵀ q̇ + L₀ read off L's expanded terms: (M, b, L₀), or None."""
    n, index = len(qd), {x: i for i, x in enumerate(qd)}
    M = [[sp.Integer(0)] * n for _ in range(n)]
    b, L0 = [sp.Integer(0)] * n, []
    for term in sp.Add.make_args(L):
        rates = [f for f in sp.Mul.make_args(term) if f.as_base_exp()[0] in index]
        powers = [(index[f.as_base_exp()[0]], f.as_base_exp()[1]) for f in rates]
        rest = sp.Mul(*[f for f in sp.Mul.make_args(term) if f not in rates])
        if rest.has(*qd) or sum(p for _, p in powers) > 2 or any(not p.is_Integer for _, p in powers):
            return None
        slots = [i for i, p in powers for _ in range(int(p))]
        if len(slots) == 2:
            i, j = sorted(slots)
            M[i][j] += 2 * rest if i == j else rest
            if i != j:
                M[j][i] += rest
        elif len(slots) == 1:
            b[slots[0]] += rest
        else:
            L0.append(rest)
    return M, b, sp.Add(*L0)


def _from_parts(model: Model, M, b, L0) -> list[sp.Expr]:
    """Lagrange's equations of L = ½ q̇ᵀ M(q, t) q̇ + b(q, t)ᵀ q̇ + L₀(q, t):

        E_i = Σ_j M_ij q̈_j + Σ_jk (∂M_ij/∂q_k − ½ ∂M_jk/∂q_i) q̇_j q̇_k + Σ_j ∂M_ij/∂t q̇_j
              + Σ_j (∂b_i/∂q_j − ∂b_j/∂q_i) q̇_j + ∂b_i/∂t − ∂L₀/∂q_i,

    d/dt(∂L/∂q̇_i) − ∂L/∂q_i by the chain rule, each piece a small coefficient."""
    q, qd, qdd, n = model.q, model.qd, model.qdd, len(model.q)
    dM = [[[sp.diff(M[i][j], q[k]) for k in range(n)] for j in range(n)] for i in range(n)]
    db = [[sp.diff(b[i], q[j]) for j in range(n)] for i in range(n)]
    out = []
    for i in range(n):
        E = sum((M[i][j] * qdd[j] + sp.diff(M[i][j], t) * qd[j] + (db[i][j] - db[j][i]) * qd[j] for j in range(n)),
                sp.Integer(0))
        E += sum(((dM[i][j][k] - dM[j][k][i] / 2) * qd[j] * qd[k] for j in range(n) for k in range(n)), sp.Integer(0))
        out.append(E + sp.diff(b[i], t) - sp.diff(L0, q[i]))
    return out


def _compare(rounded: sp.Expr, reference: sp.Expr) -> tuple[dict[sp.Expr, sp.Expr], float]:
    """The rounded equation's terms without those exact arithmetic cancels, and its
    normwise relative error against the reference."""
    a, b = _terms(rounded), _terms(reference)
    scale = max((abs(float(c)) for c in b.values()), default=0.0)
    if scale == 0.0:
        return {}, 0.0
    kept = [k for k in a.keys() | b.keys() if abs(float(b.get(k, 0))) > CANCELLED * scale]
    error = max((abs(float(a.get(k, 0) - b.get(k, 0))) for k in kept), default=0.0) / scale
    return {k: a.get(k, sp.Integer(0)) for k in kept}, error


def _terms(expr: sp.Expr) -> dict[sp.Expr, sp.Expr]:
    """{product of non-numeric factors: its numeric coefficient} of an expanded sum."""
    out: dict[sp.Expr, sp.Expr] = {}
    for term in sp.Add.make_args(expr):
        coefficient, rest = term.as_coeff_Mul()
        out[rest] = out.get(rest, 0) + coefficient
    return out


def _equations(rounded: _Rounded, model: Model) -> tuple[sp.Expr, ...]:
    return tuple(model.to_time(_tidied(terms, error, model)) for terms, error in zip(rounded.terms, rounded.errors))


def _tidied(terms: dict[sp.Expr, sp.Expr], error: float, model: Model, scale: float | None = None) -> sp.Expr:
    """Σ coefficient · term, collected in q̈ and q̇ with each coefficient tidied, and the
    terms that tidying leaves at rounding size (relative to ``scale``, by default the
    largest coefficient) dropped."""
    E = sp.Add(*[c * k for k, c in terms.items()])
    if E == 0:
        return E
    collected = sp.expand(sp.Add(*[c * m for m, c in collect_in(E, [*model.qdd, *model.qd]).items()]))
    parts = _terms(collected)
    scale = max((abs(float(c)) for c in parts.values()), default=0.0) if scale is None else scale
    floor = NOISE * max(error, EPS) * scale
    return sp.Add(*[c * k for k, c in parts.items() if abs(float(c)) > floor])


def _in_frame(model: Model, frame, scene: _Rounded) -> tuple[NumericFrameAnswers, _Rounded]:
    """Lagrange's equations from the frame's L', and whether they are the scene's."""
    refuse_loads_in_frame(model, frame.name)
    seen = frame_lagrangian(model, frame_motion(model, frame))
    primed = _derive(model, lambda digits: _floats(seen.L, model, digits))
    same = all(_agree(a, b, max(ea, eb), model)
               for a, b, ea, eb in zip(primed.terms, scene.terms, primed.errors, scene.errors))
    return NumericFrameAnswers(frame.name, _equations(primed, model), same), primed


def _agree(a: dict, b: dict, error: float, model: Model) -> bool:
    """Σ a − Σ b, its coefficients of q̈ and q̇ tidied, is zero within the errors."""
    scale = max((abs(float(c)) for c in (*a.values(), *b.values())), default=0.0)
    difference = _terms(_tidied({k: a.get(k, 0) - b.get(k, 0) for k in a.keys() | b.keys()}, 0.0, model, scale))
    return all(abs(float(c)) <= NOISE * max(error, EPS) * scale for c in difference.values())
