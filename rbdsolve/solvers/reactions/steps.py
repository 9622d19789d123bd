"""The worked solution of a reactions question: each body's free body diagram (the
forces named, Newton–Euler component by component), the accelerations from Lagrange's
equations, the forces solved; at the state asked for; released from rest, T + V
constant, the forces along the motion, where a contact is lost and the least μ."""

from __future__ import annotations

from collections.abc import Mapping

import sympy as sp

from rbdsolve.form.printers import to_unicode
from rbdsolve.form.arrange import descending
from rbdsolve.form.display import Relation
from rbdsolve.model.build import Model
from rbdsolve.report import steps as st
from rbdsolve.solvers.routes.labels import labels_for
from rbdsolve.solvers.reactions.applied import Applied, applied
from rbdsolve.solvers.reactions.balances import Balance
from rbdsolve.solvers.reactions.limits import implicit_variable, is_implicit
from rbdsolve.solvers.reactions.supports import Held, How
from rbdsolve.solvers.lagrange.accelerations import state_step
from rbdsolve.solvers.conditions.conditions import critical_values
from rbdsolve.solvers.conditions.signs import sign_of
from rbdsolve.solvers.conditions.present_conditions import condition_relations, critical_steps


def _vector(v) -> str:
    return "(" + ", ".join(to_unicode(x) for x in list(v)[:2 if v[2] == 0 else 3]) + ")"


def _described(s: Held, model: Model) -> str:
    parts = []
    for c in s.components:
        if c.moment:
            parts.append(f"a moment {c.symbol} about e_z")
        elif any(x != 0 for x in c.direction) or not c.also:
            parts.append(f"{c.symbol} along {_vector(model.readable(c.direction))}")
        else:  # the part of a string off its drum, over a pulley with mass: it acts on the drum and the pulley only
            parts.append(f"{c.symbol} off the drum (not on body '{s.on}')")
        parts += [f"and {c.symbol} on body '{other}' at {_vector(model.readable(point))} along "
                  f"{_vector(model.readable(direction))}" for other, point, direction in c.also]
    holder = f"body '{s.by}'" if s.by else "the string" if s.how is How.STRING else "the support"
    kind = s.how.value.replace("_", " ") + (" (a joint)" if s.by else "")
    added = ("" if not s.added else "; not asked, but it pulls a body asked about, so its tension is found with the "
             "rest" if s.how is How.STRING else "; not asked, but a string turns the pulley on it, so its force is "
             "found with the rest")
    return f"at {s.name} ({kind}{added}), {holder} on body '{s.on}': " + ", ".join(parts)


def _pull(a: Applied, model: Model) -> str:
    if a.force == sp.zeros(3, 1):
        about = (f"{to_unicode(model.readable(a.moment[2]))} about e_z" if a.moment[:2] == [0, 0]
                 else _vector(model.readable(a.moment)))
        return f"{a.kind} '{a.name}' turns body '{a.body}' by {about}"
    return (f"{a.kind} '{a.name}' {'pulls' if a.kind == 'spring' else 'acts on'} body '{a.body}' at "
            f"{_vector(model.readable(a.point))} with {_vector(model.readable(a.force))}")


def free_body_steps(model: Model, supports: tuple[Held, ...], rows: list[Balance]) -> list[st.Step]:
    """The forces named, then m a_G = m g + Σ R and dL_G/dt = Σ r × R per body."""
    steps = [st.definition("Free body diagrams. The forces the supports exert, each unknown along its unit "
                           "vector (scene axes): " + "; ".join(_described(s, model) for s in supports) + ".")]
    names = list(dict.fromkeys(r.body for r in rows))
    pulls = applied(model, names)
    springs = [a for a in pulls if a.kind == "spring"]
    if springs:
        steps.append(st.definition("The springs are applied forces, known: F = −k s ê on each end (ê the unit "
                                   "vector from the other end, s the stretch), a torsional spring's moment −k s: "
                                   + "; ".join(_pull(a, model) for a in springs) + "."))
    loads = [a for a in pulls if a.kind != "spring"]
    if loads:
        steps.append(st.definition("The applied loads, known: " + "; ".join(_pull(a, model) for a in loads) + "."))
    sprung = {a.body for a in pulls}
    for name in names:
        mine = [r for r in rows if r.body == name]
        F = " + Σ F" if name in sprung else ""
        steps.append(st.equation(f"Body '{name}': m a_G = m g + Σ R{F} component by component, and "
                                 f"dL_G/dt = Σ (r_P − r_G) × {'(R + F)' if F else 'R'} + Σ M about its centre of mass G:",
                                 *[Relation(model.to_time(r.lhs), model.to_time(r.rhs)) for r in mine]))
    return steps


def accelerations_step(model: Model, solved) -> st.Step:
    M = labels_for(model, "mass_matrix").text("mass_matrix")  # M_q beside a parameter M
    return st.substitution(f"The accelerations from Lagrange's equations ({M} q̈ = −h), put in:",
                           *[Relation(model.to_time(a), model.to_time(v)) for a, v in zip(model.qdd, solved)])


def solved_step(model: Model, supports: tuple[Held, ...], forces: dict) -> st.Step:
    return st.result("Solved for the forces, as functions of the state:",
                     *[Relation(c.symbol, model.to_time(forces[c.symbol])) for s in supports for c in s.components])


def instant_steps(model: Model, instant, supports: tuple[Held, ...], at: dict) -> list[st.Step]:
    when = "Just after release" if instant.from_rest else "At that state"
    math = [Relation(sp.Symbol(k), v) for s in supports for k, v in at[s.name].components.items()]
    return [state_step(model, instant), st.result(f"{when}, the forces are:", *math)]


def there_steps(model: Model, to: sp.Expr, w2: sp.Expr, supports: tuple[Held, ...], there: dict | None,
                at_equilibrium: bool = False) -> list[st.Step]:
    """Where the motion gets to: q̇² there, then the forces along the motion there (or
    that it does not get there, and why: released at an equilibrium it stays, q̇² < 0
    there, or a turning back on the way)."""
    q, qd = model.to_time(model.q[0]), model.to_time(model.qd[0])
    steps = [st.given("Where the motion gets to:", Relation(q, to), Relation(qd**2, model.to_time(w2)))]
    if there is None:
        if at_equilibrium:
            return steps + [st.note("Released at rest at an equilibrium (q̈ = 0 there), it stays at rest, so no force "
                                    "is given where it would get to (q̇² above is that of a start displaced ever so "
                                    "slightly).")]
        negative = sign_of(w2, model.decided_by) == -1
        why = ("q̇² < 0 there" if negative else
               "q̇² reaches 0 on the way, or it sets off the other way: it turns back before")
        return steps + [st.note(f"The motion from rest does not get there ({why}), so no force is given.")]
    math = [Relation(sp.Symbol(k), model.to_time(v)) for s in supports for k, v in there[s.name].components.items()]
    return steps + [st.result("There, the forces are:", *math)]


def holds_steps(model: Model, supports: tuple[Held, ...], limits: dict, criticals) -> list[st.Step]:
    """Each support holds while its push or tension is ≥ 0 (and rolls while |F| ≤ μ N):
    said where that is a condition, with the critical values by name."""
    criticals = critical_values(criticals)
    steps = critical_steps(criticals, "where a support stops holding")
    for s in supports:
        h = limits[s.name]
        what = _holding(s)
        if h.condition is sp.false:
            steps.append(st.note(f"At that state {what} cannot hold (its push or tension would be negative): "
                                 "the motion assumed is not possible there."))
        elif h.condition is not sp.true:
            steps.append(st.result(f"{what[0].upper() + what[1:]} holds there when:",
                                   *condition_relations(model.to_time(h.condition), criticals)))
    return steps


def _holding(s: Held) -> str:
    return {How.STRING: f"the string at {s.name} (T ≥ 0: taut)",
            How.ROLLING: f"the rolling contact at {s.name} (N ≥ 0, |F| ≤ μ N)"}.get(
        s.how, f"the contact at {s.name} (N ≥ 0)" if any(c.one_sided for c in s.components) else f"{s.name}")


def no_energy_note(model: Model) -> st.Step:
    return st.note("With more than one coordinate (or time in the scene) T + V = constant does not fix each rate: "
                   "the forces are given at release only.")


def _zero(where: sp.Relational, model: Model) -> Relation:
    """cos q = c as it is; P(sin q) = 0 highest power first, its coefficients factored."""
    if not is_implicit(where):
        return Relation(where.lhs, where.rhs)
    return Relation(descending(sp.Poly(where.lhs, implicit_variable(where, model))), sp.Integer(0))


def _implicit_note(where: sp.Relational, model: Model) -> str:
    f = implicit_variable(where, model)
    degree = sp.Poly(where.lhs, f).degree()
    return (f"That equation is of degree {degree} in {to_unicode(f)}: its roots are not written in closed form "
            "(Cardano's and Ferrari's forms hold i where the roots are real); where the parameters have values, "
            "the numeric values give the one the motion reaches first.")


def along_steps(model: Model, supports, values: dict, lost: dict, mu: dict, reached: dict,
                unsolved: Mapping[str, str], released: Mapping[str, sp.Basic]) -> list[st.Step]:
    """The forces along the motion, and for each push or tension where it is lost, or
    why that is not given (``unsolved``: its name -> the reason, limits.no_closed_form).
    A push or tension that does not reach zero holds throughout only where it holds at
    the release (``released``: its support's condition there)."""
    steps = [st.result("Along the motion, q̇² from the energy put in, the forces are:",
                       *[Relation(c.symbol, model.to_time(values[c.symbol]))
                         for s in supports for c in s.components])]
    strings = {str(c.symbol) for s in supports if s.how is How.STRING for c in s.components}
    guides = {str(c.symbol) for s in supports if s.how is How.GUIDE for c in s.components}
    for name, where in lost.items():
        if where:
            lost_how = "the string goes slack" if name in strings else "the contact is lost" + (
                " (it can only push, N ≥ 0; a bead threaded on its wire, held both ways, is 'two_sided: true')"
                if name in guides else "")
            steps.append(st.result(f"{name} = 0, so {lost_how}, where:", *[_zero(eq, model) for eq in where]))
            implicit = [eq for eq in where if is_implicit(eq)]
            if implicit:
                steps.append(st.note(_implicit_note(implicit[0], model)))
            for eq, h in zip(where, reached[name]):
                if h.condition is not sp.true:
                    named = critical_values(h.criticals)
                    steps += critical_steps(named, "where that point stops being reached")
                    lead = f"{to_unicode(eq.lhs)} = {to_unicode(eq.rhs)} is reached ({_bounded(eq)}q̇² ≥ 0 there)"
                    decided = _decided_long(h, model)
                    steps.append(st.note(f"{lead} only where a condition on the parameters holds, too long to read "
                                         f"here (JSON 'lost_exists_when'); at the values given it "
                                         f"{'holds' if decided else 'does not'}.") if decided is not None else
                                 st.result(f"{lead} only when:",
                                           *condition_relations(model.to_time(h.condition), named)))
        elif name in unsolved:
            steps.append(st.note(f"{name} = 0 has no closed-form solution along the motion ({unsolved[name]}): "
                                 "where it is reached, if it is, is not given."))
        else:
            steps.append(st.note(_never_zero(name, name in strings, released[name])))
    q = model.to_time(model.q[0])
    for name, value in mu.items():
        where = (f" at each {to_unicode(q)} (for the whole motion, the largest of it over the {to_unicode(q)} "
                 "reached)") if value.has(q) else ""
        steps.append(st.result(f"Rolling without slipping at {name} needs |F| ≤ μ N: the least coefficient of "
                               f"friction{where} is", Relation(sp.Symbol(f"mu_{name}"), value, op="≥")))
    return steps


LONG_CONDITION = 400  # characters: a condition longer, in no parameter, is said at the values


def _decided_long(found, model: Model) -> bool | None:
    """Whether a zero's condition of being reached holds at the values given, where it is
    written in no parameter (no critical value: nothing split it), runs past
    LONG_CONDITION characters, and every parameter has a value; else None (written out).
    A disk on an incline held by a spring of natural length to a point off its line had
    twenty lines of radicals for a condition that, with every value given, is a yes."""
    if found.criticals or not model.values or len(to_unicode(found.condition)) <= LONG_CONDITION:
        return None
    at = found.condition.xreplace(dict(model.values))
    if at.free_symbols:
        return None
    try:
        return bool(at)
    except TypeError:  # a comparison sympy cannot decide at the numbers
        return None


def _never_zero(name: str, string: bool, at_release: sp.Basic) -> str:
    """No zero along the motion: the support holds throughout, where it holds when let go."""
    if at_release is sp.false:
        return (f"{name} < 0 at the release for every value allowed: "
                + ("a string cannot push, so it is slack from the start." if string else
                   "the support cannot pull, so the body leaves it at once."))
    holds = "the string stays taut" if string else "the contact holds"
    where = "" if at_release is sp.true else ", where it holds at the release (above)"
    return f"{name} does not reach zero along the motion: {holds} throughout{where}."


SHORT = 24  # a bound written out up to this many characters; a longer one is said in words


def _bounded(eq: sp.Relational) -> str:
    """What must lie in [−1, 1] for the zero ``eq`` to be a place at all, as a clause: the
    c of cos q = c (sin q = c) or of q = acos(c), written out where short ("|2/3 cos(θ₀)|
    ≤ 1, and "), else in words ("the right side in [−1, 1], and "); nothing for q = c (a
    pulley's turn, where a parameter named c read as "|c| ≤ 1")."""
    if isinstance(eq.lhs, (sp.cos, sp.sin)):
        inside, words = [eq.rhs], "the right side in [−1, 1], "
    else:
        inside = list(dict.fromkeys(f.args[0] for f in eq.rhs.atoms(sp.acos, sp.asin)))
        words = "the argument of acos (asin) in [−1, 1], "
    if not inside:
        return ""
    shown = [to_unicode(c) for c in inside]
    return ("".join(f"|{c}| ≤ 1, " for c in shown) if all(len(c) <= SHORT for c in shown) else words) + "and "
