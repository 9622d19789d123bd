"""The worked solution of a steady spin: Euler's equations, the steady spins case by
case, each spin's stability; and the numeric route's principal moments and spins."""

from __future__ import annotations

import sympy as sp

from rbdsolve.form.printers import to_unicode
from rbdsolve.form.display import Product, Relation, Terms
from rbdsolve.form.tidy import tidy
from rbdsolve.model.state import t
from rbdsolve.report import steps as st
from rbdsolve.solvers.steady_spin.answers import (
    Condition,
    NumericSteadySpinAnswers,
    SpinStability,
    Stability,
    SteadySpinAnswers,
)


def describe(condition: Condition) -> str:
    """J₁ = J₂, J₂ ≠ J₃ (or 'in every case')."""
    parts = [f"{to_unicode(a)} = {to_unicode(b)}" for a, b in condition.equal]
    parts += [f"{to_unicode(a)} ≠ {to_unicode(b)}" for a, b in condition.different]
    return ", ".join(parts) if parts else "in every case"


def exact_steps(answers: SteadySpinAnswers) -> list[st.Step]:
    J = answers.moments
    w = [sp.Function(f"omega_{n}", real=True)(t) for n in (1, 2, 3)]
    euler = [Terms((Product(J[k], (sp.Derivative(w[k], t),)),
                    Product(tidy(J[(k + 2) % 3] - J[(k + 1) % 3]), (w[(k + 1) % 3], w[(k + 2) % 3]))))
             for k in range(3)]
    named = all(x == sp.Symbol(f"J{k + 1}", positive=True) for k, x in enumerate(J))
    given = [] if named else [st.given(f"Principal moments of inertia of {answers.body} about its centre of mass:",
                                       *[Relation(sp.Symbol(f"J_{k + 1}"), J[k]) for k in range(3)])]
    out = [
        *given,
        st.equation("Euler's equations of a free body (no moment about G), in principal axes:",
                    *[Relation(e, sp.Integer(0)) for e in euler]),
        st.equation("A steady spin has ω̇ = 0, so (J₃ − J₂) ω₂ ω₃ = (J₁ − J₃) ω₃ ω₁ = (J₂ − J₁) ω₁ ω₂ = 0: "
                    "ω must be an eigenvector of J_G."),
    ]
    for case in answers.cases:
        rows = [Relation(sp.Symbol("omega"), sp.ImmutableMatrix([list(s)])) for s in case.steady_spins]
        condition = describe(case.condition)
        lead = "In every case" if condition == "in every case" else f"If {condition}"
        out.append(st.result(f"{lead}, the steady spins are:", *rows))
        out += [stability_step(s) for s in case.stability]
    return out


def stability_step(s: SpinStability) -> st.Step:
    spin = Relation(sp.Symbol("omega"), sp.ImmutableMatrix([list(s.spin)]))
    if s.stability is Stability.STABLE and sum(x != 0 for x in s.spin) == 1:
        return st.result("Stable: a small perturbation of this spin turns round it (relative to the body) "
                         "at the rate ν, without growing:", spin, Relation(sp.Symbol("nu"), s.rate))
    if s.stability is Stability.UNSTABLE:
        return st.result("Unstable (the intermediate moment): a small perturbation of this spin grows "
                         "as exp(γ t), with", spin, Relation(sp.Symbol("gamma"), s.rate))
    if s.stability is Stability.CONDITIONAL:
        return st.result("Stable exactly when this spin is about the largest or the smallest moment, that "
                         "is when", spin, Relation(s.condition, sp.Integer(0), op=">"))
    return st.result("Neutral: these steady spins form a continuum, and a small perturbation moves the "
                     "spin along it without growing:", spin)


def numeric_steps(answers: NumericSteadySpinAnswers) -> tuple[st.Step, ...]:
    """The principal moments in floats, then each principal spin's stability and rate."""
    J = answers.moments
    return (
        st.result("Principal moments (numpy.linalg.eigh); steady spins are spins about the principal axes:",
                  *[Relation(sp.Symbol(f"J_{k + 1}"), sp.Float(J[k], 15)) for k in range(3)]),
        *[st.result(f"Spin about e{k + 1} = {tuple(round(x, 12) for x in s.axis)}: {s.stability.value}"
                    + (f", rate {s.rate:.6g} Ω" if s.rate is not None else ""))
          for k, s in enumerate(answers.spins)],
    )
