"""Units an answer's meaning fixes (model/values/fixed_units.py). By hand: with q an
angle (a pure number), ∂²V/∂q² is J/rad² = N·m/rad; ∂V/∂q is N·m; M over two angles is
kg·m²; over a length and an angle kg·m; q̈ of an angle rad/s²."""

from __future__ import annotations

from fractions import Fraction

import pytest

from rbdsolve.problem.quantities.quantity import LENGTH, NUMBER, Dimension
from rbdsolve.model.values.fixed_units import fixed_unit, pair_unit, per_radians, rate_unit

TIME = Dimension(time=Fraction(1))
ENERGY = Dimension(mass=Fraction(1)) * LENGTH ** 2 / TIME ** 2


def test_stiffness_and_mass_entries_per_the_coordinates() -> None:
    assert pair_unit("K", NUMBER, NUMBER) == "N·m/rad"
    assert pair_unit("K", LENGTH, LENGTH) == (ENERGY / LENGTH ** 2).unit  # N/m, kg/s²
    assert pair_unit("K", LENGTH, NUMBER) == "N/rad"
    assert pair_unit("M", NUMBER, NUMBER) == "kg·m²"
    assert pair_unit("M", LENGTH, NUMBER) == "kg·m"
    assert pair_unit("K", None, NUMBER) is None


def test_a_torque_is_not_an_energy() -> None:
    assert per_radians(ENERGY, 1) == "N·m"
    assert per_radians(ENERGY, 0) == ENERGY.unit  # J
    assert fixed_unit("reactions", ("at", "O", "components", "M_O"), {"theta": NUMBER}) == "N·m"


def test_a_support_force_is_in_newtons_at_a_given_state_too() -> None:
    """N_C at θ = 0, θ̇ = 8 reads −R k + 64 R m + g m …: the 64 (θ̇² put in) carries no
    1/s² to read, so the sum mixes dimensions; a force is in N by what it is."""
    assert fixed_unit("reactions", ("at", "C", "components", "N_C"), {"theta": NUMBER}) == "N"
    assert fixed_unit("reactions", ("at", "C", "force", 1), {"theta": NUMBER}) == "N"
    assert fixed_unit("steady_motion", ("reactions", "C", "components", "F_C"), {}) == "N"


def test_rates_of_an_angle() -> None:
    assert rate_unit(NUMBER, 1) == "rad/s" and rate_unit(NUMBER, 2) == "rad/s²"
    assert rate_unit(LENGTH, 2) == (LENGTH / TIME ** 2).unit
    assert fixed_unit("eom", ("accelerations", "theta"), {"theta": NUMBER}) == "rad/s²"
    assert fixed_unit("eom", ("accelerations", "x"), {"x": LENGTH}) == (LENGTH / TIME ** 2).unit


def test_an_angular_impulse_and_a_growth_rate() -> None:
    assert fixed_unit("impact", ("impulses", "theta"), {"theta": NUMBER}) == "N·m·s"
    assert fixed_unit("modes", ("growth_rates", 0), {"theta": NUMBER}) == "1/s"


def test_a_small_oscillation_frequency_is_in_radians_per_second_whatever_the_parameters() -> None:
    """ω = √λ with λ in 1/s²: rad/s even where its expression holds a parameter given as a
    bare number (a frame's rate Ω = 8.9 set on the command line), as the numeric route's."""
    assert fixed_unit("modes", ("about", 0, "frequencies", 0), {"theta": NUMBER}) == "rad/s"
    assert fixed_unit("modes", ("about", 0, "eigenvalues", 0), {"theta": NUMBER}) == "1/s²"


BLOCK_ON_INCLINE = """\
parameters: {m: mass, g: acceleration, alpha: angle of the incline}
values: {m: 2 kg, g: 9.81 m/s^2, alpha: 30 deg}
coordinates: {x: length}
gravity: [0, -g]
points:
  P: x*[cos(alpha), -sin(alpha)]
bodies:
  block: {shape: particle, mass: m, at: P}
questions:
  - energy: {from_rest: {x: 0}, to: {x: 50 cm}, points: [block]}
"""


def test_a_speed_where_the_motion_gets_to_is_in_metres_per_second(tmp_path) -> None:
    """A block slides 50 cm down a smooth 30° incline from rest: by hand v² = 2 g x sin α
    = 4.905 m²/s², v = 2.21472 m/s. The 50 cm is put in as 1/2, a pure number, so the
    expression alone read m^½/s (a new user's spool on an incline); a speed is in m/s by
    what it is, and the place it gets to in the coordinate's unit."""
    import json

    from click.testing import CliRunner

    from rbdsolve.cli import main

    path = tmp_path / "block.yaml"
    path.write_text(BLOCK_ON_INCLINE, encoding="utf-8")
    result = CliRunner().invoke(main, ["solve", str(path), "--format", "json"])
    found = json.loads(result.stdout)["results"][0]
    assert found["units"]["to"] == {"x": "m"}
    assert found["units"]["there"]["speed"] == {"block": "m/s"}
    assert found["units"]["speed_squared"] == {"block": "m²/s²"}
    assert abs(found["values"]["there"]["speed"]["block"] - 2.21472) < 1e-5


PENDULUM_RELEASED = """\
parameters: {m: mass, l: length, g: acceleration}
values: {m: 2 kg, l: 50 cm, g: 9.81 m/s^2}
coordinates: [theta]
gravity: [0, -g]
points:
  O: [0, 0]
  P: l*[sin(theta), -cos(theta)]
bodies:
  bob: {shape: particle, mass: m, at: P}
questions:
  - reactions: {forces: [O], from_rest: {theta: 60 deg}}
"""


def test_the_numeric_route_s_forces_at_a_state_are_in_newtons(tmp_path) -> None:
    """A bob on a light rod released from rest at 60°: by hand the rod pulls it towards O
    with m g cos θ = 9.81 N (no speed yet, so no centripetal part), and no moment. The
    numeric route's numbers at the state have no expression to read a dimension from:
    a push is in N and a moment in N·m by what it is (it printed 'N_O = 9.81 N' on the
    exact route and 'N_O = 9.81' on the numeric one)."""
    import json

    from click.testing import CliRunner

    from rbdsolve.cli import main

    path = tmp_path / "pendulum.yaml"
    path.write_text(PENDULUM_RELEASED, encoding="utf-8")
    result = CliRunner().invoke(main, ["solve", str(path), "--format", "json", "--route", "numeric"])
    found = json.loads(result.stdout)["results"][0]
    assert found["route"] == "numeric"
    assert found["units"]["at"]["O"] == {"N_O": "N", "M_O": "N·m"}
    assert found["values"]["at"]["O"]["N_O"] == pytest.approx(9.81, rel=1e-12)
    assert found["values"]["at"]["O"]["M_O"] == pytest.approx(0, abs=1e-12)
