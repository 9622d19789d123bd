"""The worked solution of small oscillations with gyroscopic terms: Routh's reduction
where a spin is cyclic, M, G and K at the steady state, det(K − ω²M + iωG) = 0, the
frequencies, and where the motion is stable, case by case."""

from __future__ import annotations

import sympy as sp

from rbdsolve.form.arrange import configuration, scaled_matrix
from rbdsolve.form.display import Relation
from rbdsolve.form.labels import Labels
from rbdsolve.form.printers import unicode_name
from rbdsolve.model.build import Model
from rbdsolve.model.state import t
from rbdsolve.report import steps as st
from rbdsolve.solvers.equilibria.answers import Stability
from rbdsolve.solvers.modes.answers import GyroscopicModesAnswers
from rbdsolve.solvers.modes.routh import Linear
from rbdsolve.solvers.routes.labels import labels_for
from rbdsolve.solvers.conditions.present_conditions import condition_relation, critical_steps
from rbdsolve.solvers.conditions.signs import Inertia, matrix_inertia

KEYS = ("mass_matrix", "stiffness_matrix", "gyroscopic_matrix", "displacement", "frequency", "growth_rate",
        "amplitude", "eigenvalue", "exponent")


def gyroscopic_labels(model: Model) -> Labels:
    return labels_for(model, *KEYS)


def gyroscopic_steps(a: GyroscopicModesAnswers, linear: Linear, model: Model) -> tuple[st.Step, ...]:
    labels = gyroscopic_labels(model)
    M, G, K, u, w, X = (labels.text(k) for k in ("mass_matrix", "gyroscopic_matrix", "stiffness_matrix",
                                                  "displacement", "frequency", "amplitude"))
    symbols = set(model.symbols.parameters.values())
    rates = [Relation(sp.Derivative(f, t), a.steady[n]) for n, f in zip(model.coordinate_names(),
                                                                        model.state.functions()) if n in a.steady]
    where = (", the cyclic coordinate" + ("s" if len(rates) > 1 else "") + " at the steady rate"
             + ("s" if len(rates) > 1 else "")) if rates else ""
    routh = bool(a.steady)
    how = (f"from Routh's function R = R₂ + R₁ + R₀ (by degree in the rates): {M} = ∂²R₂/∂q̇∂q̇, {G} from "
           f"R₁ = Σ cᵢ q̇ᵢ and {K} = −∂²R₀/∂q∂q" if routh else
           f"{M} = ∂²T/∂q̇∂q̇, {G} from the terms of L linear in the rates, L₁ = Σ cᵢ q̇ᵢ (gyroscopic), and "
           f"{K} = ∂²(V − T₀)/∂q∂q, T₀ the part of T without rates")
    steps = [*linear.steps,
             st.given(f"Small motions q = q₀ + {u} about the steady state{where}",
                      configuration(linear.functions, list(a.about.values())), *rates),
             st.equation(f"Linearized equations {M} {u}\u0308 + {G} {u}\u0307 + {K} {u} = 0, {how}, with "
                         f"{G}ᵢⱼ = ∂cᵢ/∂qⱼ − ∂cⱼ/∂qᵢ, at the steady state:",
                         Relation(labels.symbol("mass_matrix"), scaled_matrix(a.M, symbols)),
                         Relation(labels.symbol("gyroscopic_matrix"), scaled_matrix(a.G, symbols)),
                         Relation(labels.symbol("stiffness_matrix"), scaled_matrix(a.K, symbols))),
             st.equation(f"{u} = {X} e^(i{w}t) gives ({K} − {w}²{M} + i{w}{G}) {X} = 0, a real {w} for an "
                         f"oscillation; solvable when det({K} − {w}²{M} + i{w}{G}) = 0:",
                         Relation(_factors(a.characteristic, labels.symbol("frequency")), sp.Integer(0)))]
    steps += _frequency_steps(a, labels)
    steps += _stability_steps(a, labels)
    steps += critical_steps(a.critical, "where the motion changes from stable to unstable")
    return tuple(steps)


def _factors(P: sp.Expr, w: sp.Symbol) -> sp.Expr:
    """P(ω) = 0 as a product of its factors over the parameters, each with a leading
    coefficient the parameters make positive where they do, the constant left out."""
    omega = sp.Symbol("omega")
    out = []
    for factor, power in sp.factor_list(P, omega)[1]:
        lead = sp.Poly(factor, omega).LC()
        out.append((-factor if lead.could_extract_minus_sign() else factor).subs(omega, w) ** power)
    return sp.Mul(*out) if out else P


def _frequency_steps(a: GyroscopicModesAnswers, labels: Labels) -> list[st.Step]:
    if not a.frequencies:
        return []
    w = labels.text("frequency")
    text = {Stability.STABLE: "Frequencies (every root real):",
            Stability.UNSTABLE: f"Roots {w} > 0 (not all real here, see below):"}.get(
        a.stability, f"Frequencies, where every {w} is real (see below):")
    steps = [st.result(text, *[Relation(labels.symbol("frequency", i), x) for i, x in enumerate(a.frequencies, 1)])]
    if a.neutral:
        steps.append(st.note(f"{a.neutral} root{'s' if a.neutral > 1 else ''} {w} = 0: a neutral direction "
                             "(no restoring force along it)."))
    return steps


def _stability_steps(a: GyroscopicModesAnswers, labels: Labels) -> list[st.Step]:
    """Where every ω² is real, positive and simple: the conditions, then the verdict,
    case by case where a parameter decides it."""
    if a.stability is Stability.NEUTRAL:
        return []
    lam, w = labels.text("eigenvalue"), labels.text("frequency")
    conditions = [Relation(c, sp.Integer(0), ">") for c in a.stable_if]
    which = ("that is when each of these is positive:" if conditions else
             "which the parameters' signs decide: it is so for every value.")
    steps = [st.equation(f"In {lam} = {w}² the equation has degree {len(a.frequencies)}; the motion is stable to first "
                         f"order when its roots {lam} are all real, positive and distinct (every {w} real), "
                         + which, *conditions)]
    held = " (the gyroscopic terms hold it where K alone would not)" if _not_held_by_K(a) else ""
    free = (", in every direction but the neutral one (along it nothing restores a disturbance: it drifts at a "
            "constant rate)") if a.neutral else ""
    verdict = {Stability.STABLE: f"Every condition holds: the motion is stable{free}{held}.",
               Stability.UNSTABLE: "A condition fails: the motion is unstable.",
               Stability.UNDETERMINED: "Whether they hold depends on the parameters in a way not split here: give "
                                       "values, or state the signs under 'assumptions:'."}
    cases = [_case(c, a, labels) for c in a.stability_cases]
    if a.stability is Stability.DEPENDS:
        steps.append(st.result("Case by case:", *[r for rel in cases for r in rel]))
    else:
        steps.append(st.result(verdict[a.stability]))
        if cases:
            steps.append(st.note("Where that holds, case by case:", *[r for rel in cases for r in rel]))
    return steps


def _not_held_by_K(a: GyroscopicModesAnswers) -> bool:
    """Does K have a negative eigenvalue by the parameters' signs (a K positive
    definite holds the motion without G; one positive semidefinite leaves its zero
    directions to the neutral note, not to G; one whose signs are not decided is not
    said to need G)?"""
    found = matrix_inertia(sp.Matrix(a.K), {})
    return isinstance(found, Inertia) and found.negative > 0


def _case(case, a: GyroscopicModesAnswers, labels: Labels) -> list[Relation]:
    out = [condition_relation(case.when, a.critical, lead=f"{case.stability.value} when")]
    if case.growth_rate is not None:
        out.append(Relation(labels.symbol("growth_rate"), case.growth_rate))
    return out


def cyclic_note(name: str) -> str:
    """A spin angle given a value where a steady spin is likely meant."""
    return (f"{unicode_name(name)} is cyclic (L holds its rate, not itself): its mode here is a free turning at "
            f"rest; for a steady spin give its rate instead, about: {{…, dot({name}): RATE}}")


def numeric_gyroscopic_steps(a, linear: Linear, model: Model) -> tuple[st.Step, ...]:
    """The floating-point route's worked solution: the matrices, the roots s = iω, the
    verdict."""
    labels = gyroscopic_labels(model)
    M, G, K, w, u, X, s = (labels.text(k) for k in ("mass_matrix", "gyroscopic_matrix", "stiffness_matrix",
                                                    "frequency", "displacement", "amplitude", "exponent"))
    rates = [Relation(sp.Derivative(f, t), sp.Float(a.steady[n], 15))
             for n, f in zip(model.coordinate_names(), model.state.functions()) if n in a.steady]
    floats = lambda rows: sp.ImmutableMatrix([[sp.Float(x, 15) for x in row] for row in rows])  # noqa: E731
    steps = [*linear.steps,
             st.given(f"Small motions q = q₀ + {u} about the steady state",
                      configuration(linear.functions, [sp.Float(v, 15) for v in a.about.values()]), *rates),
             st.equation(f"Linearized equations {M} {u}\u0308 + {G} {u}\u0307 + {K} {u} = 0 at the parameter values "
                         "(the exact linearization, rounded once):",
                         Relation(labels.symbol("mass_matrix"), floats(a.M)),
                         Relation(labels.symbol("gyroscopic_matrix"), floats(a.G)),
                         Relation(labels.symbol("stiffness_matrix"), floats(a.K))),
             st.equation(f"{u} = {X} e^({s}t) gives ({s}²{M} + {s}{G} + {K}) {X} = 0, solved in its first-order form "
                         f"[[0, 1], [−{K}, −{G}]] z = {s} [[1, 0], [0, {M}]] z, z = ({X}, {s}{X}) (LAPACK's eigenvalues, "
                         f"through numpy); {s} = i{w} on the imaginary axis is an oscillation:",
                         *[Relation(labels.symbol("exponent", i), sp.Float(re, 15) + sp.I * sp.Float(im, 15))
                           for i, (re, im) in enumerate(a.roots, 1)])]
    if a.frequencies:
        steps.append(st.result("Frequencies:", *[Relation(labels.symbol("frequency", i), sp.Float(x, 15))
                                                for i, x in enumerate(a.frequencies, 1)]))
    if a.stability is Stability.STABLE:
        steps.append(st.result("Every root lies on the imaginary axis within its error bound: the motion is "
                               "stable to first order."))
    else:
        steps.append(st.result("A root lies right of the imaginary axis: the motion is unstable, growing at",
                               *[Relation(labels.symbol("growth_rate", i), sp.Float(x, 15))
                                 for i, x in enumerate(a.growth_rates, 1)]))
    steps.append(st.accuracy(f"Each root's error bound is {SAFETY_TEXT} its distance to the same root at 50 digits "
                             f"(mpmath); largest {max(a.root_errors):.1e}."))
    return tuple(steps)


SAFETY_TEXT = "10 times"
