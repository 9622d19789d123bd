"""Where a push first reaches zero along the motion, with the parameters that only scale
it left open (a new user's ladder). A uniform rod AB (mass m, length L) with A on a
smooth floor and B on a smooth wall, φ its angle to the floor, released from rest at φ₀.
By hand (energy, then Newton for G):

    φ̇² = 3 g (sin φ₀ − sin φ)/L,   N_B = ¾ m g cos φ (3 sin φ − 2 sin φ₀),

so B leaves the wall where sin φ = ⅔ sin φ₀, the first zero of N_B on the way down from
φ₀ (cos φ > 0 until then): φ = asin(1/√3) = 0.6154797 rad at φ₀ = 60°, whatever m, L
and g. With only φ₀ given, rbdsolve gave no place; now it gives the one it gives with
every value.
"""

from __future__ import annotations

import math

import pytest

import rbdsolve

LADDER = """\
parameters: [m, L, phi0, g]
values: {VALUES}
coordinates: [phi]
gravity: [0, -g]
points:
  A: [L*cos(phi), 0]
  B: [0, L*sin(phi)]
bodies:
  rod: {shape: rod, mass: m, length: L, at: "L/2*[cos(phi), sin(phi)]", angle: -phi}
questions:
  - reactions: {forces: [{at: A, normal: [0, 1]}, {at: B, normal: [1, 0]}], from_rest: {phi: phi0}}
"""


@pytest.mark.parametrize("values", ["{phi0: 60 deg}", "{phi0: 60 deg, m: 2, L: 3, g: 9.81}"])
def test_the_ladder_leaves_the_wall_where_sin_phi_is_two_thirds_of_sin_phi0(tmp_path, values) -> None:
    path = tmp_path / "ladder.yaml"
    path.write_text(LADDER.replace("{VALUES}", values))
    (solution,) = rbdsolve.solve(path, budget=1200.0)  # a budget far from the work
    found = solution.answers.first_zero
    assert found["N_B"].lost_at["phi"] == pytest.approx(math.asin(2 / 3 * math.sin(math.pi / 3)), abs=1e-9)
    assert "N_A" not in found or found["N_A"].lost_at is None  # the floor pushes all the way


def test_a_parameter_that_moves_the_place_leaves_it_open(tmp_path) -> None:
    """φ₀ open: the place asin(⅔ sin φ₀) depends on it, so no number is given."""
    path = tmp_path / "ladder.yaml"
    path.write_text(LADDER.replace("{VALUES}", "{m: 2}"))
    (solution,) = rbdsolve.solve(path, budget=1200.0)
    assert solution.answers.first_zero is None
