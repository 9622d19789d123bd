"""The accelerations from Lagrange's equations, and a state of the motion to put in.

Lagrange's equations are linear in the accelerations,

    E(q, q̇, q̈, t) = M(q, t) q̈ + h(q, q̇, t) = 0,   M_ij = ∂E_i/∂q̈_j,  h = E|_{q̈=0},

so where det M ≠ 0 they give q̈ = −M⁻¹ h, by Cramer's rule q̈_i = det M_i / det M with
column i of M replaced by −h: one fraction per coordinate, numerator and denominator
tidied and the common factors (the scales m r², …) cancelled. A state (``at:``, or
``from_rest:`` with every rate 0) is put in exactly.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from rbdsolve.form.display import Relation
from rbdsolve.form.expansion import expanded
from rbdsolve.form.roots import roots_as_absolute
from rbdsolve.form.tidy import cancelled, has_denominator, has_root, tidy, tidy_fraction_parts
from rbdsolve.model.build import Model
from rbdsolve.model.derivative import derivative
from rbdsolve.problem.instants import Instant
from rbdsolve.report import steps as st
from rbdsolve.model.values.values import sample


@dataclass(frozen=True)
class Accelerations:
    """M(q) = ∂E/∂q̈ and h = E − M q̈ of Lagrange's equations, and q̈ solved from them."""

    M: sp.Matrix  # ∂E/∂q̈
    h: tuple[sp.Expr, ...]  # E − M q̈
    solved: tuple[sp.Expr, ...] | None  # q̈_i(q, q̇, t); None where det M = 0 identically, or too long
    too_long: bool = False  # None because the general form is too long to write out, not a singular M


GENERAL_OPS = 400  # beyond this size of h the general q̈ is not written out
NUMERATOR_OPS = 4000  # nor beyond this size of a q̈'s numerator (Cramer's rule): a 5-link chain's has 10⁴


def accelerations(equations: tuple[sp.Expr, ...], model: Model, at: dict | None = None,
                  general: bool = True) -> Accelerations:
    """q̈ = −M⁻¹ h from the equations E_i = 0 (each linear in q̈), at the state ``at``
    when given (put in first: numbers are cheap); ``solved`` is None too where the
    general form is too long to write out (``general``: refuse rather than wait)."""
    n = len(model.q)
    M = sp.Matrix(n, n, lambda i, j: derivative(equations[i], model.qdd[j]))
    h = tuple(expanded(E.xreplace({a: 0 for a in model.qdd})) for E in equations)
    if at is not None:
        M, h = M.xreplace(at).applyfunc(sp.simplify), tuple(sp.simplify(x.xreplace(at)) for x in h)
    elif general and n > 1 and (sum(sp.count_ops(x) for x in h) > GENERAL_OPS or _radicals(h)):
        # (one coordinate: q̈ = −h/M, no determinant to swell, whatever h holds)
        return Accelerations(M, h, None, too_long=True)
    det = tidy(expanded(_det(M)))
    if det == 0:
        return Accelerations(M, h, None)
    numerators = []
    for i in range(n):
        Mi = M.copy()
        Mi[:, i] = sp.Matrix([-x for x in h])
        numerators.append(tidy(expanded(_det(Mi))))
        if at is None and general and sp.count_ops(numerators[-1]) > NUMERATOR_OPS:
            return Accelerations(M, h, None, too_long=True)  # cancelling it would take minutes
    return Accelerations(M, h, tuple(_fraction(num, det) for num in numerators))


def _det(M: sp.Matrix) -> sp.Expr:
    """det M by Berkowitz's division-free algorithm; a 2 × 2 one whose entries have no sum
    in a denominator directly, a d − b c: once expanded, term for term the polynomial
    Berkowitz's gives (−b c + (−a)(−d), its Toeplitz product), at a fraction of the cost
    (~1 ms a 2 × 2 of long entries). With a sum in a denominator the two expand to
    different forms of the same value, so Berkowitz's is kept there."""
    if M.shape == (2, 2) and not any(has_denominator(x) for x in M):
        return M[0, 0] * M[1, 1] - M[0, 1] * M[1, 0]
    return M.det(method="berkowitz")


def _radicals(h: tuple[sp.Expr, ...]) -> bool:
    """A square root of the coordinates (a spring's length): the general q̈ then swells
    past use, and tidying it costs seconds."""
    return any(has_root(x) for x in h)


def _fraction(num: sp.Expr, den: sp.Expr) -> sp.Expr:
    """num/den cancelled, its denominator led by a plus sign: (28 − 3 cos²(φ − θ)).
    (Each part's factors are pulled out here, so the cancelled fraction is taken as it
    comes, without ``tidy_fraction``'s own factor_terms: the same result.)"""
    value = cancelled(num / den)
    top, bottom = sp.fraction(value)
    if sample(bottom, {}).real < 0:  # a denominator such as 3 cos² − 28, negative throughout
        top, bottom = -top, -bottom
    top, bottom = sp.factor_terms(expanded(top)), sp.factor_terms(expanded(bottom))
    return top / bottom


def clean_fraction(expr: sp.Expr) -> sp.Expr:
    """One cancelled fraction, then each part tidied (sin² + cos² = 1, common factors)."""
    top, bottom = tidy_fraction_parts(expr)
    return sp.factor_terms(tidy(expanded(top))) / sp.factor_terms(tidy(expanded(bottom)))


def state_values(model: Model, instant: Instant) -> dict[sp.Symbol, sp.Expr]:
    """{q: value, q̇: value} of a state, exact (rates 0 when released from rest)."""
    coordinates = dict(zip(model.coordinate_names(), model.q))
    rates = dict(zip(model.coordinate_names(), model.qd))
    table = {coordinates[n]: model.symbols.scalar(e) for n, e in instant.coordinates}
    if instant.from_rest:
        table.update({qd: sp.Integer(0) for qd in model.qd})
    else:
        table.update({rates[n]: model.symbols.scalar(e) for n, e in instant.rates})
    return table


# A longer expression at a state is tidied, not run through sympy's simplify: every
# exam's force at a state is shorter (the longest in problems/ and the new users' files,
# 119); a disk on an incline held by a spring of natural length to a point off its line
# has 483 (the spring's radical at the state with every parameter open), 2 s of simplify.
AT_STATE_SIMPLIFY_OPS = 150


def at_state(expr: sp.Expr, table: dict) -> sp.Expr:
    """An expression of the state put at the state, simplified (a few terms: cheap; a
    long one tidied, ``AT_STATE_SIMPLIFY_OPS``), its roots of squares taken (a spring's
    length √(h² + 2 h l cos θ + l²) at θ = 0 is h + l)."""
    at = sp.sympify(expr).xreplace(table)
    shorter = sp.simplify(at) if sp.count_ops(at) <= AT_STATE_SIMPLIFY_OPS else tidy(at)
    return sp.radsimp(roots_as_absolute(shorter))


def state_relations(model: Model, instant: Instant) -> tuple[Relation, ...]:
    """The state as the exam writes it: θ = π/2, φ = 0, θ̇ = 0, φ̇ = 0."""
    table = state_values(model, instant)
    return tuple(Relation(model.to_time(k), v) for k, v in table.items())


def state_step(model: Model, instant: Instant):
    """The state as a given step: released from rest at …, or the state asked for."""
    text = "Released from rest (every rate 0) at:" if instant.from_rest else "At the state:"
    return st.given(text, *state_relations(model, instant))
