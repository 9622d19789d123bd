"""model/values/units.py: a coordinate's dimension without writing out the scene's points."""

from __future__ import annotations

from rbdsolve.model.build import build_model
from rbdsolve.model.deferred import Deferred
from rbdsolve.problem import load_text
from rbdsolve.problem.quantities.quantity import NUMBER
from rbdsolve.model.values.units import known_dimensions

SCENE = """\
title: two bobs
parameters: {m: mass, l: length, g: acceleration}
values: {m: 1, l: 1, g: 981/100}
coordinates: [a, b]
gravity: [0, -g]
points:
  P1: l * [sin(a), -cos(a)]
  P2: P1 + l * [sin(2*b), -cos(2*b)]
bodies:
  bob1: {shape: particle, mass: m, at: P1}
  bob2: {shape: particle, mass: m, at: P2}
questions:
  - modes: {about: {a: 0, b: 0}}
"""


def test_angles_read_from_the_points_trees_leave_the_points_unmade() -> None:
    # By hand: a and b enter only as sin and cos of 1·a and 2·b: pure numbers (radians).
    model = build_model(load_text(SCENE, "s.yaml"))
    a, b = model.q
    dims = known_dimensions(model)
    assert dims[a] == NUMBER and dims[b] == NUMBER
    assert not any(Deferred.made(body, "position") for body in model.bodies)
    assert len(model.points) == 2 and not model.points._made  # noqa: SLF001 - nothing folded
