"""The scene at the configuration an inertia question asks about (``at: {theta: …}``).

A body that moves with the coordinates has a tensor that is a formula in them; asked
at one configuration, the coordinates are put in before anything else, so that the
parallel axis theorem, the principal moments and their axes are found for that one
tensor (compact, and defined where the general formula divides by zero).
"""

from __future__ import annotations

from dataclasses import replace

import sympy as sp

from rbdsolve.model.build import Model
from rbdsolve.problem.options import InertiaOptions


def substitution(opts: InertiaOptions, model: Model) -> dict[sp.Symbol, sp.Expr]:
    """q -> its value in ``at`` (the coordinates it leaves out stay symbols)."""
    index = {name: k for k, name in enumerate(model.state.names)}
    return {model.q[index[name]]: model.symbols.scalar(value) for name, value in opts.at}


def at_configuration(model: Model, at: dict[sp.Symbol, sp.Expr]) -> Model:
    """The model with the coordinates put in: points, bodies' centres and rotations."""
    if not at:
        return model

    def put(m: sp.Matrix | None) -> sp.Matrix | None:
        return None if m is None else m.xreplace(at)

    bodies = tuple(replace(b, position=put(b.position), rotation=put(b.rotation),
                           angle=b.angle.xreplace(at) if b.angle is not None else None) for b in model.bodies)
    return replace(model, points={k: put(v) for k, v in model.points.items()}, bodies=bodies)


def about_point(opts: InertiaOptions, model: Model, at: dict[sp.Symbol, sp.Expr]) -> sp.Matrix:
    """The point asked about, at the configuration: a point, a position, or a contact's
    point C (where a rolling body touches: model/constraints/contacts.py)."""
    contacts = {c.name: c.point for c in model.contacts}
    names = model.symbols.with_points({**model.points, **contacts})
    return names.vector(opts.about).xreplace(at)
