"""A condition on a parameter of either sign, split in its size (conditions.by_size): a
new user's square plate hung from a corner and turned by a couple C of either sign read
"1 − 2 C²/(a² g² m²) ≥ 0" for one equilibrium and "a² g² m² − 2 C² ≥ 0" for the other,
with no critical value; a teacher writes |C| ≤ m g a/√2.

By hand: OG = a/√2, so V = −m g (a/√2) cos θ − C θ and ∂V/∂θ = m g (a/√2) sin θ − C = 0
at sin θ = √2 C/(m g a), which is a place only where |√2 C/(m g a)| ≤ 1, that is
|C| ≤ C_c = m g a/√2 = √2 a g m/2, whatever the sign of C. Sampled on each side of C_c
and of −C_c below.
"""

from __future__ import annotations

import math

import pytest
import sympy as sp

import rbdsolve
from conftest import PLATE_ON_A_CORNER

PLATE = PLATE_ON_A_CORNER.replace("C: moment", "C: {description: moment, positive: false}")


@pytest.fixture(scope="module")
def solution(tmp_path_factory):
    path = tmp_path_factory.mktemp("plate") / "plate.yaml"
    path.write_text(PLATE)
    (found,) = rbdsolve.solve(path, budget=1200.0)  # a budget far from the work
    return found


def test_each_equilibrium_exists_where_the_size_of_the_couple_is_below_its_critical_value(solution) -> None:
    m, a, g = sp.symbols("m a g", positive=True)
    C = sp.Symbol("C", real=True)
    by_hand = sp.Le(sp.Abs(C), sp.sqrt(2) * a * g * m / 2)
    assert len(solution.answers.equilibria) == 2
    for e in solution.answers.equilibria:
        assert e.exists_when == by_hand
    (critical,) = solution.answers.critical
    assert critical.parameter == "C" and sp.simplify(critical.value - m * g * a / sp.sqrt(2)) == 0


@pytest.mark.parametrize("factor", [-1.01, -0.99, 0.99, 1.01])
def test_the_condition_holds_exactly_where_the_equilibrium_is_a_place(solution, factor) -> None:
    """On each side of +C_c and of −C_c: the printed condition against sin θ = √2 C/(m g a)."""
    m, a, g = 2.0, 0.4, 9.81
    c = factor * m * g * a / math.sqrt(2)
    real = abs(math.sqrt(2) * c / (m * g * a)) <= 1
    (e, _) = solution.answers.equilibria
    point = {s: v for s in e.exists_when.free_symbols for v in [{"m": m, "a": a, "g": g, "C": c}[s.name]]}
    assert bool(e.exists_when.xreplace(point)) is real


HOOP = """\
parameters:
  m: mass
  R: radius
  g: gravity
  Omega: {description: rate of the hoop, positive: false}
coordinates: [theta]
gravity: [0, -g, 0]
frames:
  hoop: {axis: y, rate: Omega}
points:
  P: R * [sin(theta)*cos(Omega*t), -cos(theta), -sin(theta)*sin(Omega*t)]
bodies:
  bead: {shape: particle, mass: m, at: P}
questions:
  - equilibria: {frame: hoop, for: Omega}
"""


def test_a_hoop_turning_either_way_holds_the_bead_off_its_axis_where_the_rate_is_fast_enough(tmp_path) -> None:
    """A bead on a hoop (R) turning at Ω of either sense about its vertical diameter, a
    new user's: by hand V' = −m g R cos θ − ½ m Ω² R² sin²θ, ∂V'/∂θ = m R sin θ (g − Ω² R
    cos θ), so cos θ = g/(Ω² R) off the axis, a place only where g/(Ω² R) ≤ 1: |Ω| ≥
    √(g/R), written in Ω as the question's ``for:`` asks (it read R ≥ g/Ω²). Sampled on
    each side of ±Ω_c."""
    path = tmp_path / "hoop.yaml"
    path.write_text(HOOP)
    (solution,) = rbdsolve.solve(path, budget=1200.0)
    R, g = sp.symbols("R g", positive=True)
    Omega = sp.Symbol("Omega", real=True)
    off_axis = [e for e in solution.answers.equilibria if e.exists_when is not sp.true]
    assert len(off_axis) == 2
    for e in off_axis:
        c = e.exists_when
        assert isinstance(c, sp.GreaterThan) and c.lhs == sp.Abs(Omega)
        assert sp.simplify(c.rhs - sp.sqrt(g) / sp.sqrt(R)) == 0
        for factor in (-1.01, -0.99, 0.99, 1.01):
            w = factor * math.sqrt(9.81 / 0.5)
            point = {s: {"R": 0.5, "g": 9.81, "Omega": w}[s.name] for s in e.exists_when.free_symbols}
            assert bool(e.exists_when.xreplace(point)) is (9.81 / (w * w * 0.5) <= 1)
