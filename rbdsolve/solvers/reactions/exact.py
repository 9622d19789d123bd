"""The reactions, exact: Lagrange's equations give q̈, Newton–Euler per body gives the
forces (balances.py); at a state they are put in; released from rest with one
coordinate, T + V constant gives q̇²(q), the forces along the motion and where a push
or a tension reaches zero, and the least μ for rolling (motion.py)."""

from __future__ import annotations

import random
from dataclasses import replace

import sympy as sp

from rbdsolve.errors import UnsolvedError
from rbdsolve.form.printers import to_unicode, unicode_name
from rbdsolve.form.tidy import tidy
from rbdsolve.form.zero import simplifies_to_zero
from rbdsolve.model.build import Model
from rbdsolve.problem.schema import Question
from rbdsolve.report.steps import Route, Solution
from rbdsolve.solvers.eom.exact import general_accelerations
from rbdsolve.solvers.reactions import steps as rs
from rbdsolve.solvers.reactions.answers import ReactionsAnswers, Reaction
from rbdsolve.solvers.reactions.first_zero import (ANGLE_STEP, FirstZero, first_zero, length_step, reaches,
                                                     real_number, unscaled)
from rbdsolve.solvers.reactions.largest import LargestFriction, largest_friction
from rbdsolve.solvers.reactions.balances import balances, solve_forces, with_strings
from rbdsolve.solvers.reactions.limits import Release, exists, holds, least_mu, no_closed_form, pushes_held, zeros
from rbdsolve.solvers.reactions.motion import along, energy
from rbdsolve.solvers.reactions.supports import Held, How, held, planar
from rbdsolve.solvers.lagrange.accelerations import at_state, clean_fraction, state_values
from rbdsolve.solvers.conditions.conditions import critical_values
from rbdsolve.solvers.conditions.condition_roots import admissible
from rbdsolve.solvers.conditions.signs import sign_of
from rbdsolve.solvers.lagrange.energy_integral import energy_step
from rbdsolve.solvers.routes.needed import missing_values
from rbdsolve.solvers.routes.options import Options


def setup(question: Question, model: Model):
    """The supports, the accelerations and the free body rows, shared by both routes."""
    supports = with_strings(model, tuple(held(model, s) for s in question.options.supports), question.options.loc)
    found = general_accelerations(model)
    if found.too_long:
        raise UnsolvedError("the general accelerations are too long to write out, and Newton–Euler needs them")
    if found.solved is None:
        raise UnsolvedError("the mass matrix is singular: Lagrange's equations do not fix the accelerations, "
                            "so Newton–Euler cannot give the forces")
    rows = balances(model, supports, 2 if planar(model) else 3)
    return supports, found.solved, rows


def solve(question: Question, model: Model, options: Options) -> Solution:
    supports, solved, rows = setup(question, model)
    qdd = dict(zip(model.qdd, solved))
    forces = solve_forces(model, rows, supports, qdd)
    reactions = {s.name: _reaction(s, forces) for s in supports}
    steps = [*rs.free_body_steps(model, supports, rows), rs.accelerations_step(model, solved),
             rs.solved_step(model, supports, forces)]
    answers = ReactionsAnswers(reactions, {n: model.to_time(a) for n, a in zip(model.coordinate_names(), solved)})
    criticals: list = []
    warnings: tuple[str, ...] = ()
    if question.options.instant is not None:
        to = {n: model.symbols.scalar(v) for n, v in question.options.to} or None
        answers, more, criticals, warnings = _at_the_state(model, question.options.instant, supports, forces, answers,
                                                           to)
        steps += more
    answers = _replace(answers, reactions={k: _timeless(r, model) for k, r in answers.reactions.items()},
                       critical=critical_values(criticals))
    return Solution("reactions", Route.EXACT, answers, tuple(steps), warnings=warnings)


def _at_the_state(model: Model, instant, supports, forces, answers, to: dict | None):
    """The forces at the state, when each support holds there; released from rest, along
    the motion too (and where it gets to, ``to``). Returns the answers, the steps, the
    critical values used and the warnings."""
    table = state_values(model, instant)
    there = {x: at_state(v, table) for x, v in forces.items()}  # once, not once per support
    at = {s.name: _reaction(s, there, table) for s in supports}
    limits = {s.name: holds(s, at[s.name].components, model) for s in supports}
    let_go = _let_go(model, supports, at)
    answers = _replace(answers, at={k: _timeless(r, model) for k, r in at.items()},
                       holds_when={k: model.to_time(h.condition) for k, h in limits.items()},
                       least_friction_at=_least_friction_at(model, supports, at, limits, let_go))
    criticals = [c for h in limits.values() for c in h.criticals]
    steps = [*rs.instant_steps(model, instant, supports, at), *rs.holds_steps(model, supports, limits, criticals)]
    warnings: tuple[str, ...] = ()
    if instant.from_rest:
        released = {str(c.symbol): Release(at[s.name].components[str(c.symbol)], pushes_held(limits[s.name], s.name))
                    for s in supports for c in s.components if c.one_sided}
        answers, more, found, warnings = _along_the_motion(model, supports, forces, table, answers, to, released)
        steps, criticals = steps + more, criticals + found
        kept = {k: v for k, v in (answers.least_friction_over or {}).items() if k not in let_go}
        answers = _replace(answers, least_friction_over=kept or None)
    return answers, steps, criticals, _let_go_warnings(supports, let_go, instant.from_rest) + warnings


def _let_go(model: Model, supports, at: dict[str, Reaction]) -> dict[str, tuple[str, str]]:
    """With the values given, each support whose push or tension is negative at the
    state asked: its name -> (that component, its value written out). It does not hold
    there, and the body leaves it at once (a disk released inside a track above the level
    of its centre: N = m g cos θ₀ < 0). Negative beyond rounding: 10⁻⁹ of the largest
    force there. Parameters left open may only scale it by positive factors (a ball
    released on a drum at θ₀ = 100°, m and g open: N = g m cos θ₀ = −0.173648 g m)."""
    given = dict(model.values)
    complete = not missing_values(model)
    found = {}
    for s in supports:
        numbers = {k: real_number(v.xreplace(given)) for k, v in at[s.name].components.items()}
        scale = max((abs(x) for x in numbers.values() if x is not None), default=0.0)
        for c in s.components:
            x = numbers.get(str(c.symbol))
            if not c.one_sided:
                continue
            if x is not None and x < -1e-9 * scale:
                found[s.name] = (str(c.symbol), f"{x:.6g}")
            elif x is None and not complete:
                shown = _negative_scaled(at[s.name].components[str(c.symbol)], given)
                if shown is not None:
                    found[s.name] = (str(c.symbol), shown)
    return found


def _negative_scaled(value: sp.Expr, given: dict) -> str | None:
    """``value`` at the values, written out, where the parameters left open only scale it
    by positive factors and what is left is a negative number (beyond rounding: 10⁻⁹ of
    its terms' size); else None."""
    at_values = sp.factor_terms(value.xreplace(given))
    scale = [x for x in sp.Mul.make_args(at_values) if x.free_symbols and x.is_positive is True]
    rest = sp.Mul(*(x for x in sp.Mul.make_args(at_values) if x not in scale))
    x = real_number(rest)
    sizes = [real_number(t) for t in sp.Add.make_args(sp.expand(rest))]
    if x is None or None in sizes or x >= -1e-9 * sum(abs(t) for t in sizes):
        return None
    return to_unicode(sp.Float(x, 6) * sp.Mul(*scale))


def _let_go_warnings(supports, let_go: dict[str, tuple[str, str]], from_rest: bool) -> tuple[str, ...]:
    """A warning per support that does not hold at the state asked (``_let_go``)."""
    how = {s.name: s.how for s in supports}
    after = (", and the forces given along the motion and where it gets to are those of a support that holds, "
             "not the motion's") if from_rest else ""
    out = []
    for k, (name, x) in let_go.items():
        why = "the string is slack" if how[k] is How.STRING else f"the support at {k} cannot pull"
        friction = "; no friction is given for it" if how[k] is How.ROLLING else ""
        out.append(f"{name} = {x} < 0 at the state asked: {why}, so the body leaves it at once{friction}{after}")
    return tuple(out)


def _least_friction_at(model: Model, supports, at: dict[str, Reaction], limits: dict,
                       let_go: dict) -> dict[str, sp.Expr] | None:
    """μ ≥ |F|/N at the state asked, per rolling contact that pushes there (``least_mu``):
    the number an exam asks for ("the least coefficient of friction at release"), which
    ``holds_when`` holds only inside a condition; none where, at the values, it does not
    push there (``let_go``)."""
    found = {}
    for s in supports:
        if s.how is not How.ROLLING or limits[s.name].condition is sp.false or s.name in let_go:
            continue
        N, F = (at[s.name].components[str(c.symbol)] for c in s.components)
        if not simplifies_to_zero(N):
            found[s.name] = model.to_time(least_mu(F, N, model))
    return found or None


def _reaction(s: Held, values: dict[sp.Symbol, sp.Expr], table: dict | None = None) -> Reaction:
    """The support's components, and its force R = Σ x e_x in scene axes (at the state
    ``table`` when given)."""
    pushes = [(values[c.symbol], c.direction.xreplace(table or {})) for c in s.components if not c.moment]
    moment = next((values[c.symbol] for c in s.components if c.moment), None)
    return Reaction(s.on, s.by, s.how, {str(c.symbol): values[c.symbol] for c in s.components},
                    tuple(_summed([x * d[k] for x, d in pushes if d[k] != 0]) for k in range(3)), moment)


def _summed(terms: list[sp.Expr]) -> sp.Expr:
    """A force component: one term as it is (a pivot's R_Ox along e_x), several as one
    cleaned fraction (a push along a turning normal)."""
    if len(terms) <= 1:
        return terms[0] if terms else sp.Integer(0)
    return clean_fraction(sp.Add(*terms))


def _timeless(r: Reaction, model: Model) -> Reaction:
    """The reaction with the coordinates as functions of time, for the answers."""
    return Reaction(r.on, r.by, r.how, {k: model.to_time(v) for k, v in r.components.items()},
                    tuple(model.to_time(x) for x in r.force), model.to_time(r.moment) if r.moment is not None else None)


def _first_zeros(model: Model, supports, values, rate_squared: sp.Expr, table) -> dict[str, FirstZero] | None:
    """With every parameter given a value: where each push or tension first reaches zero
    along the motion, or where the motion turns back before (first_zero.py). Parameters
    left open may only scale each push and q̇² (positive factors, ``sign_part``): their
    signs along the way, so the places, are then the same for every value of them (a
    ladder released at φ₀ = 60° leaves the wall at sin φ = ⅔ sin φ₀ whatever m, L, g)."""
    q = model.q[0]
    name = model.coordinate_names()[0]
    given = dict(model.values)
    pushes = {str(c.symbol): values[c.symbol] for s in supports for c in s.components if c.one_sided}
    if missing_values(model):
        pushes, rate_squared = {k: unscaled(v, given, q) for k, v in pushes.items()}, unscaled(rate_squared, given, q)
        if rate_squared is None or table[q].xreplace(given).free_symbols:
            return None
    step = _step(model, float(table[q].xreplace(given)), rate_squared.xreplace(given))
    if step is None:
        return None
    found = {k: first_zero(v, rate_squared, q, table[q], name, given, step) for k, v in pushes.items() if v is not None}
    found = {k: v for k, v in found.items() if v is not None}
    return _before_first_loss(found, name, float(table[q].xreplace(given))) or None


def _before_first_loss(found: dict[str, FirstZero], name: str, start: float) -> dict[str, FirstZero]:
    """The motion assumed ends where the first contact is lost (a ladder's top leaving
    the wall): what another push would meet past that place (its own loss, the turning
    back) is left out."""
    losses = [abs(z.lost_at[name] - start) for z in found.values() if z.lost_at]
    if not losses:
        return found
    first = min(losses)

    def reached(z: FirstZero) -> bool:
        where = z.lost_at or z.turns_at
        return where is None or abs(where[name] - start) <= first

    return {k: z for k, z in found.items() if reached(z)}


def _step(model: Model, start: float, rate_squared: sp.Expr) -> float | None:
    """first_zero's step along the coordinate from ``start`` (q̇², ``rate_squared``, with
    the values put in): half a degree for an angle; for a length, ``length_step`` from the
    scene's lengths (the parameters' values of a length, the release's place); None for
    anything else, or a length without a value to scale by."""
    from rbdsolve.model.values.units import known_dimensions  # loaded where there are values
    from rbdsolve.problem.quantities.quantity import LENGTH, NUMBER

    dimensions = known_dimensions(model)
    kind = dimensions.get(model.q[0])
    if kind == NUMBER:
        return ANGLE_STEP
    if kind != LENGTH:
        return None
    lengths = [float(v) for k, v in model.values.items() if dimensions.get(k) == LENGTH and v.is_real]
    return length_step([*lengths, start], rate_squared, model.q[0], start)


def _largest_frictions(model: Model, supports, values: dict, rate_squared: sp.Expr, table,
                       first: dict[str, FirstZero] | None) -> dict[str, LargestFriction] | None:
    """With every parameter given a value: each rolling contact's least μ at its largest
    over the motion reached from rest, and where (largest.py), from its push's first
    zero or the motion's turning back (``first``). Parameters left open may scale the
    push and q̇² (``unscaled``, as for ``first``) where μ = |F|/N holds none of them: a
    disk rolling inside a track with its mass m open needs |sin θ|/(7 cos θ − 4 cos θ₀)
    whatever m."""
    if not first:
        return None
    given = dict(model.values)
    q, name = model.q[0], model.coordinate_names()[0]
    start, v2 = float(table[q].xreplace(given)), unscaled(rate_squared, given, q)
    if v2 is None:
        return None
    found = {}
    for s in supports:
        own = str(s.components[0].symbol)
        if s.how is not How.ROLLING or own not in first:
            continue
        push, friction = (values[c.symbol].xreplace(given) for c in s.components[:2])
        ratio, push = sp.cancel(friction / push), unscaled(push, given, q)
        if push is None or not ratio.free_symbols <= {q}:
            continue
        largest = largest_friction(push, ratio * push, own, first, v2, q, start, name)
        if largest is not None:
            found[s.name] = largest
    return found or None


def _replace(answers: ReactionsAnswers, **changes) -> ReactionsAnswers:
    return replace(answers, **changes)


def _along_the_motion(model: Model, supports, forces, table, answers, to: dict | None,
                      released: dict[str, Release]):
    """q̇²(q) by energy, the forces along the motion, their zeros and the least μ, and
    the forces where the motion gets to (``to``); a warning for each push or tension
    whose zeros have no closed form (not listed, and not said to hold throughout). A zero
    is a loss only where its support held at the release (``released``, limits.exists)."""
    e = energy(model, table)
    if e is None:
        if to:
            raise UnsolvedError("'to' needs q̇ where the motion gets to, from the energy integral, and there is "
                                "none here (more than one coordinate, a force without a potential, or time in the "
                                "scene, as a driven support: a support at a constant acceleration a₀ written at rest, "
                                "with −a₀ added to 'gravity', keeps one)")
        return answers, [rs.no_energy_note(model)], [], ()
    values = {x: along(v, model, e) for x, v in forces.items()}
    if any(v is None for v in values.values()):
        said = ("the forces along the motion are too long to write out, so none is given where it gets to ('to')",)
        return answers, [energy_step(model, e, True)], [], said if to else ()
    name = model.coordinate_names()[0]
    by_support = {s.name: {str(c.symbol): model.to_time(values[c.symbol]) for c in s.components} for s in supports}
    one_sided = {str(c.symbol): c.symbol for s in supports for c in s.components if c.one_sided}
    found = {k: zeros(values[symbol], model) for k, symbol in one_sided.items()}
    unsolved = {k: no_closed_form(values[one_sided[k]], model) for k, where in found.items() if where is None}
    lost = {k: tuple(where or ()) for k, where in found.items()}
    mu = {s.name: least_mu(values[s.components[1].symbol], values[s.components[0].symbol], model)
          for s in supports if s.how is How.ROLLING}
    mu = {k: model.to_time(v) for k, v in mu.items()}
    reached = {k: tuple(exists(eq, model, e.rate_squared, table[model.q[0]], released[k]) for eq in where)
               for k, where in lost.items()}
    lost = {k: tuple(eq for eq, h in zip(where, reached[k]) if h.condition is not sp.false)
            for k, where in lost.items()}
    reached = {k: tuple(h for h in found if h.condition is not sp.false) for k, found in reached.items()}
    criticals = [c for found in reached.values() for h in found for c in h.criticals]
    answers = _replace(answers, rate_squared={name: model.to_time(e.rate_squared)}, along=by_support,
                       contact_lost=lost, least_friction=mu,
                       lost_exists_when={k: tuple(h.condition for h in found) for k, found in reached.items()},
                       first_zero=(first := _first_zeros(model, supports, values, e.rate_squared, table)),
                       least_friction_over=_largest_frictions(model, supports, values, e.rate_squared, table, first))
    steps = [energy_step(model, e, True),
             *rs.along_steps(model, supports, values, lost, mu, reached, unsolved,
                           {k: r.held for k, r in released.items()})]
    warnings = tuple(f"{k} = 0 along the motion has no closed-form solution ({why}): where it is reached, if "
                     "it is, is not given" for k, why in unsolved.items()) + _unbounded(supports, first, name)
    if to:
        answers, more = _there(model, supports, values, e.rate_squared, table[model.q[0]], to[name], answers)
        passed = _lost_before(model, answers.first_zero, table[model.q[0]], to[name])
        steps, warnings = steps + more, warnings + passed
    return answers, steps, criticals, warnings


def _unbounded(supports, first: dict[str, FirstZero] | None, name: str) -> tuple[str, ...]:
    """Where a rolling contact's own push reaches zero on the way (at the values), the
    friction it needs grows without bound towards there: no largest is given, and this
    says why (the steps promise "the largest of it over the places reached")."""
    lost = {k: z.lost_at[name] for k, z in (first or {}).items() if z.lost_at}
    return tuple(f"μ_{s.name} grows without bound as {s.components[0].symbol} → 0 at {unicode_name(name)} = "
                 f"{lost[str(s.components[0].symbol)]:.6g}, where the contact is lost: the friction needed over the "
                 "whole motion has no largest value" for s in supports
                 if s.how is How.ROLLING and str(s.components[0].symbol) in lost)


def _there(model: Model, supports, values: dict, rate_squared: sp.Expr, start: sp.Expr, to: sp.Expr, answers):
    """The forces where the motion released from rest gets to, q = ``to``: the forces
    along the motion there, with q̇² there; where the motion does not get there
    (``_gets_there``: q̇² < 0 there, or on the way) no force is given (``there_reached``
    false; None where the parameters decide it, the forces then given for where it
    does)."""
    table = {model.q[0]: to}
    w2 = at_state(rate_squared, table)
    reached = _gets_there(model, rate_squared, start, to, w2)
    there = None if reached is False else {
        s.name: _reaction(s, {c.symbol: tidy(at_state(values[c.symbol], table)) for c in s.components}, table)
        for s in supports}
    name = model.coordinate_names()[0]
    answers = _replace(answers, to={name: to}, there=there and {k: _timeless(r, model) for k, r in there.items()},
                       there_rate_squared={name: w2}, there_reached=reached)
    stays = reached is False and simplifies_to_zero(rate_squared.diff(model.q[0]).xreplace({model.q[0]: start}))
    return answers, rs.there_steps(model, to, w2, supports, there, at_equilibrium=stays)


SAMPLES = 6  # parameter points at which, without values, whether the motion gets there is judged


def _gets_there(model: Model, rate_squared: sp.Expr, start: sp.Expr, to: sp.Expr, w2: sp.Expr) -> bool | None:
    """Whether the motion from rest at ``start`` gets to ``to``: not where q̇² < 0 there
    by the parameters' signs; else along the way (``first_zero.reaches``: it sets off
    towards it and q̇² ≥ 0 all the way), at the values, or, without them, at admissible
    samples of the parameters — true or false where they all agree, None where they do
    not (the parameters decide it)."""
    if sign_of(w2, model.decided_by) == -1:
        return False
    q = model.q[0]
    if not missing_values(model):
        return reaches(rate_squared, q, start, to, dict(model.values))
    found = {reaches(rate_squared, q, start, to, point) for k in range(SAMPLES)
             if (point := admissible(model, random.Random(31 + k))) is not None}
    return found.pop() if len(found) == 1 else None


def _lost_before(model: Model, first: dict | None, start: sp.Expr, to: sp.Expr) -> tuple[str, ...]:
    """A warning for each push the motion loses (at the values: ``first``, its
    first_zero) on its way from ``start`` to ``to``."""
    name = model.coordinate_names()[0]
    try:
        q0, end = (float(x.xreplace(dict(model.values))) for x in (start, to))
    except (TypeError, ValueError):
        return ()
    return tuple(f"{k} = 0 at {unicode_name(name)} = {z.lost_at[name]:.6g}, before the motion gets to "
                 f"{unicode_name(name)} = {end:.6g}: past it that contact is lost, so the forces given there are not "
                 "the motion's" for k, z in (first or {}).items()
                 if z.lost_at and min(q0, end) < z.lost_at[name] < max(q0, end))
