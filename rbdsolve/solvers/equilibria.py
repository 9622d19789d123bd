"""Equilibria of a conservative system and their stability.

Equilibria: ∂V/∂q = 0. Angles enter V through sin and cos, so each angle q is replaced
by s = sin q, c = cos q with s² + c² = 1, which turns a trigonometric system into a
polynomial one that sympy solves completely (Gröbner bases); q = atan2(s, c) recovers
every branch in (−π, π], so no root is missed (plain ``solve`` misses some).

Stability (Lagrange–Dirichlet): with T positive definite, a strict minimum of V is
stable. The Hessian H = ∂²V/∂q∂q is symmetric, so its characteristic polynomial has
real roots only, and Descartes' rule of signs then counts its positive, zero and
negative eigenvalues exactly from the signs of the coefficients, even when the
entries are symbolic:

* all eigenvalues positive → stable;
* one negative → unstable (the linearized motion grows exponentially);
* zero eigenvalues only along coordinates V does not contain → neutral;
* other zero eigenvalues → undetermined: higher-order terms decide.
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import Enum
from typing import Mapping

import sympy as sp

from rbdsolve.errors import UnsolvedError
from rbdsolve.model.build import Model
from rbdsolve.model.energy import potential_energy
from rbdsolve.model.tidy import tidy
from rbdsolve.problem.schema import Question
from rbdsolve.report import steps as st
from rbdsolve.report.steps import Relation, Route, Solution
from rbdsolve.solvers.common import Options, scaled_matrix


class Stability(Enum):
    STABLE = "stable"
    UNSTABLE = "unstable"
    NEUTRAL = "neutral"
    UNDETERMINED = "undetermined"


@dataclass(frozen=True)
class Equilibrium:
    at: Mapping[str, sp.Expr]  # coordinate name -> value
    stability: Stability
    hessian: sp.ImmutableMatrix
    reason: str  # why this stability: the eigenvalue signs, or what is undecided


@dataclass(frozen=True)
class EquilibriaAnswers:
    equilibria: tuple[Equilibrium, ...]


def gradient(model: Model) -> list[sp.Expr]:
    V = potential_energy(model).total
    return [tidy(sp.diff(V, q)) for q in model.q]


def find_equilibria(model: Model) -> tuple[list[dict[sp.Expr, sp.Expr]], list[str]]:
    """Every solution of ∂V/∂q = 0, angles in (−π, π]; and warnings, if any."""
    equations = [e for e in gradient(model) if e != 0]
    free = [q for q in model.q if not any(e.has(q) for e in equations)]
    if free:
        warnings = [f"V does not depend on {', '.join(str(q.func) for q in free)}: "
                    "every value is an equilibrium; it is shown as 0"]
    else:
        warnings = []
    unknowns = [q for q in model.q if q not in free]
    solutions = _solve_trig_polynomial(equations, unknowns, model.angles)
    if solutions is None:
        solutions = _solve_general(equations, unknowns)
        warnings.append("the equilibrium equations are not polynomial in sin, cos and the "
                        "coordinates; sympy's solve was used and may miss solutions")
    out = []
    for sol in solutions:
        full = {q: sol.get(q, sp.Integer(0)) for q in model.q}
        if full not in out:
            out.append(full)
    return out, warnings


def _solve_trig_polynomial(equations, unknowns, angles) -> list[dict] | None:
    s = {q: sp.Dummy(f"s_{q.func}", real=True) for q in unknowns if q in angles}
    c = {q: sp.Dummy(f"c_{q.func}", real=True) for q in unknowns if q in angles}
    plain = {q: sp.Dummy(str(q.func), real=True) for q in unknowns if q not in angles}
    system = []
    for e in equations:
        poly = sp.expand_trig(sp.expand(e))
        poly = poly.xreplace({sp.sin(q): s[q] for q in s} | {sp.cos(q): c[q] for q in c})
        poly = poly.xreplace(plain)
        if any(poly.has(q) for q in unknowns):
            return None
        numerator = sp.numer(sp.together(poly))
        if not numerator.is_polynomial(*s.values(), *c.values(), *plain.values()):
            return None
        system.append(numerator)
    system += [s[q] ** 2 + c[q] ** 2 - 1 for q in s]
    symbols = [*s.values(), *c.values(), *plain.values()]
    if not symbols:
        return [{}]
    roots = sp.solve(system, symbols, dict=True)
    out = []
    for root in roots:
        if any(sp.sympify(v).is_real is False for v in root.values()):
            continue
        if len(root) < len(symbols):  # a family of solutions: not isolated points
            raise UnsolvedError("the equilibria form a continuum (V is flat along a curve); "
                                "rbdsolve reports isolated equilibria only")
        sol = {q: _angle(root[s[q]], root[c[q]]) for q in s}
        sol |= {q: tidy(root[plain[q]]) for q in plain}
        out.append(sol)
    return out


def _angle(sin_value: sp.Expr, cos_value: sp.Expr) -> sp.Expr:
    """The angle in (−π, π] with this sine and cosine."""
    angle = sp.atan2(sin_value, cos_value)
    if angle.is_number:
        return sp.nsimplify(angle) if angle.is_rational else angle
    if sin_value.is_zero:
        return sp.Integer(0) if cos_value.is_positive else sp.pi
    return sp.simplify(angle) if sp.count_ops(angle) < 40 else angle


def _solve_general(equations, unknowns) -> list[dict]:
    roots = sp.solve(equations, unknowns, dict=True)
    return [r for r in roots if all(sp.sympify(v).is_real is not False for v in r.values())]


def classify(model: Model, at: dict[sp.Expr, sp.Expr]) -> Equilibrium:
    V = potential_energy(model).total
    H = sp.ImmutableMatrix(
        len(model.q), len(model.q), lambda i, j: tidy(sp.diff(V, model.q[i], model.q[j]).subs(at))
    )
    positive, zero, negative, undecided = eigenvalue_signs(H, model)
    names = {q: n for q, n in zip(model.q, model.coordinate_names())}
    where = {names[q]: v for q, v in at.items()}
    if undecided:
        return Equilibrium(where, Stability.UNDETERMINED, H,
                           f"the sign of {undecided} depends on the parameters")
    if negative:
        return Equilibrium(where, Stability.UNSTABLE, H,
                           f"the Hessian of V has {negative} negative eigenvalue(s)")
    if zero:
        flat = [q for q in model.q if not V.has(q)]
        if len(flat) == zero:
            return Equilibrium(where, Stability.NEUTRAL, H,
                               "V does not depend on " + ", ".join(names[q] for q in flat))
        return Equilibrium(where, Stability.UNDETERMINED, H,
                           "the Hessian of V is singular: higher-order terms decide")
    return Equilibrium(where, Stability.STABLE, H, "the Hessian of V is positive definite")


def eigenvalue_signs(H: sp.Matrix, model: Model) -> tuple[int, int, int, sp.Expr | None]:
    """(positive, zero, negative, undecided coefficient) eigenvalue counts of symmetric H.

    Descartes' rule of signs is exact for a polynomial with only real roots. Parameter
    values, when given, decide signs that assumptions alone cannot.
    """
    lam = sp.Dummy("lambda")
    coeffs = [tidy(c) for c in H.charpoly(lam).all_coeffs()]  # leading coefficient 1
    signs = []
    for c in coeffs:
        sign = _sign(c, model)
        if sign is None:
            return 0, 0, 0, c
        signs.append(sign)
    n = len(coeffs) - 1
    zero = 0
    while signs and signs[-1] == 0:
        signs.pop()
        zero += 1
    nonzero = [x for x in signs if x != 0]
    positive = sum(1 for a, b in zip(nonzero, nonzero[1:]) if a != b)
    return positive, zero, n - positive - zero, None


def _sign(value: sp.Expr, model: Model) -> int | None:
    if value.is_zero:
        return 0
    if value.is_positive:
        return 1
    if value.is_negative:
        return -1
    if model.values:
        number = value.xreplace(model.values)
        if number.is_number:
            return int(sp.sign(sp.N(number, 30)))
    return None


def solve(question: Question, model: Model, options: Options) -> Solution:
    grad = gradient(model)
    solutions, warnings = find_equilibria(model)
    if not solutions:
        raise UnsolvedError("∂V/∂q = 0 has no real solution: the system has no equilibrium")
    equilibria = tuple(classify(model, sol) for sol in solutions)
    symbols = set(model.symbols.parameters.values())
    steps = [
        st.equation(
            "Equilibria are constant solutions q(t) = q₀; with q̇ = q̈ = 0 Lagrange's "
            "equations reduce to ∂V/∂q = 0:",
            *[Relation(sp.Derivative(sp.Symbol("V"), sp.Symbol(n)), g)
              for n, g in zip(model.coordinate_names(), grad)],
        ),
        st.result(f"{len(equilibria)} equilibri{'um' if len(equilibria) == 1 else 'a'} "
                  "(angles in (−π, π]):"),
    ]
    for eq in equilibria:
        steps.append(st.result(
            f"{eq.stability.value}: {eq.reason}.",
            *[Relation(sp.Symbol(n), v) for n, v in eq.at.items()],
            Relation(sp.Symbol("K"), scaled_matrix(eq.hessian, symbols)),
        ))
    return Solution("equilibria", Route.EXACT, EquilibriaAnswers(equilibria), tuple(steps),
                    warnings=tuple(warnings))
