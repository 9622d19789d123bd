"""A winding angle held by a torsional spring is searched wide enough for every
equilibrium (solvers/numeric/search_box.py, ``_held_by_torsion``). Found by the oracle
(seed 2034, scene 72): a body pivoted at O, G at d from it, upright at θ = 0, with a
weak torsional spring (c = 0.5 N m/rad, rest π/4): V = m g d cos θ + ½ c (θ − π/4)²,
so ∂V/∂θ = c (θ − π/4) − m g d sin θ = 0 needs |θ − π/4| ≤ m g d/c = 78.48 (by hand),
and the ±10π searched before missed the equilibria past it (θ = −77.0929, stable)."""

from __future__ import annotations

import math

from scipy.optimize import brentq

from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.solvers import Options, RouteChoice, solve_problem

BODY = """
parameters: {m: mass, d: length, kG: length, g: gravity, c: torsional stiffness}
values: {m: 2 kg, d: 2, kG: 1.2 m, g: 9.81, c: 1/2}
coordinates: [theta]
gravity: [0, -g]
points:
  G: d * [sin(theta), cos(theta)]
bodies:
  body: {mass: m, inertia: "m*kG**2", at: G, angle: -theta}
springs:
  s: {stiffness: c, angle: theta, rest: pi/4}
questions: [equilibria]
"""


def _by_hand() -> list[float]:
    """The roots of c (θ − π/4) − m g d sin θ, by sign changes on a fine grid over the
    bound and brentq."""
    c, mgd = 0.5, 2 * 9.81 * 2
    f = lambda x: c * (x - math.pi / 4) - mgd * math.sin(x)  # noqa: E731
    reach = mgd / c + 1
    grid = [math.pi / 4 - reach + 2 * reach * k / 200000 for k in range(200001)]
    return [brentq(f, a, b, xtol=1e-13) for a, b in zip(grid, grid[1:]) if f(a) * f(b) < 0]


def test_every_equilibrium_is_found_out_to_the_bound() -> None:
    (solution,) = solve_problem(build_model(load_text(BODY, "body.yaml")), Options(route=RouteChoice.NUMERIC)).solutions
    found = sorted(e.at["theta"] for e in solution.answers.equilibria)
    hand = _by_hand()
    assert len(hand) == 51 and min(hand) < -77
    assert len(found) == len(hand)
    assert all(abs(a - b) <= 1e-9 * max(1.0, abs(b)) for a, b in zip(found, hand))
