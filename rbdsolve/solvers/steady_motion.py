"""Steady motion of a rigid body: rolling conditions and angular momentum balance in a
turning triad (the seed's problem 3: a ring rolling on a horizontal circle).

In a steady motion every component in a triad T (turning at Ω_T) is constant. Then

- rolling without slipping at a contact point C: v_G + ω × (r_C − r_G) = 0, solved for
  the unknown rates (a spin rate);
- the angular momentum about a point P, L_P = J_G ω + (r_G − r_P) × m v_G, has constant
  components in T, so dL_P/dt = (dL_P/dt)_T + Ω_T × L_P = Ω_T × L_P;
- angular momentum balance about P, which may move with velocity v_P,

      dL_P/dt + v_P × m v_G = M_P = Σ (r_i − r_P) × F_i,

  with gravity at G as the force whose moment counts (a contact force at C has none
  about C), gives the relations between the parameters (each component = 0).
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from rbdsolve.errors import UnsolvedError
from rbdsolve.model.build import Model, RigidBody
from rbdsolve.model.rotation import sequence_rotation, vee
from rbdsolve.model.state import t
from rbdsolve.model.tidy import tidy, tidy_fraction
from rbdsolve.problem.schema import Question, SteadyMotionOptions
from rbdsolve.report import steps as st
from rbdsolve.report.math import Label, Product, Terms
from rbdsolve.report.steps import Relation, Route, Solution
from rbdsolve.solvers.common import Options, in_basis


@dataclass(frozen=True)
class SteadyMotionAnswers:
    triad: tuple[str, str, str]  # the names of the triad's unit vectors
    rates: dict[str, sp.Expr]  # unknown rates found from the rolling conditions
    angular_velocity: tuple[sp.Expr, sp.Expr, sp.Expr]  # ω in the triad's components
    angular_momentum: tuple[sp.Expr, sp.Expr, sp.Expr]  # L_P, triad components
    moment: tuple[sp.Expr, sp.Expr, sp.Expr]  # M_P, triad components
    relations: tuple[sp.Expr, ...]  # each = 0
    solved: dict[str, sp.Expr]  # the asked quantity, from the relations


def solve(question: Question, model: Model, options: Options) -> Solution:
    opts: SteadyMotionOptions = question.options
    body = next(b for b in model.bodies if b.name == opts.body)
    triad = next(tr for tr in model.problem.triads if tr.name == opts.triad)
    k = _Kinematics(model, triad.name, body)
    names = model.symbols.with_points(model.points)
    omega, v_G = k.omega(), k.velocity(body.position)
    steps = [st.definition(f"The body's angular velocity and the velocity of its centre of mass, in the triad "
                           f"{', '.join(triad.vectors)} (which turns at Ω_T):",
                           Relation(sp.Symbol("Omega_T"), _show(k.Omega, triad.vectors)),
                           Relation(sp.Symbol("omega"), _show(omega, triad.vectors)),
                           Relation(sp.Symbol("v_G"), _show(v_G, triad.vectors)))]
    rates, rolling_steps = _rolling(opts, model, k, omega, v_G, triad.vectors)
    steps += rolling_steps

    def fix(v: sp.Matrix) -> sp.Matrix:  # the unknown rates found, each component tidied
        return sp.Matrix([tidy(x.xreplace(rates)) for x in v])

    omega, v_G = fix(omega), fix(v_G)
    P = names.vector(opts.about)
    if opts.contact is not None and tidy_fraction((P - names.vector(opts.contact)).dot(P - names.vector(opts.contact))) != 0:
        raise UnsolvedError(f"the body rolls at {opts.contact.text}: take moments about that point (about: "
                            f"{opts.contact.text}), where the unknown contact force has no moment")
    r_PG = fix(k.components(body.position) - k.components(P))
    L = fix(k.inertia() * omega + r_PG.cross(body.mass * v_G))
    steady = k.rate_in_triad(L)
    if any(tidy(x) != 0 for x in steady) or any(x.has(t) for x in L):
        raise UnsolvedError("not a steady motion: the angular momentum's components in the triad change")
    dL = fix(k.Omega.cross(L))
    v_P = fix(k.velocity(P))
    g = k.components(model.gravity) if model.gravity is not None else sp.zeros(3, 1)
    M = fix((k.components(body.position) - k.components(P)).cross(body.mass * g))
    balance = dL + v_P.cross(body.mass * v_G) - M
    if any(tidy(x).has(t) for x in balance):
        raise UnsolvedError("not a steady motion: the balance's components in the triad change with time "
                            "(is gravity along the triad's axis of turning?)")
    target = model.symbols.scalar(opts.solve_for) if opts.solve_for is not None else None
    relations = tuple(_relation(x, target) for x in balance if tidy_fraction(x) != 0)
    solved = _solve_for(opts, relations, model, rates)
    answers = SteadyMotionAnswers(triad.vectors, {str(a): b for a, b in rates.items()}, tuple(omega), tuple(L),
                                  tuple(M), relations, solved)
    steps += _balance_steps(answers, dL, v_P, opts, target)
    return Solution("steady_motion", Route.EXACT, answers, tuple(steps))


class _Kinematics:
    """Vectors in a turning triad's components, by the transport theorem, so that a
    steady motion's components come out free of t:

        Ω_T = vee(Tᵀ Ṫ),  v = d r_T/dt + Ω_T × r_T,  ω = Ω_T + vee(Ṙ_rel R_relᵀ),
        J_G = R_rel J R_relᵀ,  with R_rel = Tᵀ R the body's turns relative to T."""

    def __init__(self, model: Model, triad: str, body: RigidBody):
        T = model.triads[triad]
        self.model, self.T, self.body = model, T, body
        self.Omega = vee((T.T * model.state.d_dt(T)).applyfunc(tidy))
        orientation = body.source.orientation
        if orientation and orientation[0] == triad:  # the body's own turns after the triad's
            names = model.symbols.with_points(model.points)
            self.R_rel = sequence_rotation([(names.vector(x.axis), names.scalar(x.angle)) for x in orientation[1:]])
        else:
            self.R_rel = (T.T * body.rotation).applyfunc(tidy)

    def components(self, v: sp.Matrix) -> sp.Matrix:
        return (self.T.T * v).applyfunc(tidy)

    def velocity(self, r: sp.Matrix) -> sp.Matrix:
        r_T = self.components(r)
        return (self.model.state.d_dt(r_T) + self.Omega.cross(r_T)).applyfunc(tidy)

    def rate_in_triad(self, v: sp.Matrix) -> sp.Matrix:
        return self.model.state.d_dt(v).applyfunc(tidy)

    def omega(self) -> sp.Matrix:
        relative = vee((self.model.state.d_dt(self.R_rel) * self.R_rel.T).applyfunc(tidy))
        return (self.Omega + relative).applyfunc(tidy)

    def inertia(self) -> sp.Matrix:
        return (self.R_rel * self.body.inertia * self.R_rel.T).applyfunc(tidy)


def _rolling(opts: SteadyMotionOptions, model: Model, k: _Kinematics, omega, v_G, vectors):
    """v_C = v_G + ω × (r_C − r_G) = 0 at the contact, solved for the unknown rates."""
    if opts.contact is None:
        return {}, []
    names = model.symbols.with_points(model.points)
    C = names.vector(opts.contact)
    v_C = (v_G + omega.cross(k.components(C) - k.components(k.body.position))).applyfunc(tidy)
    unknowns = [model.symbols.parameters[u] for u in model.problem.unknowns]
    equations = [x for x in v_C if x != 0]
    found = sp.solve(equations, unknowns, dict=True) if equations else [{}]
    if len(found) != 1:
        raise UnsolvedError("the rolling condition does not fix the unknown rates")
    rates = {a: tidy(b) for a, b in found[0].items()}
    steps = [st.equation(f"Rolling without slipping at {opts.contact.text}: the body's point there is at rest, "
                         "v_G + ω × (r_C − r_G) = 0:", Relation(_show(v_C, vectors), sp.Integer(0)))]
    if rates:
        steps.append(st.result("which gives", *[Relation(a, b) for a, b in rates.items()]))
        steps.append(st.result("so the angular velocity is",
                               Relation(sp.Symbol("omega"), _show(omega.xreplace(rates).applyfunc(tidy), vectors))))
    return rates, steps


def _relation(x: sp.Expr, target: sp.Expr | None) -> sp.Expr:
    """A balance component as a relation = 0: its numerator, without the positive
    parameter factors (m r/2 …) that do not change it, and, with a quantity to solve
    for, as a X + b with a factored and not negative: ω₀² cos θ (4R + r sin θ) − 2g sin θ."""
    numerator = sp.fraction(sp.together(tidy_fraction(x)))[0]
    kept = [f for f in sp.Mul.make_args(sp.factor_terms(sp.expand(numerator)))
            if not (f.is_number or f.is_positive)]
    relation = tidy(sp.Mul(*kept))
    if target is None:
        return relation
    X = sp.Dummy("X")
    linear = sp.expand(relation).subs(target, X)
    a, b = sp.diff(linear, X), linear.subs(X, 0)
    if a == 0 or sp.diff(a, X) != 0 or any(linear.has(s) for s in target.free_symbols):
        return relation
    a, b = sp.factor(a), tidy(b)
    if a.could_extract_minus_sign():
        a, b = -a, -b
    return sp.Add(a * target, b, evaluate=False) if b != 0 else a * target


def _solve_for(opts: SteadyMotionOptions, relations, model: Model, rates: dict | None = None) -> dict[str, sp.Expr]:
    """The asked quantity from the relation that holds it alone; the other relations
    must then hold too, or there is no such steady motion."""
    if opts.solve_for is None:
        return {}
    target = model.symbols.scalar(opts.solve_for)
    if rates and target in rates:
        return {opts.solve_for.text: rates[target]}
    X = sp.Dummy("X")
    for relation in relations:
        replaced = relation.subs(target, X)
        if not replaced.has(X) or any(replaced.has(s) for s in target.free_symbols):
            continue
        found = [v for v in sp.solve(replaced, X)
                 if not (target.is_positive and (v.is_negative or v.could_extract_minus_sign()))]
        if len(found) != 1:
            continue
        value = tidy_fraction(found[0])
        plain = value.replace(sp.tan, lambda x: sp.sin(x) / sp.cos(x))
        rest = [r for r in relations if tidy_fraction(r.subs(target, plain)) != 0]
        if rest:
            raise UnsolvedError(f"{opts.solve_for.text} = {sp.sstr(value)} from one relation, but then "
                                f"{sp.sstr(rest[0])} = 0 must hold too: no such steady motion in general")
        return {opts.solve_for.text: value}
    raise UnsolvedError(f"no relation gives {opts.solve_for.text} alone")


def _show(v, vectors):
    return in_basis([(x, sp.Symbol(name)) for x, name in zip(v, vectors) if x != 0])


def _balance_steps(answers: SteadyMotionAnswers, dL, v_P, opts, target=None) -> list[st.Step]:
    e = answers.triad
    about = opts.about.text if opts.about.text.isidentifier() else "P"
    return [
        st.definition(f"Angular momentum about {about}, L = J_G ω + r_{about}G × m v_G:",
                      Relation(sp.Symbol(f"L_{about}"), _show(answers.angular_momentum, e))),
        st.equation("In a steady motion its components in the triad are constant, so dL/dt = Ω_T × L:",
                    Relation(Label(f"dL_{about}/dt", f"\\dot{{L}}_{{{about}}}"), _show(dL, e))),
        st.definition(f"The moment of gravity about {about}, and the velocity of {about}:",
                      Relation(sp.Symbol(f"M_{about}"), _show(answers.moment, e)),
                      Relation(sp.Symbol(f"v_{about}"), _show(v_P, e))),
        st.result(f"Angular momentum balance dL/dt + v_{about} × m v_G = M_{about}, component by component:",
                  *[Relation(_target_first(r, target), sp.Integer(0)) for r in answers.relations]),
        *([st.result("Solved:", *[Relation(target, v) for v in answers.solved.values()])]
          if answers.solved else []),
    ]


def _target_first(relation: sp.Expr, target: sp.Expr | None):
    """ω₀² (4R + r sin θ) cos θ − 2 g sin θ: the term with the asked quantity first."""
    if target is None or not relation.is_Add:
        return relation
    with_target = [x for x in relation.args if x.has(target)]
    rest = [x for x in relation.args if not x.has(target)]
    if len(with_target) != 1:
        return relation
    coefficient = sp.Mul(*[f for f in sp.Mul.make_args(with_target[0]) if f != target])
    return Terms((Product(sp.Integer(1), (target, coefficient)), *rest))
