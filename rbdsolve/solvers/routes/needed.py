"""Which values floating-point work needs: the parameters a question's answer can
depend on (T, V, the given velocities, what the question names), those of them without
a value, the refusal that names them, and the model with the others filled by a
placeholder that the answer never sees.

Used by routes.py (whether the numeric route may follow the exact one, and the model
the numeric route receives) and by every family's numeric route (``require_values``)."""

from __future__ import annotations

import dataclasses

import sympy as sp

from rbdsolve.errors import UnsolvedError
from rbdsolve.problem.expr import Expr


def missing_values(model, free: tuple[str, ...] = ()) -> tuple[str, ...]:
    """The parameters without a numeric value, in the file's order, except those in
    ``free`` (a route's own unknowns: steady_motion solves for omega0)."""
    return tuple(p.name for p in model.problem.parameters
                 if p.name not in free and model.symbols.parameters[p.name] not in model.values)


def missing_for(model, question, free: tuple[str, ...] = ()) -> tuple[str, ...]:
    """The parameters without a value that the question's answer depends on
    (``relevant_parameters``): floating-point work needs none of them missing."""
    relevant = relevant_parameters(model, question)
    return tuple(n for n in missing_values(model, free) if model.symbols.parameters[n] in relevant)


def require_values(model, what: str, free: tuple[str, ...] = ()) -> None:
    """Refuse floating-point work while ``missing_values`` is not empty, naming them (a
    route called through ``routes`` gets a model whose irrelevant parameters are filled,
    ``with_irrelevant_filled``, so only the ones that matter are named)."""
    missing = missing_values(model, free)
    if missing:
        raise UnsolvedError(f"{what} needs a value for every parameter the answer depends on"
                            f"{_except(free)}; give {', '.join(missing)} ('values:' in the file, or "
                            "--set NAME=VALUE)")


def _except(free: tuple[str, ...]) -> str:
    return f" except {', '.join(free)} (solved for)" if free else ""


PLACEHOLDER = sp.Integer(1)


def with_irrelevant_filled(model, question):
    """The model with PLACEHOLDER for each parameter that has no value and that the
    question's answer cannot depend on (a yo-yo axle's length in a planar motion): the
    floating-point machinery evaluates every ingredient, the answer never sees these."""
    if all(s in model.values for s in model.symbols.parameters.values()):
        return model  # nothing to fill (and no need to read every body for what is relevant)
    relevant = relevant_parameters(model, question)
    filler = {s: PLACEHOLDER for s in model.symbols.parameters.values()
              if s not in model.values and s not in relevant}
    return dataclasses.replace(model, values={**model.values, **filler}) if filler else model


def relevant_parameters(model, question) -> frozenset[sp.Symbol]:
    """The parameters T, V, the applied loads, the given velocities and the question
    itself can depend on.

    Per body: its mass, r_G, rotation and the entries (R J_G Rᵀ)_ij that ω·(R J_G Rᵀ)ω
    can reach, i, j over the axes ω may have a component on (a planar angle: J_zz only,
    so a cylinder's length does not count in a planar motion); springs, gravity and the
    inertial potentials of a moving frame; plus whatever the question names (a
    parameter, a point's position, a body in full, a frame's motion).
    """
    parts: list = [*(s.stiffness for s in model.springs), *(s.stretch for s in model.springs),
                   *(x.value for x in model.inertial), *(x.value for x in model.gyroscopic),
                   *model.velocities.values()]
    parts += [model.gravity] if model.gravity is not None else []
    for load in model.loads:  # an applied force's or couple's size and place (a couple M₀ filled with 1 was silent)
        parts += [load.force, load.moment, load.point, *load.generalized]
    for body in model.bodies:
        parts += _body_ingredients(body)
    parts += _named_by(question, model)
    params = set(model.symbols.parameters.values())
    return frozenset(s for part in parts for s in sp.sympify(part).free_symbols if s in params)


def _body_ingredients(body, whole: bool = False) -> list:
    """What of a body T and V read (``whole``: everything, for a question about it)."""
    out = [body.mass, body.rotation]
    out += [x for x in (body.position, body.given_velocity, body.given_angular_velocity) if x is not None]
    if whole or body.turns_3d:
        return [*out, body.inertia]
    if body.given_angular_velocity is not None:
        axes = [i for i in range(3) if body.given_angular_velocity[i] != 0]
    else:
        axes = [2] if body.angle is not None else []
    J = body.inertia_in_scene() if axes else None
    return out + [J[i, j] for i in axes for j in axes]


def _named_by(question, model) -> list:
    """The sympy objects behind every name in the question: parameters as themselves,
    points by their positions, bodies whole, frames by their origin, axis and rate."""
    bodies = {b.name: b for b in model.bodies}
    out: list = []
    for name in _names_in(question.options):
        if name in model.symbols.parameters:
            out.append(model.symbols.parameters[name])
        elif name in model.points:
            out.append(model.points[name])
        elif name in model.body_points and name not in bodies:
            out.append(model.body_points[name])
        elif name in bodies:
            out += _body_ingredients(bodies[name], whole=True)
        elif any(f.name == name for f in model.problem.frames):
            frame = model.problem.frame(name)
            out += [model.symbols.parameters[n] for x in (frame.origin, frame.axis, frame.rate)
                    if x is not None for n in x.names() if n in model.symbols.parameters]
    return out


def _names_in(value: object):
    """Every name a question's options hold: the names in its expressions, and its plain
    strings (a body, a point, a frame)."""
    if isinstance(value, Expr):
        yield from value.names()
    elif isinstance(value, str):
        yield value
    elif dataclasses.is_dataclass(value) and not isinstance(value, type):
        for f in dataclasses.fields(value):
            yield from _names_in(getattr(value, f.name))
    elif isinstance(value, (tuple, list, frozenset)):
        for item in value:
            yield from _names_in(item)
