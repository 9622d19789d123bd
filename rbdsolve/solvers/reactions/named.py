"""The names the reactions' worked solution prints its answers by (report/numbers.py):
each q̈, q̇² from the energy integral, each reaction's components at the state asked
(R_Ox, N_C, F_C, T_S, M_O) and where the motion gets to (`to`), or as functions of the state where those hold no
coordinate (an Atwood machine's tensions), the least friction coefficients μ_C and the critical values."""

from __future__ import annotations

import sympy as sp

from rbdsolve.model.build import Model
from rbdsolve.report.numbers import Meaning, Named
from rbdsolve.solvers.routes.naming import coordinate, criticals, state


def named(question, answers, model: Model) -> tuple[Named, ...]:
    out = [Named(("accelerations", k), coordinate(model, f"ddot({k})")) for k in answers.accelerations]
    out += [Named(("rate_squared", k), coordinate(model, f"dot({k})") ** 2) for k in (getattr(answers, "rate_squared", None) or {})]
    for name, r in (answers.at or {}).items():
        components = r.components if hasattr(r, "components") else r  # the numeric route: component -> value
        path = ("at", name, "components") if hasattr(r, "components") else ("at", name)
        out += [Named((*path, c), sp.Symbol(c), "At the state asked") for c in components]
    at = answers.at or {}
    for name, r in (getattr(answers, "reactions", None) or {}).items():
        if name in at or not hasattr(r, "components"):
            continue  # the state asked names it already; a line is written only where its numbers are known
        out += [Named(("reactions", name, "components", c), sp.Symbol(c), "Forces") for c in r.components]
    along = getattr(answers, "least_friction", None) or {}
    same = {c for c, v in along.items() if not v.has(*(model.to_time(q) for q in model.q))}  # one number all along
    out += [Named(("least_friction_at", c), sp.Symbol(f"mu_{c}"), "At the state asked", Meaning.LEAST)
            for c in (getattr(answers, "least_friction_at", None) or {}) if c not in same]
    out += [Named(("least_friction", c), sp.Symbol(f"mu_{c}"), meaning=Meaning.LEAST) for c in along]
    out += [Named(("there_rate_squared", k), coordinate(model, f"dot({k})") ** 2, "Where the motion gets to")
            for k in (getattr(answers, "there_rate_squared", None) or {})]
    out += [Named(("there", name, "components", c), sp.Symbol(c), "Where the motion gets to")
            for name, r in (getattr(answers, "there", None) or {}).items() for c in r.components]
    out += _first_zeros(getattr(answers, "first_zero", None) or {}, model)
    out += _largest(getattr(answers, "least_friction_over", None) or {}, model)
    if hasattr(answers, "residual"):
        out.append(Named(("residual",), sp.Symbol("residual"), accuracy=True))
    return tuple(out + criticals(("critical",), getattr(answers, "critical", ())))


def _first_zeros(found: dict, model: Model) -> list[Named]:
    """Where each push or tension first reaches zero along the motion, or where the
    motion turns back before it does (a heading each: 'N_C = 0 first at')."""
    out = []
    for name, where in found.items():
        if where.lost_at:
            out.append(Named(("first_zero", name, "lost_at"), state(model, where.lost_at),
                             f"Along the motion, {name} = 0 first at"))
        elif where.turns_at:
            out.append(Named(("first_zero", name, "turns_at"), state(model, where.turns_at),
                             f"Along the motion, {name} > 0 throughout: the motion turns back at"))
    return out


def _largest(found: dict, model: Model) -> list[Named]:
    """Each rolling contact's least μ at its largest over the motion, and where, under a
    heading that says where the motion reached ends (the first zero's line above gives
    the place)."""
    out = []
    for contact, largest in found.items():
        ends = (f"to where {largest.lost} = 0" if largest.lost else
                "to where it turns back" if largest.until else "over a whole turn")
        group = f"Most friction needed over the motion ({ends}), at"
        out += [Named(("least_friction_over", contact, "mu"), sp.Symbol(f"mu_{contact}"), group, Meaning.LEAST),
                Named(("least_friction_over", contact, "at"), state(model, largest.at), group)]
    return out
