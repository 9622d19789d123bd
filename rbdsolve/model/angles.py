"""Which coordinates and parameters of a scene are angles, for how their numbers are
read and shown: a bare value of an angle past a full turn is said (model/summary/scene.py),
and an angle left without a value is noted in rad beside an answer that holds it
(model/values/answers.py). Angles are pure numbers in SI; this reads them from how the
scene writes them, not from a dimension."""

from __future__ import annotations

import sympy as sp

from rbdsolve.model.build import Model
from rbdsolve.model.energies.energy import memoized
from rbdsolve.problem.schema import CoordinateKind
from rbdsolve.problem.usage import angle_terms, state_parameters


@memoized
def angle_coordinates(model: Model) -> frozenset[str]:
    """The names of the coordinates that are angles: declared so, or inside a sine or
    cosine of a position (a disk in a track, placed by its contact at
    (R − r)(sin θ, −cos θ)), periodic or not. It reads every position: once per model,
    though each question's warnings and open units ask."""
    positions = [*model.points.values(), *(b.position for b in model.bodies if b.position is not None)]
    trig = set().union(*(sp.Matrix(p).atoms(sp.sin, sp.cos) for p in positions))
    declared = {c.name for c in model.problem.coordinates if c.kind is CoordinateKind.ANGLE}
    return frozenset(declared | {name for q, name in zip(model.q, model.coordinate_names())
                                 if any(f.has(q) for f in trig)})


def angle_parameters(model: Model, among: frozenset[str]) -> frozenset[str]:
    """Those of the parameters ``among`` that are angles: a term of a sine's argument or
    of an ``angle`` (``problem.usage.angle_terms``: an incline's β), or alone as an angle
    coordinate's value in a state (``from_rest: {theta: theta0}``). The coordinates are
    read (every position) only where a parameter among them is a state's value."""
    written = angle_terms(model.problem) & among
    states = {p: qs for p, qs in state_parameters(model.problem).items() if p in among and p not in written}
    coordinates = angle_coordinates(model) if states else frozenset()
    return written | {p for p, qs in states.items() if qs & coordinates}
