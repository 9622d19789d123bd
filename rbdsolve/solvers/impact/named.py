"""The names the impact's worked solution prints its answers by (report/numbers.py):
I_q, q̇_f, v_P and u_P just after, λ_A, P_P, e_P, Tᵢ, T_f, Tᵢ − T_f and the fraction
lost, P_supports, and the parameter a centre of percussion solves for."""

from __future__ import annotations

import sympy as sp

from rbdsolve.model.build import Model
from rbdsolve.model.state import t
from rbdsolve.report.numbers import Meaning, Named
from rbdsolve.solvers.routes.naming import per_coordinate

T_I, T_F = sp.Symbol("T_i"), sp.Symbol("T_f")


def named(question, answers, model: Model) -> tuple[Named, ...]:
    out = per_coordinate(model, ("impulses",), answers.impulses, lambda k, q: sp.Symbol(f"I_{k}"))
    out += [Named(("velocities", k), sp.Derivative(sp.Function(f"{k}_f", real=True)(t), t)) for k in answers.velocities]
    out += [Named(("points", p), sp.Symbol(f"v_{p}")) for p in answers.points]
    out += [Named(("particles", p), sp.Symbol(f"u_{p}")) for p in answers.particles]
    out += [Named(("contact_impulses", p), sp.Symbol(f"lamda_{p}")) for p in answers.contact_impulses]
    out += [Named(("sticking_impulses", p), sp.Symbol(f"P_{p}")) for p in answers.sticking_impulses]
    out += [Named(("restitution", p), sp.Symbol(f"e_{p}")) for p in answers.restitution]
    out += [Named(("energy_before",), T_I), Named(("energy_after",), T_F),
            Named(("energy_lost",), T_I - T_F, meaning=Meaning.ENERGY_LOST),
            Named(("energy_fraction",), (T_I - T_F) / T_I, meaning=Meaning.FRACTION),
            Named(("support_impulse",), sp.Symbol("P_supports"))]
    centre = getattr(question.options, "centre_of_percussion", None)
    if centre:
        out.append(Named(("centre_of_percussion",), sp.Symbol(centre)))
    return tuple(out)
