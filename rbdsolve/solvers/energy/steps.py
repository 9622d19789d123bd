"""The worked solution of an energy question, as an exam writes it: the start state, the
integral ("T + V = h is constant, h = V(q₀)"), q̇² solved from it, each point's v², and
the configuration asked: q̇² there and the rate |q̇|, each point's speed."""

from __future__ import annotations

import sympy as sp

from rbdsolve.form.display import Relation
from rbdsolve.model.build import Model
from rbdsolve.problem.options import EnergyOptions
from rbdsolve.report import steps as st
from rbdsolve.solvers.energy.answers import EnergyAnswers, NumericEnergyAnswers
from rbdsolve.solvers.lagrange.accelerations import state_step
from rbdsolve.solvers.lagrange.energy_integral import EnergyIntegral, energy_step
from rbdsolve.solvers.lagrange.momentum_integrals import Reduction, momentum_step
from rbdsolve.solvers.conditions.present_conditions import condition_relations, critical_steps


def exact_steps(answers: EnergyAnswers, e: EnergyIntegral, reduction: Reduction | None, opts: EnergyOptions,
                model: Model) -> tuple[st.Step, ...]:
    steps = [state_step(model, opts.start)]
    if reduction is not None:
        steps.append(momentum_step(model, reduction))
    steps.append(energy_step(model, e, opts.start.from_rest))
    if e.rate_squared is None:
        steps.append(st.note("With several coordinates the integral is one equation for several rates: it fixes "
                             "no one rate by itself."))
    if answers.work:
        steps.append(st.result("The work of the applied loads from the start, W = −ΔV_F (it is in T + V through "
                               "V_F):", *[Relation(sp.Symbol(f"W_{k}"), v) for k, v in answers.work.items()]))
    if answers.speed_squared:
        how = "v = Σ ∂r/∂qᵢ q̇ᵢ with the cyclic rates put in" if reduction else "v² = |∂r/∂q|² q̇²"
        steps.append(st.result(f"Each point's speed along the motion, {how}:",
                               *[Relation(sp.Symbol(f"v_{p}") ** 2, v) for p, v in answers.speed_squared.items()]))
    there = answers.there
    if there is not None:
        at = [Relation(model.to_time(q), answers.to[n]) for q, n in zip(model.q, model.coordinate_names())]
        steps.append(st.given("At the configuration asked:", *at))
        rates = dict(zip(model.coordinate_names(), model.qd))
        squared = [Relation(model.to_time(rates[n]) ** 2, v) for n, v in there.rate_squared.items()]
        if there.reached is False:
            steps.append(st.note("There q̇² < 0: the motion from the start state does not reach it.", *squared))
            return tuple(steps)
        if there.reached is None:  # the parameters decide: where q̇² ≥ 0 there
            steps += [st.result("There q̇² is", *squared),
                      st.result("The motion from the start state reaches it only where q̇² ≥ 0 there, that is "
                                "when:", *condition_relations(there.reached_when, answers.critical)),
                      *critical_steps(answers.critical, "where it stops being reached")]
        taken = ("its rate taken positive; the cyclic rates and the speeds those of the motion getting there, "
                 "moving from the start towards it" if answers.rates else "the rate taken positive")
        lead = f"There ({taken}):" if there.reached else f"Where it is reached ({taken}):"
        steps.append(st.result(lead, *(squared if there.reached else ()),
                               *[Relation(model.to_time(rates[n]), v) for n, v in there.rate.items()],
                               *[Relation(sp.Symbol(f"v_{p}"), v) for p, v in there.speed.items()],
                               *[Relation(sp.Symbol(f"W_{k}"), v) for k, v in (there.work or {}).items()]))
    return tuple(steps)


def numeric_steps(answers: NumericEnergyAnswers, model: Model) -> tuple[st.Step, ...]:
    rates = {n: model.to_time(qd) for n, qd in zip(model.coordinate_names(), model.qd)}
    math = [Relation(rates[n] ** 2, sp.Float(v, 6)) for n, v in answers.rate_squared.items() if v is not None]
    math += [Relation(rates[n], sp.Float(v, 6)) for n, v in answers.rate.items() if v is not None]
    math += [Relation(sp.Symbol(f"v_{p}"), sp.Float(v, 6)) for p, v in answers.speed.items() if v is not None]
    return (st.result("At the configuration asked (the rate taken positive), the exact route's rates and speeds "
                      "at the parameter values:",
                      *math),)
