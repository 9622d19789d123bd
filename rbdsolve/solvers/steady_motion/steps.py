"""The worked solution of a steady motion: ω and v_G in the turning triad, the rolling
conditions, L about the point, dL/dt = Ω_T × L, the moment, the balances and what they
are solved for; and the numeric route's relations and solutions."""

from __future__ import annotations

import sympy as sp

from rbdsolve.form.arrange import in_basis
from rbdsolve.form.display import Label, Product, Relation, Terms
from rbdsolve.form.printers import float_text, to_unicode
from rbdsolve.model.build import Model
from rbdsolve.problem.options import SteadyMotionOptions
from rbdsolve.report import steps as st
from rbdsolve.solvers.routes.labels import labels_for
from rbdsolve.solvers.conditions.present_conditions import condition_relations, critical_steps
from rbdsolve.solvers.steady_motion.answers import NumericSteadyMotionAnswers, SteadyMotionAnswers


def show(v, vectors):
    return in_basis([(x, sp.Symbol(name)) for x, name in zip(v, vectors) if x != 0])


OMEGA = sp.Symbol("omega")


def omega_label(model: Model) -> sp.Symbol:
    """The body's angular velocity, ω unless the problem names something omega."""
    return labels_for(model, "angular_velocity").symbol("angular_velocity")


def balance_steps(answers: SteadyMotionAnswers, dL, v_P, opts: SteadyMotionOptions, targets=(),
                   a_G: sp.Matrix | None = None, w: sp.Symbol = OMEGA, loaded: bool = False,
                   L: str = "L") -> list[st.Step]:
    """The angular momentum (named ``L``, H beside a parameter L: form/labels.py), its rate,
    the moment and the balances, then what they are solved for."""
    e = answers.triad
    about = opts.about.text if opts.about.text.isidentifier() else "P"
    target = targets[0] if len(targets) == 1 else None
    forces = {(False, False): "gravity", (True, False): "gravity and the applied loads",
              (False, True): "gravity and the reactions", (True, True): "gravity, the applied loads and the reactions"
              }[(loaded, bool(opts.reactions))]
    newton = ([st.equation("The acceleration of G (constant components, so a_G = Ω_T × v_G):",
                           Relation(sp.Symbol("a_G"), show(a_G, e)))] if a_G is not None else [])
    balances = ("Newton's law for G, m a_G = m g + Σ R, and the angular momentum balance "
                f"d{L}/dt + v_{about} × m v_G = M_{about}, component by component:" if a_G is not None else
                f"Angular momentum balance d{L}/dt + v_{about} × m v_G = M_{about}, component by component:")
    return [
        st.definition(f"Angular momentum about {about}, {L} = J_G {to_unicode(w)} + r_{about}G × m v_G:",
                      Relation(sp.Symbol(f"{L}_{about}"), show(answers.angular_momentum, e))),
        st.equation(f"In a steady motion its components in the triad are constant, so d{L}/dt = Ω_T × {L}:",
                    Relation(Label(f"d{L}_{about}/dt", f"\\dot{{{L}}}_{{{about}}}"), show(dL, e))),
        st.definition(f"The moment of {forces} about {about}, and the velocity of {about}:",
                      Relation(sp.Symbol(f"M_{about}"), show(answers.moment, e)),
                      Relation(sp.Symbol(f"v_{about}"), show(v_P, e))),
        *newton,
        st.result(balances, *[Relation(_target_first(r, target), sp.Integer(0)) for r in answers.relations]),
        *_solved_steps(answers, targets),
    ]


def _solved_steps(answers: SteadyMotionAnswers, targets) -> list[st.Step]:
    """The asked values; with the reactions' other unknowns found together with them
    first (N = m g before the x_N it fixes), as a worked solution would find them."""
    if answers.branches:
        return _branch_steps(answers, targets)
    if not answers.solved:
        return []
    asked = [Relation(x, v) for x, v in zip(targets, answers.solved.values())]
    if not answers.found_along:
        return [st.result("Solved:", *asked)]
    return [st.result("Solved, together with the reactions' other unknowns:",
                      *[Relation(sp.Symbol(u), v) for u, v in answers.found_along.items()], *asked)]


def _branch_steps(answers: SteadyMotionAnswers, targets) -> list[st.Step]:
    """Every solution, each with where it is real, then the critical values."""
    steps = []
    for k, branch in enumerate(answers.branches, 1):
        where = condition_relations(branch.exists_when, answers.critical) if branch.exists_when is not sp.true else []
        name = "Solved" if len(answers.branches) == 1 else f"Solution {k}"
        steps.append(st.result(name + (" (real only where the following holds)" if where else "") + ":",
                               *[Relation(x, v) for x, v in zip(targets, branch.solved.values())], *where))
    return steps + critical_steps(answers.critical, "where the solutions stop being real")


def _target_first(relation: sp.Expr, target: sp.Expr | None):
    """ω₀² (4R + r sin θ) cos θ − 2 g sin θ: the term with the asked quantity first."""
    if target is None or not relation.is_Add:
        return relation
    with_target = [x for x in relation.args if x.has(target)]
    rest = [x for x in relation.args if not x.has(target)]
    if len(with_target) != 1:
        return relation
    number, coefficient = sp.Mul(*[f for f in sp.Mul.make_args(with_target[0]) if f != target]).as_coeff_Mul()
    return Terms((Product(number, (target, coefficient)), *rest))


def numeric_steps(a: NumericSteadyMotionAnswers, opts: SteadyMotionOptions, omega, v_G, model: Model) -> tuple[st.Step, ...]:
    vectors = a.triad
    values = ", ".join(f"{to_unicode(k)} = {float_text(float(v))}" for k, v in model.values.items())
    steps = [st.definition(f"The body's angular velocity and the velocity of its centre of mass, in the triad "
                           f"{', '.join(vectors)}:",
                           Relation(omega_label(model), show(omega, vectors)),
                           Relation(sp.Symbol("v_G"), show(v_G, vectors))),
             st.equation("The rolling conditions and the balances (Newton's law for G first, with reactions), "
                         "each = 0, the unknown rates left in:", *[Relation(r, sp.Integer(0)) for r in a.relations])]
    for i, s in enumerate(a.solutions, 1):
        found = [Relation(sp.Symbol(n), sp.Float(v, 15)) for n, v in s.unknowns.items() if v is not None]
        found += [Relation(model.symbols.scalar(q), sp.Float(s.solved[q.text], 15))
                  for q in opts.solve_for if q.text not in s.unknowns]
        found.append(Relation(omega_label(model), show([sp.Float(v, 15) if v else 0 for v in s.angular_velocity],
                                                       vectors)))
        where = f"With {values}, " if i == 1 and values else ""
        steps.append(st.result(f"{where}solution {i} in floating point:", *found))
    return tuple(steps)  # how it was searched for: the search's warning


def kinematics_step(vectors, Omega_T, omega, v_G, w: sp.Symbol = OMEGA) -> st.Step:
    return st.definition(f"The body's angular velocity and the velocity of its centre of mass, in the triad "
                         f"{', '.join(vectors)} (which turns at Ω_T):",
                         Relation(sp.Symbol("Omega_T"), show(Omega_T, vectors)),
                         Relation(w, show(omega, vectors)),
                         Relation(sp.Symbol("v_G"), show(v_G, vectors)))


def contact_point_step(name: str, offset, vectors) -> st.Step:
    """C on the plane: a sphere's point along −n, a rim's point nearest the plane
    (model/constraints/plane_rolling.py), shown in the triad."""
    return st.definition(f"The contact point {name} is where the body touches the plane: for a rim of radius ρ "
                         "and axis a on a plane of normal n, its point nearest the plane, r_C − r_G = "
                         "−ρ (n − (n·a) a)/|n − (n·a) a| (a sphere: −ρ n):",
                         Relation(sp.Symbol(f"r_{name}") - sp.Symbol("r_G"), show(offset, vectors)))


def rolling_steps(opts: SteadyMotionOptions, v_C, rates: dict, omega, vectors, derived=(),
                  w: sp.Symbol = OMEGA) -> list[st.Step]:
    """Where each contact on a plane touches (``derived``: (C, r_C − r_G)), then
    v_G + ω × (r_C − r_G) = 0 at each contact, the rates it gives, and ω with them."""
    where = " and ".join(C.text for C in opts.contacts)
    steps = [contact_point_step(name, offset, vectors) for name, offset in derived]
    steps += [st.equation(f"Rolling without slipping at {where}: the body's point there is at rest, "
                         f"v_G + {to_unicode(w)} × (r_C − r_G) = 0:", *[Relation(show(v, vectors), sp.Integer(0)) for v in v_C])]
    if rates:
        steps.append(st.result("which gives", *[Relation(a, b) for a, b in rates.items()]))
        steps.append(st.result("so the angular velocity is", Relation(w, show(omega, vectors))))
    return steps
