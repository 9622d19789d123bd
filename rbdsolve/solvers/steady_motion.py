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
  about C), gives the relations between the parameters (each component = 0);
- with the contact forces stated as reactions R_i at points r_i (their unknowns N,
  x_N, …), they join M_P = Σ (r_i − r_P) × F_i, and Newton's law for G,

      m a_G = m g + Σ R_i,   a_G = (dv_G/dt)_T + Ω_T × v_G,

  gives three relations more: a cone rolling on its side (a line contact) has its
  normal force's resultant at an unknown distance along the line. Each rolling contact
  then needs a reaction (Newton's law counts it even where it has no moment), and the
  asked quantities are solved together with the reactions' other unknowns, so that no
  answer keeps one (docs/format.md, steady_motion).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import sympy as sp

from rbdsolve.errors import InputError, UnsolvedError
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
    solved: dict[str, sp.Expr]  # the asked quantities, from the relations
    # the reactions' other unknowns (not asked for), solved together with the asked ones
    found_along: dict[str, sp.Expr] = field(default_factory=dict)


def solve(question: Question, model: Model, options: Options) -> Solution:
    opts: SteadyMotionOptions = question.options
    k, vectors = setup(opts, model)
    omega, v_G = k.omega(), k.velocity(k.body.position)
    steps = [st.definition(f"The body's angular velocity and the velocity of its centre of mass, in the triad "
                           f"{', '.join(vectors)} (which turns at Ω_T):",
                           Relation(sp.Symbol("Omega_T"), show(k.Omega, vectors)),
                           Relation(sp.Symbol("omega"), show(omega, vectors)),
                           Relation(sp.Symbol("v_G"), show(v_G, vectors)))]
    rates, rolling_steps = _rolling(opts, model, rolling_velocities(opts, model, k, omega, v_G), omega, vectors)
    steps += rolling_steps
    b = balances(opts, model, k, rates, omega, v_G)
    targets = tuple(model.symbols.scalar(x) for x in opts.solve_for)
    target = targets[0] if len(targets) == 1 else None
    relations = tuple(relation(x, target) for x in b.components if tidy_fraction(x) != 0)
    names = model.symbols.with_points(model.points)
    solved, along = _solve_for(opts, targets, relations, model, rates, _reaction_unknowns(opts, model, names))
    answers = SteadyMotionAnswers(vectors, {str(a): b for a, b in rates.items()}, tuple(b.omega), tuple(b.L),
                                  tuple(b.M), relations, solved, {str(u): v for u, v in along.items()})
    steps += _balance_steps(answers, b.dL, b.v_P, opts, targets, b.a_G)
    return Solution("steady_motion", Route.EXACT, answers, tuple(steps))


@dataclass(frozen=True)
class Balances:
    """A steady motion's balances in the triad, with the rates found so far put in: ω,
    v_G, L_P, dL_P/dt = Ω_T × L_P, v_P, M_P, a_G (with reactions, else None) and the
    balances' components, each = 0 (Newton's law for G first, with reactions)."""

    omega: sp.ImmutableMatrix
    v_G: sp.ImmutableMatrix
    L: sp.ImmutableMatrix
    dL: sp.ImmutableMatrix
    v_P: sp.ImmutableMatrix
    M: sp.ImmutableMatrix
    a_G: sp.ImmutableMatrix | None
    components: tuple[sp.Expr, ...]


def setup(opts: SteadyMotionOptions, model: Model) -> tuple[_Kinematics, tuple[str, str, str]]:
    """The kinematics of the asked body in the asked triad, and the triad's vector names."""
    body = next(b for b in model.bodies if b.name == opts.body)
    triad = next(tr for tr in model.problem.triads if tr.name == opts.triad)
    return _Kinematics(model, triad.name, body), triad.vectors


def rolling_velocities(opts: SteadyMotionOptions, model: Model, k: _Kinematics, omega, v_G) -> list[sp.Matrix]:
    """v_C = v_G + ω × (r_C − r_G) at each rolling contact C, in triad components: each = 0."""
    names = model.symbols.with_points(model.points)
    r_G = k.components(k.body.position)
    return [(v_G + omega.cross(k.components(names.vector(C)) - r_G)).applyfunc(tidy) for C in opts.contacts]


def balances(opts: SteadyMotionOptions, model: Model, k: _Kinematics, rates: dict, omega, v_G) -> Balances:
    """The angular momentum balance about P (and, with reactions, Newton's law for G),
    with the rates found put in (none: the rates stay unknowns, as on the numeric
    route). Refuses what is not a steady motion, and moments or reactions that would
    leave out an unknown contact force."""
    body = k.body

    def fix(v: sp.Matrix) -> sp.Matrix:  # the unknown rates found, each component tidied
        return sp.Matrix([tidy(x.xreplace(rates)) for x in v])

    names = model.symbols.with_points(model.points)
    omega, v_G = fix(omega), fix(v_G)
    P = names.vector(opts.about)
    if not opts.reactions:
        _require_moments_about_contact(opts, names, P)
    _require_reactions_at_contacts(opts, model, k, names)
    L = fix(k.inertia().applyfunc(_sin_cos) * omega + fix(k.components(body.position) - k.components(P)).cross(body.mass * v_G))
    if any(tidy(x) != 0 for x in k.rate_in_triad(L)) or any(x.has(t) for x in L):
        raise UnsolvedError("not a steady motion: the angular momentum's components in the triad change")
    dL, v_P = fix(k.Omega.cross(L)), fix(k.velocity(P))
    forces = _forces(model, k, body, opts, names)
    M = fix(sum(((r - k.components(P)).cross(F) for r, F in forces), sp.zeros(3, 1)))
    found, a_G = [dL + v_P.cross(body.mass * v_G) - M], None
    if opts.reactions:  # the reactions' unknowns need Newton's law for G as well
        a_G = fix(k.rate_in_triad(v_G) + k.Omega.cross(v_G))
        found.insert(0, body.mass * a_G - sum((F for _, F in forces), sp.zeros(3, 1)))
    if any(tidy(x).has(t) for balance in found for x in balance):
        raise UnsolvedError("not a steady motion: the balance's components in the triad change with time "
                            "(is gravity along the triad's axis of turning?)")
    frozen = [sp.ImmutableMatrix(x) if x is not None else None for x in (omega, v_G, L, dL, v_P, M, a_G)]
    return Balances(*frozen, tuple(x for balance in found for x in balance))


def _require_moments_about_contact(opts: SteadyMotionOptions, names, P: sp.Matrix) -> None:
    """Without stated reactions the contact force is unknown; only moments about the
    rolling contact are free of it."""
    if not opts.contacts:
        return
    if len(opts.contacts) > 1:
        raise UnsolvedError("the body rolls at more than one point: state the contact forces as 'reactions' "
                            "(each {at: POINT, force: VECTOR} with unknowns) so both balances can use them")
    contact = opts.contacts[0]
    offset = P - names.vector(contact)
    if tidy_fraction(offset.dot(offset)) != 0:
        raise UnsolvedError(f"the body rolls at {contact.text}: take moments about that point (about: "
                            f"{contact.text}), where the unknown contact force has no moment, or state the "
                            "contact forces as 'reactions'")


def _require_reactions_at_contacts(opts: SteadyMotionOptions, model: Model, k: _Kinematics, names) -> None:
    """With reactions, Newton's law for G, m a_G = m g + Σ R, joins the balance, so the
    reactions must be all the contact forces: a missing one is a wrong answer, also at
    the point P the moments are taken about (its force has no moment about P, but it
    still counts in Σ R). A rolling contact C is stated by a reaction applied at C, or
    by one at an unknown place on the line through C and another rolling contact: the
    resultant of a line contact's distributed push (the cone's N at Q = x_N e1, on OB)."""
    if not opts.reactions:
        return
    unknown = _unknown_symbols(model)
    contacts = [k.components(names.vector(C)) for C in opts.contacts]
    at = [k.components(names.vector(r.at)) for r in opts.reactions]
    for C, r_C in zip(opts.contacts, contacts):
        lines = [d for d in (r - r_C for r in contacts) if not _is_zero(d)]
        if any(_is_zero(a - r_C) or (a.free_symbols & unknown and any(_is_zero((a - r_C).cross(d)) for d in lines))
               for a in at):
            continue
        raise InputError(f"no reaction at the rolling contact '{C.text}': with 'reactions' given they must be all "
                         "the contact forces, as Newton's law for G counts each one (even at the point the moments "
                         f"are taken about); add one such as {{at: {C.text}, force: ...}} with unknowns (or, for a "
                         f"line contact, one at an unknown distance along the line through {C.text} and another "
                         "rolling point)", opts.reactions_loc)


def _is_zero(v: sp.Matrix) -> bool:
    return all(tidy_fraction(_sin_cos(x)) == 0 for x in v)


def _forces(model: Model, k: _Kinematics, body: RigidBody, opts: SteadyMotionOptions, names):
    """(point of application, force) in triad components: gravity at G, then the reactions."""
    g = k.components(model.gravity) if model.gravity is not None else sp.zeros(3, 1)
    gravity = (k.components(body.position), body.mass * g)
    return [gravity] + [(k.components(names.vector(r.at)), k.components(names.vector(r.force)))
                        for r in opts.reactions]


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


def _rolling(opts: SteadyMotionOptions, model: Model, v_C: list[sp.Matrix], omega, vectors):
    """v_C = v_G + ω × (r_C − r_G) = 0 at the contact, solved for the unknown rates."""
    if not opts.contacts:
        return {}, []
    unknowns = [model.symbols.parameters[u] for u in model.problem.unknowns]
    equations = [x for v in v_C for x in v if x != 0]
    found = sp.solve(equations, unknowns, dict=True) if equations else [{}]
    if len(found) != 1:
        raise UnsolvedError("the rolling condition does not fix the unknown rates")
    rates = {a: tidy(b) for a, b in found[0].items()}
    where = " and ".join(C.text for C in opts.contacts)
    steps = [st.equation(f"Rolling without slipping at {where}: the body's point there is at rest, "
                         "v_G + ω × (r_C − r_G) = 0:", *[Relation(show(v, vectors), sp.Integer(0)) for v in v_C])]
    if rates:
        steps.append(st.result("which gives", *[Relation(a, b) for a, b in rates.items()]))
        steps.append(st.result("so the angular velocity is",
                               Relation(sp.Symbol("omega"), show(omega.xreplace(rates).applyfunc(tidy), vectors))))
    return rates, steps


def relation(x: sp.Expr, target: sp.Expr | None) -> sp.Expr:
    """A balance component as a relation = 0: its numerator, without the positive
    parameter factors (m r/2 …) that do not change it, and, with a quantity to solve
    for, as a X + b with a factored and not negative: ω₀² cos θ (4R + r sin θ) − 2g sin θ."""
    numerator = sp.fraction(sp.together(tidy_fraction(_sin_cos(x))))[0]
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


def _solve_for(opts: SteadyMotionOptions, targets: tuple[sp.Expr, ...], relations, model: Model,
               rates: dict, reaction_unknowns: tuple[sp.Symbol, ...] = ()):
    """The asked quantities from the relations that hold them, solved together with the
    reactions' other unknowns (x_N alone needs N too: N x_N = … and N = m g hold them
    together), so that no answer keeps an unknown; an answer that still holds one (a
    reaction's unknown or a rate the rolling conditions leave open) is refused. Every
    other relation must then hold too (unless it holds an unknown not found), or there
    is no such steady motion. A positive quantity (ω₀²) takes only positive roots.
    Returns the asked values and those of the reactions' other unknowns."""
    if not targets:
        return {}, {}
    if all(x in rates for x in targets):
        return {x.text: rates[y] for x, y in zip(opts.solve_for, targets)}, {}
    held = set().union(*(x.free_symbols for x in targets))
    along = [u for u in reaction_unknowns if u not in held]
    X = [sp.Dummy(f"X{i}") for i in range(len(targets))]
    replaced = [r.subs(dict(zip(targets, X))) for r in relations]
    holding = [r for r in replaced if r.has(*X, *along) and not r.has(*held)]
    found = [f for f in (sp.solve(holding, X + along, dict=True) if holding else [])
             if all(d in f for d in X) and not any(x.is_positive and (f[d].is_negative or f[d].could_extract_minus_sign())
                                                   for x, d in zip(targets, X))]
    asked = ", ".join(x.text for x in opts.solve_for)
    if len(found) != 1:
        raise UnsolvedError(f"the relations do not give {asked} uniquely "
                            f"({'no relation holds ' + asked if not holding else f'{len(found)} solutions'})")
    back = dict(zip(X, targets))
    values = {x: tidy_fraction(_sin_cos(found[0][d].xreplace(back))) for x, d in zip(targets, X)}
    _require_known(values, _unknown_symbols(model) | held)
    found_along = {u: tidy_fraction(_sin_cos(found[0][u])) for u in along
                   if u in found[0] and not found[0][u].has(*X, *_unknown_symbols(model))}
    _require_rest(relations, {**values, **found_along}, model, targets, held, bool(opts.reactions))
    return {x.text: values[y] for x, y in zip(opts.solve_for, targets)}, found_along


def _require_known(values: dict, unknown: set) -> None:
    """An answer must be free of the unknowns: one still holding N (not asked for, and not
    fixed by the relations) would be no answer."""
    for x, v in values.items():
        left = sorted(str(u) for u in v.free_symbols & unknown)
        if left:
            raise UnsolvedError(f"the relations leave {', '.join(left)} unknown, and {x} = {sp.sstr(v)} depends "
                                f"on {'it' if len(left) == 1 else 'them'}: {x} is not fixed by this balance")


def _require_rest(relations, values: dict, model: Model, targets, held: set, reactions: bool) -> None:
    """Every relation free of the unknowns not found must hold with the values found."""
    others = _unknown_symbols(model) - set(targets) - held - set(values)
    rest = [r for r in relations if not r.has(*others) and tidy_fraction(_sin_cos(r.subs(values))) != 0]
    if rest:
        shown = ", ".join(f"{x} = {sp.sstr(v)}" for x, v in values.items())
        hint = " (or a contact force is missing from 'reactions')" if reactions else ""
        raise UnsolvedError(f"{shown} from the relations, but then {sp.sstr(rest[0])} = 0 must hold too: "
                            f"no such steady motion in general{hint}")


def _unknown_symbols(model: Model) -> set[sp.Symbol]:
    return {model.symbols.parameters[u] for u in model.problem.unknowns}


def _reaction_unknowns(opts: SteadyMotionOptions, model: Model, names) -> tuple[sp.Symbol, ...]:
    """The declared unknowns the reactions hold (N, x_N, F1, F2), in their declared order."""
    held = set().union(*(names.vector(r.at).free_symbols | names.vector(r.force).free_symbols
                         for r in opts.reactions))
    return tuple(s for s in (model.symbols.parameters[u] for u in model.problem.unknowns) if s in held)


def _sin_cos(x: sp.Expr) -> sp.Expr:
    """tan as sin/cos and sin 2α as 2 sin α cos α, so that the sin² + cos² = 1
    reduction can see them."""
    return sp.expand_trig(x.replace(sp.tan, lambda y: sp.sin(y) / sp.cos(y)))


def show(v, vectors):
    return in_basis([(x, sp.Symbol(name)) for x, name in zip(v, vectors) if x != 0])


def _balance_steps(answers: SteadyMotionAnswers, dL, v_P, opts: SteadyMotionOptions, targets=(),
                   a_G: sp.Matrix | None = None) -> list[st.Step]:
    e = answers.triad
    about = opts.about.text if opts.about.text.isidentifier() else "P"
    target = targets[0] if len(targets) == 1 else None
    forces = "gravity and the reactions" if opts.reactions else "gravity"
    newton = ([st.equation("The acceleration of G (constant components, so a_G = Ω_T × v_G):",
                           Relation(sp.Symbol("a_G"), show(a_G, e)))] if a_G is not None else [])
    balances = ("Newton's law for G, m a_G = m g + Σ R, and the angular momentum balance "
                f"dL/dt + v_{about} × m v_G = M_{about}, component by component:" if a_G is not None else
                f"Angular momentum balance dL/dt + v_{about} × m v_G = M_{about}, component by component:")
    return [
        st.definition(f"Angular momentum about {about}, L = J_G ω + r_{about}G × m v_G:",
                      Relation(sp.Symbol(f"L_{about}"), show(answers.angular_momentum, e))),
        st.equation("In a steady motion its components in the triad are constant, so dL/dt = Ω_T × L:",
                    Relation(Label(f"dL_{about}/dt", f"\\dot{{L}}_{{{about}}}"), show(dL, e))),
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
    if not answers.solved:
        return []
    asked = [Relation(x, v) for x, v in zip(targets, answers.solved.values())]
    if not answers.found_along:
        return [st.result("Solved:", *asked)]
    return [st.result("Solved, together with the reactions' other unknowns:",
                      *[Relation(sp.Symbol(u), v) for u, v in answers.found_along.items()], *asked)]


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
