"""The names the inertia's worked solution prints its answers by (report/numbers.py):
the mass, r_G, the point P and r_P, J_G and J_P, the principal moments Jᵢ and axes eᵢ,
the configuration asked about, the axis e and the moment about it, J_e (or J_P,z about
the normal to the plane of the motion)."""

from __future__ import annotations

import sympy as sp

from rbdsolve.model.build import Model
from rbdsolve.report.numbers import Named
from rbdsolve.solvers.routes.labels import labels_for
from rbdsolve.solvers.routes.naming import state


def named(question, answers, model: Model) -> tuple[Named, ...]:
    opts = question.options
    label = point_label(opts)
    out = [Named(("mass",), labels_for(model, "total_mass").symbol("total_mass"))]
    if hasattr(answers, "J_G"):  # the exact route
        out += [Named(("centre",), sp.Symbol("r_G"))]
        out += [Named(("about",), sp.Symbol(f"r_{label}"))] if opts.about is not None else []
        out += [Named(("at",), state(model, answers.at))] if answers.at else []
        out += [Named(("J_G",), sp.Symbol("J_G"))]
    if opts.about is not None or not hasattr(answers, "J_G"):
        out.append(Named(("J",), sp.Symbol(f"J_{label}")))
    out += [Named(("principal_moments", i), sp.Symbol(f"J_{i + 1}")) for i in range(len(answers.principal_moments))]
    out += [Named(("principal_axes", i), sp.Symbol(f"e_{i + 1}")) for i in range(len(answers.principal_axes))]
    if getattr(answers, "axis", None) is not None:
        out.append(Named(("axis",), sp.Symbol("e")))
    if answers.J_axis is not None:
        out.append(Named(("J_axis",), sp.Symbol("J_e" if opts.axis is not None else f"J_{label},z")))
    return tuple(out)


def point_label(opts) -> str:
    """The name the steps give the point J is about: its own name, P for a vector, G
    for none (solvers/inertia/exact.py)."""
    if opts.about is None:
        return "G"
    return opts.about.text if opts.about.text.isidentifier() else "P"
