"""Steady spin of a free rigid body: Euler's equations and the stability of each spin.

In principal axes through the centre of mass, Euler's equations of a free body are
(the seed's problem 6; Goldstein, ch. 5)

    J₁ ω̇₁ + (J₃ − J₂) ω₂ ω₃ = 0,  J₂ ω̇₂ + (J₁ − J₃) ω₃ ω₁ = 0,  J₃ ω̇₃ + (J₂ − J₁) ω₁ ω₂ = 0.

ω is constant exactly when (J₃ − J₂) ω₂ ω₃ = (J₁ − J₃) ω₃ ω₁ = (J₂ − J₁) ω₁ ω₂ = 0, that
is, when ω is an eigenvector of J_G. So the answer depends on which moments are equal:

- all different: a spin about one principal axis, of any size;
- J_i = J_j ≠ J_k: a spin about the symmetry axis e_k, or any ω in the e_i e_j plane;
- all equal: every ω.

Stability of a spin Ω e_k (linearizing about it): the other two components obey
ε̈_i = −Ω² (J_k − J_i)(J_k − J_j)/(J_i J_j) ε_i. A spin about the largest or the smallest
moment is stable, the perturbation turning at Ω √((J_k − J_i)(J_k − J_j)/(J_i J_j));
about the intermediate one it is unstable and grows at Ω √((J_k − J_i)(J_j − J_k)/(J_i J_j)).
About the symmetry axis of a symmetric body (J_i = J_j) the perturbation precesses at
(J_k − J_i) Ω / J_i relative to the body, and a spin in the equatorial plane is neutral:
a small ε_k makes the spin axis drift round that plane at (J_i − J_k) ε_k / J_i.
"""

from __future__ import annotations

from itertools import combinations

import sympy as sp

from rbdsolve.errors import UnsolvedError
from rbdsolve.form.tidy import tidy, tidy_fraction
from rbdsolve.model.build import Model
from rbdsolve.problem.schema import Question
from rbdsolve.report import steps as st
from rbdsolve.report.steps import Route, Solution
from rbdsolve.solvers.inertia.exact import principal
from rbdsolve.solvers.routes.options import Options
from rbdsolve.solvers.conditions.signs import sign_of
from rbdsolve.solvers.steady_spin.answers import (
    Condition,
    SpinCase,
    SpinStability,
    Stability,
    SteadySpinAnswers,
)
from rbdsolve.solvers.steady_spin.precession import precession, precession_steps
from rbdsolve.solvers.steady_spin.steps import exact_steps

OMEGA = sp.Symbol("Omega")  # the size of a steady spin
NAMES = ("e1", "e2", "e3")


def solve(question: Question, model: Model, options: Options) -> Solution:
    name = question.options.body
    body = next(b for b in model.bodies if b.name == name)
    J_G = body.inertia.applyfunc(tidy)
    steps: list[st.Step] = []
    if J_G.is_diagonal():
        moments = tuple(J_G[i, i] for i in range(3))
    else:
        found = principal(J_G, set(model.symbols.parameters.values()), model)
        moments = tuple(found.moments)
        steps += [st.note("The body axes are not principal: e1, e2, e3 below are the principal axes."),
                  *found.steps]
    if any(tidy(J) == 0 for J in moments):
        raise UnsolvedError(f"body '{name}' has a zero principal moment (a particle, a slender rod or a planar "
                            "inertia): Euler's equations need three positive moments")
    omega = model.symbols.parameters.get("Omega", OMEGA)  # a parameter Omega is the spin's size, with its value
    cases = tuple(_case(pattern, moments, model, omega) for pattern in _patterns(moments, model))
    asked = question.options.precession
    free = precession(asked, moments, model) if asked is not None else None
    answers = SteadySpinAnswers(name, moments, cases, free)
    steps += exact_steps(answers) + (precession_steps(free) if free is not None else [])
    return Solution("steady_spin", Route.EXACT, answers, tuple(steps))


# --- which moments may be equal ---------------------------------------------------------


def _patterns(J: tuple[sp.Expr, ...], model: Model) -> list[tuple[frozenset[int], ...]]:
    """The partitions of {0, 1, 2} into groups of equal moments that the scene allows."""
    all_partitions = [
        (frozenset({0}), frozenset({1}), frozenset({2})),
        (frozenset({0, 1}), frozenset({2})),
        (frozenset({0, 2}), frozenset({1})),
        (frozenset({1, 2}), frozenset({0})),
        (frozenset({0, 1, 2}),),
    ]
    return [p for p in all_partitions if all(_possible(J, i, j, _together(p, i, j), model)
                                              for i, j in combinations(range(3), 2))]


def _together(pattern, i: int, j: int) -> bool:
    return any(i in group and j in group for group in pattern)


def _possible(J, i: int, j: int, equal: bool, model: Model) -> bool:
    sign = sign_of(tidy_fraction(J[i] - J[j]), model.decided_by)  # values, or assumptions such as A > B
    if sign == 0:
        return equal
    if isinstance(sign, int):
        return not equal
    return True  # symbolic: both may happen


def _condition(pattern, J, model: Model) -> Condition:
    """The equalities and inequalities between moments that are not already decided;
    of the inequalities, one per pair of groups."""
    equal, different = [], []
    seen_groups = set()
    root = list(range(3))  # which moments are already known equal (union-find)

    def find(n: int) -> int:
        return n if root[n] == n else find(root[n])

    for i, j in combinations(range(3), 2):
        if tidy_fraction(J[i] - J[j]) == 0:
            root[find(j)] = find(i)
    for i, j in combinations(range(3), 2):
        if isinstance(sign_of(tidy_fraction(J[i] - J[j]), model.decided_by), int):
            continue
        if _together(pattern, i, j):
            if find(i) != find(j):
                equal.append((J[i], J[j]))
                root[find(j)] = find(i)
            continue
        groups = frozenset(next(g for g in pattern if n in g) for n in (i, j))
        if groups not in seen_groups:
            seen_groups.add(groups)
            different.append((J[i], J[j]))
    return Condition(tuple(equal), tuple(different))


# --- steady spins and their stability ------------------------------------------------------


def _case(pattern, J, model: Model, omega: sp.Expr) -> SpinCase:
    groups = sorted(pattern, key=len)
    if len(groups) == 3:  # all different
        spins = tuple(_axis(k, omega) for k in range(3))
        return SpinCase(_condition(pattern, J, model), spins,
                        tuple(_distinct(k, J, model, omega) for k in range(3)))
    if len(groups) == 2:
        (k,), pair = sorted(groups[0]), sorted(groups[1])
        plane = tuple(sp.Symbol(f"w{n + 1}") if n in pair else sp.Integer(0) for n in range(3))
        symmetric = SpinStability(_axis(k, omega), Stability.STABLE,
                                  tidy_fraction((J[k] - J[pair[0]]) * omega / J[pair[0]]), None)
        drift = SpinStability(plane, Stability.NEUTRAL, None, None)
        return SpinCase(_condition(pattern, J, model), (_axis(k, omega), plane), (symmetric, drift))
    every = (sp.Symbol("w1"), sp.Symbol("w2"), sp.Symbol("w3"))
    return SpinCase(_condition(pattern, J, model), (every,), (SpinStability(every, Stability.NEUTRAL, None, None),))


def _axis(k: int, omega: sp.Expr) -> tuple[sp.Expr, sp.Expr, sp.Expr]:
    return tuple(omega if n == k else sp.Integer(0) for n in range(3))


def _distinct(k: int, J, model: Model, omega: sp.Expr) -> SpinStability:
    """Spin Ω e_k with three different moments: the sign of (J_k − J_i)(J_k − J_j)."""
    i, j = (n for n in range(3) if n != k)
    product = sp.factor(tidy_fraction((J[k] - J[i]) * (J[k] - J[j])))
    sign = sign_of(product, model.decided_by)  # values, or assumptions such as A > B > C
    positive, negative = sign == 1, sign == -1
    frequency = tidy(omega * sp.sqrt(tidy_fraction(product / (J[i] * J[j]))))
    growth = tidy(omega * sp.sqrt(tidy_fraction(-product / (J[i] * J[j]))))
    if positive:
        return SpinStability(_axis(k, omega), Stability.STABLE, frequency, None)
    if negative:
        return SpinStability(_axis(k, omega), Stability.UNSTABLE, growth, None)
    return SpinStability(_axis(k, omega), Stability.CONDITIONAL, None, product)
