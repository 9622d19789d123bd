"""A ladder pushed at its foot (a new user's trial): smooth floor and wall, a horizontal
push P at the foot A towards the wall, released from rest at φ₀ = 50° from the floor. Its
exact route ran out of its 30 s share on two trigonometric equations sympy's solve worked
through for minutes; the numeric route then gave the forces at the release only, not
where the top leaves the wall.

By hand: A = (L cos φ, 0), B = (0, L sin φ), G = (L/2)(cos φ, sin φ); T = m L² φ̇²/6 and
V = m g (L/2) sin φ + P L cos φ (the push −P x̂ at A), so from rest at φ₀
φ̇² = 3 (g m (sin φ₀ − sin φ) + 2 P (cos φ₀ − cos φ))/(m L), φ̈ = 3 (2 P sin φ − g m cos φ)/(2 m L);
Newton along x: N_B − P = m ẍ_G = −m (L/2)(sin φ φ̈ + cos φ φ̇²). N_B at the release is
a quadratic form in sin φ₀, cos φ₀ plus a constant (by the double angle, a quadratic in
tan φ₀); N_B along the motion mixes sin φ and cos φ (a quartic in tan(φ/2)): its zero
is searched numerically."""

from __future__ import annotations

import math

import pytest
from scipy.optimize import brentq

import rbdsolve

LADDER = """\
parameters: {m: mass, L: length, P: push at the foot, phi0: angle at release, g: gravity}
values: {m: 12 kg, L: 3 m, P: 40 N, phi0: 50 deg, g: 9.81 m/s^2}
coordinates: [phi]
gravity: [0, -g]
points:
  A: [L*cos(phi), 0]
  B: [0, L*sin(phi)]
bodies:
  ladder: {shape: rod, mass: m, length: L, at: "L/2*[cos(phi), sin(phi)]", angle: -phi}
forces:
  push: {on: ladder, at: A, force: [-P, 0]}
questions:
  - reactions: {forces: [{at: A, normal: [0, 1]}, {at: B, normal: [1, 0]}], from_rest: {phi: phi0}}
"""
m, L, P, g, PHI0 = 12.0, 3.0, 40.0, 9.81, math.radians(50)


def _wall_push(phi: float) -> float:
    rate2 = 3 * (g * m * (math.sin(PHI0) - math.sin(phi)) + 2 * P * (math.cos(PHI0) - math.cos(phi))) / (m * L)
    accel = 3 * (2 * P * math.sin(phi) - g * m * math.cos(phi)) / (2 * m * L)
    return P - m * L / 2 * (math.sin(phi) * accel + math.cos(phi) * rate2)


@pytest.fixture(scope="module")
def solution(tmp_path_factory):
    path = tmp_path_factory.mktemp("ladder") / "ladder.yaml"
    path.write_text(LADDER, encoding="utf-8")
    (found,) = rbdsolve.solve(path, budget=1200.0)  # a budget far from the work: the route is the structure's
    return found


def test_it_answers_on_the_exact_route(solution) -> None:
    assert solution.error is None and solution.route == "exact"


def test_the_wall_push_at_the_release_is_the_hand_one(solution) -> None:
    assert solution.values["at"]["B"]["components"]["N_B"] == pytest.approx(_wall_push(PHI0), rel=1e-12)


def test_the_top_leaves_the_wall_where_the_hand_push_first_vanishes(solution) -> None:
    # sliding down from φ₀: N_B > 0 at the release, first zero on the way down
    assert _wall_push(PHI0) > 0
    grid = [PHI0 * (1 - k / 2000) for k in range(2000)]
    first = next(i for i in range(1, len(grid)) if _wall_push(grid[i]) <= 0)
    lost = brentq(_wall_push, grid[first], grid[first - 1], xtol=1e-14)
    assert solution.values["first_zero"]["N_B"]["lost_at"]["phi"] == pytest.approx(lost, abs=1e-9)


def test_the_release_angle_where_the_wall_lets_go_is_the_double_angle_s(solution) -> None:
    """N_B(φ₀) = 0 at tan φ₀ = (3 g m ± √(32 P² + 9 g² m²))/(4 P) (by hand from
    (3/4) P cos 2φ₀ + P/4 + (3/8) g m sin 2φ₀ = 0 over cos² φ₀), in (0, π)."""
    root = math.sqrt(32 * P**2 + 9 * (g * m) ** 2)
    hand = sorted([math.atan((3 * g * m + root) / (4 * P)), math.atan((3 * g * m - root) / (4 * P)) + math.pi])
    printed = sorted(c["value"] for c in solution.values["critical"])
    assert printed == pytest.approx(hand, rel=1e-12)
