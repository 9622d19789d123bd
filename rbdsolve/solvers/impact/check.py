"""What an impact's answers must satisfy, for the check before they are printed
(solvers/routes/checks.py): the velocities after solve Lagrange's equations for impact with
the generalized impulses answered,

    ∂T/∂q̇_a |_f − ∂T/∂q̇_a |_i − I_a = 0,

and each collision whose impulse was unknown, λ n with λ = (its size)/|n|, Newton's
law of restitution, n · (v_P − u)_f + e n · (v_P − u)_i = 0 (u_f = u_i − λ n/μ for a
striking particle of mass μ; 0 for a fixed surface). T is taken afresh at the instant."""

from __future__ import annotations

import sympy as sp

from rbdsolve.model.build import Model
from rbdsolve.problem.options import ImpactOptions
from rbdsolve.problem.schema import Question
from rbdsolve.solvers.impact.answers import ImpactAnswers
from rbdsolve.solvers.impact.equations import Instant, blows, instant
from rbdsolve.solvers.routes.checks import Residual, Vanishes


def residuals(question: Question, model: Model, answers: object) -> tuple[Residual, ...]:
    """The exact route's answers (the numeric route's floats carry their own error bound)."""
    if not isinstance(answers, ImpactAnswers) or not all(isinstance(v, sp.Expr) for v in answers.velocities.values()):
        return ()
    opts: ImpactOptions = question.options
    now = instant(model, opts)
    names = model.coordinate_names()
    given = dict(opts.before)
    before = {qd: model.symbols.scalar(given[n]) if n in given else sp.Integer(0) for n, qd in zip(names, model.qd)}
    after = {qd: answers.velocities[n] for n, qd in zip(names, model.qd)}
    out: list[Residual] = []
    for n, qd in zip(names, model.qd):
        p = sp.diff(now.T, qd)
        change = p.xreplace(after) - p.xreplace(before)
        out.append(Vanishes(f"the impulse equation of {n}", change - answers.impulses[n]))
    return (*out, *_restitution(opts, model, now, answers, before, after))


def _restitution(opts: ImpactOptions, model: Model, now: Instant, answers: ImpactAnswers, before: dict,
                 after: dict) -> list[Residual]:
    out: list[Residual] = []
    for blow in blows(model, opts, now):
        if blow.size is None or blow.point not in answers.contact_impulses:
            continue
        n = blow.normal
        size = answers.contact_impulses[blow.point] / sp.sqrt(n.dot(n))
        particle = blow.collision.particle
        u = model.symbols.vector(particle.velocity) if particle is not None else sp.zeros(3, 1)
        u_after = u - size * n / model.symbols.scalar(particle.mass) if particle is not None else u
        e = model.symbols.scalar(blow.collision.restitution)
        v = now.velocity(blow.point)
        law = n.dot(v.xreplace(after) - u_after) + e * n.dot(v.xreplace(before) - u)
        out.append(Vanishes(f"the law of restitution at {blow.point}", law))
    return out
