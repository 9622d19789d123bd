"""The worked solution of an equilibria question: ∂V/∂q = 0, each equilibrium with the
conditions for it to exist, its stability and the Hessian K there; and the numeric
route's search and the eigenvalues of K at each root found."""

from __future__ import annotations

import math

import sympy as sp

from rbdsolve.form.arrange import configuration, scaled_matrix
from rbdsolve.form.display import Relation
from rbdsolve.form.printers import to_unicode, unicode_name
from rbdsolve.model.build import Model
from rbdsolve.report import steps as st
from rbdsolve.solvers.routes.labels import labels_for
from rbdsolve.solvers.equilibria.answers import EquilibriaAnswers, NumericEquilibriaAnswers
from rbdsolve.solvers.conditions.present_conditions import condition_relation, condition_relations, critical_steps


def exact_steps(answers: EquilibriaAnswers, grad: tuple[sp.Expr, ...], model: Model,
                periodic: bool) -> tuple[st.Step, ...]:
    """∂V/∂q = 0, then each equilibrium with where it exists, its stability and K;
    ``periodic``: some angle was reduced to (−π, π]."""
    symbols = set(model.symbols.parameters.values())
    labels = labels_for(model, "stiffness_matrix")
    K = labels.symbol("stiffness_matrix")
    equilibria = answers.equilibria
    steps = [
        st.equation(
            "Equilibria are constant solutions q(t) = q₀; with q̇ = q̈ = 0 Lagrange's "
            "equations reduce to ∂V/∂q = 0:",
            *[Relation(sp.Derivative(sp.Symbol("V"), q), model.to_time(g))
              for q, g in zip(model.state.functions(), grad)],
        ),
        st.result(f"{len(equilibria)} equilibri{'um' if len(equilibria) == 1 else 'a'}"
                  + (" (angles in (−π, π])" if periodic else "") + ":"),
    ]
    coordinates = model.state.functions()
    for number, eq in enumerate(equilibria, start=1):
        if eq.exists_when is not sp.true:
            steps.append(st.result(f"Equilibrium {number} (it exists only where the following holds):",
                                   configuration(coordinates, list(eq.at.values())),
                                   *condition_relations(eq.exists_when, answers.critical)))
        else:
            exists = "" if not eq.conditions else " (it exists only where the following are ≥ 0)"
            steps.append(st.result(f"Equilibrium {number}{exists}:", configuration(coordinates, list(eq.at.values())),
                                   *[Relation(c, sp.Integer(0), "≥") for c in eq.conditions]))
        if eq.equivalent:
            steps.append(st.note("The same configuration (the same orientation, or up to a coordinate V does "
                                 "not depend on) is also written", *[configuration(coordinates, list(e.values()))
                                                                      for e in eq.equivalent]))
        steps.append(st.equation(
            f"{eq.stability.value.capitalize()}: {eq.reason}; the Hessian {labels.text('stiffness_matrix')} = ∂²V/∂q∂q there is",
            Relation(K, scaled_matrix(eq.hessian, symbols)),
        ))
        if eq.stability_cases:
            steps.append(st.result("Its stability, case by case:",
                                   *[condition_relation(c.when, answers.critical, f"{c.stability.value} when")
                                     for c in eq.stability_cases]))
    steps += critical_steps(answers.critical)
    return tuple(steps) + singular_steps(answers.singular_points, model)


def singular_steps(points, model: Model) -> tuple[st.Step, ...]:
    """The solutions of ∂V/∂q = 0 at singular points of the coordinates, set apart."""
    if not points:
        return ()
    coordinates = model.state.functions()
    head = st.note(f"{len(points)} more solution(s) of ∂V/∂q = 0 lie at singular points of the coordinates "
                   "(∂r/∂q loses rank: some motion of the scene has no coordinate there); they are not "
                   "listed as equilibria:")
    return (head, *[st.note(f"{p.verdict.capitalize()}: {p.reason}.",
                            configuration(coordinates, [sp.sympify(v) for v in p.at.values()])) for p in points])


def numeric_steps(a: NumericEquilibriaAnswers, model: Model) -> tuple[st.Step, ...]:
    # numpy's machinery only here: the exact route's steps load none of it
    from rbdsolve.solvers.numeric.numeric_model import CURVATURE_TOL, continuum_text
    from rbdsolve.solvers.numeric.recognized import shown as _shown

    names = model.coordinate_names()
    steps = [st.equation("Equilibria solve ∂V/∂q = 0; stability from the eigenvalues of the Hessian of V:"),
             st.accuracy(f"An eigenvalue of the Hessian within {CURVATURE_TOL:g} × its scale over the search box, "
                         "or within its rounding (4 n ε of the terms it sums), counts as zero (undetermined: "
                         "higher-order terms decide); how the equilibria were "
                         "searched for, and what that guarantees, is in the warning above.")]
    for i, eq in enumerate(a.equilibria, 1):
        where = configuration(model.state.functions(), [_shown(name, v, eq.recognized)
                                                        for name, v in eq.at.items()])
        curv = Relation(sp.Symbol("eig(H)"), sp.ImmutableMatrix([[sp.Float(c, 15) for c in eq.curvatures]]))
        family = f" ({continuum_text(eq.free, names)})" if eq.free else ""
        steps.append(st.result(f"Equilibrium {i}{family}: {eq.stability.value} (eigenvalues of ∂²V/∂q∂q there):",
                               where, curv))
        if eq.recognized:
            exact = ", ".join(f"{unicode_name(n)} = {to_unicode(_shown(n, 0.0, eq.recognized))}" for n in eq.recognized)
            steps.append(st.accuracy(f"Equilibrium {i} is within the error bound {eq.bound:.2g} of a simple exact "
                                     f"value: {exact}."))
        if eq.equivalent:
            steps.append(_written_also(eq, model))
    return tuple(steps) + singular_steps(a.singular_points, model)


def _written_also(eq, model: Model) -> st.Step:
    """The other coordinate values of one configuration the search met: listed, or, where
    they are whole turns of every angle together (a double pendulum whose hinge spring
    holds θ₂ − θ₁: (θ₁, θ₂) + 2πk (1, 1)), said in one line with the turns' range."""
    at = list(eq.at.values())
    turns = [[(float(x) - float(a)) / (2 * math.pi) for x, a in zip(e.values(), at)] for e in eq.equivalent]
    whole = all(abs(k - round(k)) < 1e-6 for ks in turns for k in ks)
    counts = sorted({round(ks[0]) for ks in turns})
    joint = whole and all(len({round(k) for k in ks}) == 1 for ks in turns)
    if joint and len(turns) > 2:
        names = ", ".join(unicode_name(n) for n in eq.at)
        run = counts == [k for k in range(counts[0], counts[-1] + 1) if k != 0]
        ks = f"{_signed(counts[0])}, …, {_signed(counts[-1])} (k ≠ 0" if run else ", ".join(map(_signed, counts)) + " ("
        return st.note(f"The same configuration is also written with whole turns added to every angle, "
                       f"({names}) + 2πk for k = {ks}; {len(turns)} more roots in the search box)")
    return st.note("The same configuration is also written",
                   *[configuration(model.state.functions(), [sp.Float(v, 15) for v in e.values()])
                     for e in eq.equivalent])


def _signed(k: int) -> str:
    return f"−{-k}" if k < 0 else str(k)
