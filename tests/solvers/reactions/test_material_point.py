"""A support at a moving point holds the body's own point there: a body whose angle
turns the other way from its points is refused, not answered with wrong forces."""

import pytest

from rbdsolve.api import loads
from rbdsolve.errors import InputError
from rbdsolve.model.build import build_model
from rbdsolve.solvers import solve_question

LADDER = """
title: A ladder on a smooth wall and floor
parameters: {m: mass, L: length, g: gravity, theta0: angle}
values: {m: 20 kg, L: 3 m, g: 9.81 m/s^2, theta0: 20 deg}
coordinates: [theta]
gravity: [0, -g]
points:
  A: [L*sin(theta), 0]
  B: [0, L*cos(theta)]
  G: L/2 * [sin(theta), cos(theta)]
bodies:
  ladder: {shape: rod, mass: m, length: L, at: G, angle: ANGLE, axis: y}
questions:
  - reactions: {forces: [{at: A, normal: [0, 1]}, {at: B, normal: [1, 0]}], from_rest: {theta: theta0}}
"""


def _reactions(angle: str):
    model = build_model(loads(LADDER.replace("ANGLE", angle)))
    return solve_question(model.problem.questions[0], model)


def test_a_ladder_turned_the_other_way_from_its_ends_is_refused_with_the_reason():
    # A → B is (−sin θ, cos θ): the rod's y axis turned by +θ; −θ turns its ends the other way
    with pytest.raises(InputError, match="'A' moves, but not with body 'ladder'.*the other way round"):
        _reactions("-theta")


def test_the_ladder_turned_with_its_ends_is_answered():
    # by hand: T = ½ (m L²/3) θ̇² about the instant centre, V = m g (L/2) cos θ, so
    # θ̈ = 3 g sin θ/(2 L); from rest a_G = (L/2) θ̈ (cos θ, −sin θ), so the wall's push
    # N_B = (3/4) m g sin θ₀ cos θ₀ and the floor's N_A = m g (1 − (3/4) sin² θ₀)
    import math

    solution = _reactions("theta")
    assert solution.error is None
    values = solution.values["at"]
    s, c = math.sin(math.radians(20)), math.cos(math.radians(20))
    assert math.isclose(values["B"]["components"]["N_B"], 0.75 * 20 * 9.81 * s * c, rel_tol=1e-12)
    assert math.isclose(values["A"]["components"]["N_A"], 20 * 9.81 * (1 - 0.75 * s * s), rel_tol=1e-12)
