"""The worked solution of the equations of motion: Lagrange's equations with the
inertia and potential parts each scaled, as an exam writes them; in a moving frame, T',
V', L', its equations and the checks against the scene's; and the numeric route's
equations with float coefficients."""

from __future__ import annotations

import sympy as sp

from rbdsolve.form.arrange import arranged, arranged_equation, subscript
from rbdsolve.form.display import Relation
from rbdsolve.model.build import Model
from rbdsolve.report import steps as st
from rbdsolve.solvers.routes.labels import labels_for
from rbdsolve.solvers.eom.answers import NumericEomAnswers
from rbdsolve.solvers.lagrange.accelerations import state_step


def frame_steps(model: Model, frame, seen, primed, agree: bool, derivative: bool) -> list[st.Step]:
    reading = model.reading()

    def rows(terms, name):
        return [Relation(sp.Symbol(f"{name}_{i}"), arranged(x.value, reading)) for i, x in enumerate(terms, start=1)]

    legend_T = ", ".join(f"T'{subscript(i)} {x.name}" for i, x in enumerate(seen.kinetic, start=1))
    legend_V = ", ".join(f"V'{subscript(i)} {x.name}" for i, x in enumerate(seen.potential, start=1))
    F = Relation(sp.Symbol("F"), model.to_time(seen.F))
    checks = "They are the same equations" if agree else "rbdsolve could not simplify the difference of the equations to 0"
    checks += ", and L − L' = dF/dt" if derivative else "; L − L' − dF/dt did not simplify to 0"
    return [
        st.definition(f"In frame {frame.name} (positions r' = Rᵀ (r − r_O)): kinetic parts; {legend_T}:",
                      *rows(seen.kinetic, "T'")),
        st.definition(f"Potentials, gravity and the inertial forces included; {legend_V}:",
                      *rows(seen.potential, "V'")),
        st.equation(f"The Lagrangian in frame {frame.name}:", Relation(sp.Symbol("L'"), arranged(seen.L, reading))),
        st.result(f"Lagrange's equations in frame {frame.name}:",
                  *[Relation(arranged_equation(E, reading), sp.Integer(0)) for E in primed]),
        st.result(f"{checks}, with", F) if derivative else st.note(f"{checks}.", F),
    ]


def numeric_steps(answers: NumericEomAnswers, model: Model, error: float,
                  reference_digits: int) -> tuple[st.Step, ...]:
    def shown(equations):
        return [Relation(E, sp.Integer(0)) for E in equations]  # printed to the digits asked (--digits)

    steps = [st.result("Lagrange's equations, d/dt(∂L/∂q̇) − ∂L/∂q = 0 with L = T − V, the parameter values put "
                       "in as floats before differentiating:", *shown(answers.equations)),
             st.accuracy(f"Relative error ≤ {error:.1e} against the same derivation in {reference_digits}-digit "
                         "arithmetic.")]
    for frame in answers.frames:
        verdict = ("They are the scene's equations, coefficient by coefficient within the errors."
                   if frame.equivalent else "They differ from the scene's equations beyond the errors.")
        steps.append(st.result(f"Lagrange's equations from the Lagrangian L' in frame {frame.frame}. {verdict}",
                               *shown(frame.equations)))
    return tuple(steps)


def lagrange_step(equations: tuple[sp.Expr, ...], model: Model) -> st.Step:
    reading = model.reading()
    return st.result("Lagrange's equations, d/dt(∂L/∂q̇) − ∂L/∂q = 0 with L = T − V, one for each "
                     "coordinate in turn:", *[Relation(arranged_equation(E, reading), sp.Integer(0)) for E in equations])


def solved_step(solved: tuple[sp.Expr, ...], model: Model) -> st.Step:
    """q̈ = −M⁻¹ h, one line per coordinate."""
    M = labels_for(model, "mass_matrix").text("mass_matrix")  # M_q beside a parameter M
    return st.result(f"Solved for the accelerations (the equations are linear in q̈: {M}(q) q̈ = −h(q, q̇), and "
                     f"det {M} ≠ 0):", *[Relation(model.to_time(a), model.to_time(v))
                                       for a, v in zip(model.qdd, solved)])


def instant_steps(instant, values: tuple[sp.Expr, ...], model: Model) -> list[st.Step]:
    """q̈ at the state: just after release from rest, or at the state given."""
    when = "Just after release, the" if instant.from_rest else "There the"
    return [state_step(model, instant),
            st.result(f"{when} accelerations are:", *[Relation(model.to_time(a), v) for a, v in zip(model.qdd, values)])]


def singular_step(found) -> st.Step:
    """Why q̈ is not written out: M singular, or (no state put in) too long to write."""
    return st.note("The accelerations are not written out here: the mass matrix M = ∂²T/∂q̇² is singular (then "
                   "Lagrange's equations do not fix every q̈), or the general form is too long to be useful (ask "
                   "for them at a state with 'at:' or 'from_rest:').")
