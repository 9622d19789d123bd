"""The energy question, exact: the energy integral from the start state
(solvers/lagrange/energy_integral.py); with one coordinate q̇²(q) = 2 (h₀ + T₀ − V)/M, each point's
v² = |∂r_P/∂q|² q̇² along the motion, and both at the configuration asked (``to``),
where the rate is |q̇| = √(q̇²) and a point's speed |v| = √(v²), unless q̇² < 0 there
(the motion does not reach it); where the parameters decide that, the condition for
q̇² ≥ 0 there is given (``_there``). With several coordinates all but one cyclic, their
constant momenta give their rates in terms of the one left and the integral its q̇²
(solvers/lagrange/momentum_integrals.py: "momentum and energy"), and a point's
v = Σ ∂r/∂qᵢ q̇ᵢ with those rates put in."""

from __future__ import annotations

from dataclasses import replace

import sympy as sp

from rbdsolve.errors import UnsolvedError
from rbdsolve.form.factor import factored
from rbdsolve.form.tidy import tidy
from rbdsolve.model.build import Model
from rbdsolve.problem.options import EnergyOptions
from rbdsolve.problem.schema import Question
from rbdsolve.report.steps import Route, Solution
from rbdsolve.solvers.energy.answers import EnergyAnswers, There
from rbdsolve.solvers.energy.steps import exact_steps
from rbdsolve.solvers.lagrange.accelerations import at_state, clean_fraction, state_values
from rbdsolve.solvers.lagrange.energy_integral import EnergyIntegral, energy_integral, not_conserved
from rbdsolve.solvers.lagrange.momentum_integrals import Reduction, reduce
from rbdsolve.solvers.routes.options import Options
from rbdsolve.solvers.conditions.conditions import Critical, critical_values, nonnegative_where
from rbdsolve.solvers.conditions.signs import sign_of


def solve(question: Question, model: Model, options: Options) -> Solution:
    answers, e, reduction = energy(question.options, model)
    return Solution("energy", Route.EXACT, answers, exact_steps(answers, e, reduction, question.options, model),
                    warnings=lost_contacts(question.options, model, answers, e))


def lost_contacts(opts: EnergyOptions, model: Model, answers: EnergyAnswers, e: EnergyIntegral) -> tuple[str, ...]:
    """Where the scene has contacts or strings and the rates are given at ``to``, a
    warning for each push or tension that reaches zero on the way there
    (solvers/reactions/on_the_way.py: loaded only for such a scene); with several
    coordinates, a warning that they were not followed."""
    if not model.contacts or answers.there is None or answers.there.reached is False:
        return ()
    if len(model.q) > 1:
        return ("with several coordinates the contacts' pushes (and strings' tensions) on the way are not followed: "
                "where one reaches zero before the configuration asked, the rates and speeds given there are not the "
                "motion's (ask 'reactions' at the state reached to check the pushes there)",)
    from rbdsolve.solvers.reactions.on_the_way import lost_on_the_way

    to = model.symbols.scalar(dict(opts.to)[model.coordinate_names()[0]])
    return lost_on_the_way(model, state_values(model, opts.start), to, e)


def energy(opts: EnergyOptions, model: Model) -> tuple[EnergyAnswers, EnergyIntegral, Reduction | None]:
    """The answers, the integral (its ``rate_squared`` of the coordinate ``kept``) and,
    with several coordinates all but one cyclic, the momentum integrals that reduce it."""
    why = not_conserved(model)
    if why is not None:
        raise UnsolvedError(f"no energy integral: {why}")
    start = state_values(model, opts.start)
    e = energy_integral(model, start)
    reduction = _reduction(opts, model, e, start)
    if reduction is not None:
        e = replace(e, rate_squared=reduction.rate_squared, kept=reduction.kept)
    names = model.coordinate_names()
    name = names[e.kept]
    one = e.rate_squared is not None
    rates = _rates(model, reduction)
    speeds = {p: _speed_squared(model, p, rates, e) for p in opts.points} if one else None
    to = {n: model.symbols.scalar(v) for n, v in opts.to} if opts.to else None
    there, criticals = _there(model, to, e, rates, speeds) if to else (None, ())
    work = _work(model, start)
    if there is not None and work:
        table = {q: to[n] for q, n in zip(model.q, names)}
        there = replace(there, work={k: at_state(w, table) for k, w in work.items()})
    momenta = ({names[k]: model.to_time(v) for k, v in zip(reduction.cyclic, reduction.start)}
               if reduction else None)
    answers = EnergyAnswers("T + V" if e.plain else "T2 - T0 + V", model.to_time(e.h), model.to_time(e.start),
                            {name: model.to_time(e.rate_squared)} if one else None,
                            {p: model.to_time(v) for p, v in speeds.items()} if speeds else None, to, there,
                            {k: model.to_time(w) for k, w in work.items()} or None, critical_values(criticals),
                            momenta, {names[model.qd.index(qd)]: model.to_time(v) for qd, v in rates.items()} or None)
    return answers, e, reduction


def _reduction(opts: EnergyOptions, model: Model, e: EnergyIntegral, start: dict) -> Reduction | None:
    """With several coordinates, the momentum integrals of the cyclic ones where they
    leave one coordinate; where they do not, 'to' and 'points' are refused (None
    without them: the integral alone is given)."""
    if len(model.q) == 1:
        return None
    found = reduce(model, e, start)
    if not isinstance(found, str):
        return found
    if opts.to or opts.points:
        raise UnsolvedError("with more than one coordinate the energy integral is one equation for several rates, "
                            f"and {found}: it fixes no speed at a configuration ('to', 'points' need one coordinate, "
                            "or all but one cyclic)")
    return None


def _rates(model: Model, reduction: Reduction | None) -> dict[sp.Symbol, sp.Expr]:
    """Each cyclic coordinate's rate in terms of q and the kept one's rate; {} without."""
    if reduction is None:
        return {}
    return {model.qd[k]: x for k, x in zip(reduction.cyclic, reduction.rates)}


def _work(model: Model, start: dict) -> dict[str, sp.Expr]:
    """Each applied load's work from the start state, W = −ΔV_F = V_F(q₀) − V_F(q) (a
    load in the energy integral has a potential: model/energies/loads.py)."""
    return {x.name: tidy(sp.expand(x.potential.xreplace(start) - x.potential)) for x in model.loads
            if x.potential is not None}


def _speed_squared(model: Model, point: str, rates: dict, e: EnergyIntegral) -> sp.Expr:
    """v² = |∂r/∂q|² q̇² (one coordinate, no t in the scene); with cyclic coordinates,
    v = Σ ∂r/∂qᵢ q̇ᵢ with their rates put in, v² = a₂ q̇² + a₁ q̇ + a₀, q̇ the kept
    coordinate's rate taken positive (a₁ = a₀ = 0 where their momenta start at 0)."""
    if not rates:
        dr = model.point(point).diff(model.q[0])
        return clean_fraction(tidy(sp.expand(dr.dot(dr))) * e.rate_squared)
    r, s = model.point(point), model.qd[e.kept]
    v = sum((r.diff(q) * rates.get(qd, qd) for q, qd in zip(model.q, model.qd)), sp.zeros(*r.shape))
    v = v.applyfunc(lambda x: sp.expand(x))
    a2, a1, a0 = (_readable(sp.expand(v.dot(v)).coeff(s, n)) for n in (2, 1, 0))
    return a2 * e.rate_squared + a1 * sp.sqrt(e.rate_squared) + a0


def _readable(expr: sp.Expr) -> sp.Expr:
    """One fraction, its top tidied and factored for reading: (R − r)² (M² + m (2 M + m) sin²θ)/(M + m)²."""
    top, bottom = sp.fraction(sp.factor(sp.together(expr)))
    return factored(tidy(sp.expand(top))) / bottom


def _root(value: sp.Expr) -> sp.Expr:
    """√(3 g/l) as one root, as an exam writes it (sympy would split it into √3 √g/√l)."""
    if value.is_number:
        return sp.sqrt(value)
    return sp.Pow(sp.factor(value), sp.Rational(1, 2), evaluate=False)


def _there(model: Model, to: dict[str, sp.Expr], e: EnergyIntegral, rates: dict, speeds: dict
           ) -> tuple[There, tuple[Critical, ...]]:
    """q̇² at ``to``, and whether the motion gets there, q̇² ≥ 0: decided by the signs,
    the assumptions or the values (``reached`` True or False), else None with where it
    is (``reached_when``, solved for one parameter: a block between springs from x = 0
    at ẋ = 1 reaches x = 1/10 only where k₁ + k₂ ≤ 100 m); the rates and speeds where it
    is reached (a cyclic coordinate's with the kept one's taken positive), with the
    critical values of that condition."""
    names = model.coordinate_names()
    table = {q: to[n] for q, n in zip(model.q, names)}
    w2 = at_state(e.rate_squared, table)
    name = names[e.kept]
    where = nonnegative_where(w2, model)
    reached = _decided(w2, where.condition, model)
    root = (lambda x: None if reached is False else _root(x))
    v2 = {p: at_state(v, table) for p, v in (speeds or {}).items()}
    rate = {name: root(w2)}
    for qd, x in rates.items():
        rate[names[model.qd.index(qd)]] = None if reached is False else _times(at_state(x, table), model.qd[e.kept],
                                                                               rate[name])
    there = There({name: w2}, rate, {p: root(v) for p, v in v2.items()}, reached, reached_when=where.condition)
    return there, where.criticals


def _times(rate: sp.Expr, kept: sp.Symbol, root: sp.Expr) -> sp.Expr:
    """A cyclic rate a q̇ + b at the kept rate q̇ = ``root``, the root kept whole: m (r −
    R)/(M + m) √(…), not its factors' roots spread through the product."""
    a, b = (clean_fraction(sp.expand(rate).coeff(kept, n)) for n in (1, 0))
    return (sp.Mul(*sp.Mul.make_args(a), root, evaluate=False) if a != 0 else sp.Integer(0)) + b


def _decided(w2: sp.Expr, where: sp.Basic, model: Model) -> bool | None:
    """Whether q̇² ≥ 0 at ``to``: by its sign at the values and under the assumptions,
    else by the condition found at the values; None where the parameters decide it."""
    sign = sign_of(w2, model.decided_by)
    if isinstance(sign, int):
        return sign != -1
    at_values = where.xreplace(dict(model.values)) if model.values else where
    return bool(at_values) if at_values in (sp.true, sp.false) else None
