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
from rbdsolve.form.tidy import tidy
from rbdsolve.model.build import Model
from rbdsolve.problem.options import EnergyOptions
from rbdsolve.problem.schema import Question
from rbdsolve.report.steps import Route, Solution
from rbdsolve.solvers.energy import cyclic
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
                    warnings=(*lost_contacts(question.options, model, answers, e),
                              *undirected(question.options, model, answers, e)))


def undirected(opts: EnergyOptions, model: Model, answers: EnergyAnswers, e: EnergyIntegral) -> tuple[str, ...]:
    """With cyclic rates at ``to``, a warning where the way the motion gets there (the
    sign of the kept rate) is not decided: they are then given for that rate positive."""
    if not answers.rates or answers.there is None or answers.there.reached is False:
        return ()
    start = state_values(model, opts.start)
    if cyclic.direction(model, e.kept, start, answers.to) is not None:
        return ()
    name = model.coordinate_names()[e.kept]
    return (f"which way {name} moves as the motion gets to the configuration asked is not decided by the parameters' "
            f"signs (nor does it start moving): the cyclic rates and the speeds there are given for dot({name}) > 0",)


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
    to = {n: model.symbols.scalar(v) for n, v in opts.to} if opts.to else None
    sign = cyclic.direction(model, e.kept, start, to) if rates else 1
    parts = {p: cyclic.speed_parts(model, p, rates, model.qd[e.kept]) for p in opts.points} if rates else {}
    speeds = ({p: cyclic.along(x, e.rate_squared, sign, model.qd[e.kept]) for p, x in parts.items()} if rates else
              {p: _speed_squared(model, p, e) for p in opts.points} if one else None)
    there, criticals = _there(model, to, e, rates, speeds, parts, sign) if to else (None, ())
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


def _speed_squared(model: Model, point: str, e: EnergyIntegral) -> sp.Expr:
    """v² = |∂r/∂q|² q̇² (one coordinate, no t in the scene)."""
    dr = model.point(point).diff(model.q[0])
    return clean_fraction(tidy(sp.expand(dr.dot(dr))) * e.rate_squared)


def _root(value: sp.Expr) -> sp.Expr:
    """√(3 g/l) as one root, as an exam writes it (sympy would split it into √3 √g/√l)."""
    if value.is_number:
        return sp.sqrt(value)
    return sp.Pow(sp.factor(value), sp.Rational(1, 2), evaluate=False)


def _there(model: Model, to: dict[str, sp.Expr], e: EnergyIntegral, rates: dict, speeds: dict, parts: dict,
           sign: int | None) -> tuple[There, tuple[Critical, ...]]:
    """q̇² at ``to``, and whether the motion gets there, q̇² ≥ 0: decided by the signs,
    the assumptions or the values (``reached`` True or False), else None with where it
    is (``reached_when``, solved for one parameter: a block between springs from x = 0
    at ẋ = 1 reaches x = 1/10 only where k₁ + k₂ ≤ 100 m); the rates and speeds where it
    is reached, with the critical values of that condition. With cyclic coordinates
    (``rates``, the speeds' ``parts``), their rates and the speeds are those of the
    motion getting there, the kept rate's ``sign`` (solvers/energy/cyclic.py)."""
    names = model.coordinate_names()
    table = {q: to[n] for q, n in zip(model.q, names)}
    w2 = at_state(e.rate_squared, table)
    name = names[e.kept]
    where = nonnegative_where(w2, model)
    reached = _decided(w2, where.condition, model)
    root = (lambda x: None if reached is False else _root(x))
    rate = {name: root(w2)}
    if rates:
        way = 1 if sign is None else sign
        v2 = {p: cyclic.there(x, table, w2, rate[name], way) for p, x in parts.items()} if reached is not False else {}
        for qd, x in rates.items():
            rate[names[model.qd.index(qd)]] = (None if reached is False else
                                               cyclic.cyclic_rate(at_state(x, table), model.qd[e.kept], rate[name], way))
    else:
        v2 = {p: at_state(v, table) for p, v in (speeds or {}).items()}
    # a speed whose square holds the rate itself (the momenta not 0) is left under one root as it reads
    whole = {p for p, x in parts.items() if x[1] != 0}
    speed = {p: (sp.Pow(v2[p], sp.S.Half, evaluate=False) if p in whole else root(v2[p])) if p in v2 else None
             for p in (speeds or {})}
    there = There({name: w2}, rate, speed, reached, reached_when=where.condition)
    return there, where.criticals


def _decided(w2: sp.Expr, where: sp.Basic, model: Model) -> bool | None:
    """Whether q̇² ≥ 0 at ``to``: by its sign at the values and under the assumptions,
    else by the condition found at the values; None where the parameters decide it."""
    sign = sign_of(w2, model.decided_by)
    if isinstance(sign, int):
        return sign != -1
    at_values = where.xreplace(dict(model.values)) if model.values else where
    return bool(at_values) if at_values in (sp.true, sp.false) else None
