"""A parameter that multiplies t in an angle is a rate (1/s, printed rad/s), as its unit
would say: a new user's disk on a tilted axle, spun by [z, s*t] and precessing at Ω
(solved for), with s = 200 given bare, printed "Ω = 4.26508" with no unit beside
"s_c = 108.499 rad/s", and wrote the open s's frequencies "(in rad/s, s in SI units)".

The values are the user's, from their own Newton–Euler about the pivot: the disk (m,
radius r) at L along the axle at θ from the upward vertical, A = m r²/4 + m L² and
C = m r²/2 about O; with ω = Ω e_z + s e₃ in the precessing triad, dH/dt = Ω e_z × H
balances L e₃ × (−m g e_z): (C − A) cos θ Ω² + C s Ω − m g L = 0 (per sin θ), two roots
4.26508 and 49.0683 rad/s at s = 200 rad/s."""

from __future__ import annotations

import math

import pytest

from rbdsolve.problem import load_text
from rbdsolve.problem.quantities.quantity import Dimension

from conftest import PROBLEMS, solved_scene

RATE = Dimension(time=-1)

TOP = """\
parameters: [m, r, L, g, theta, s, Omega]
values: {m: 1 kg, r: 5 cm, L: 10 cm, g: 9.81 m/s^2, theta: 60 deg, s: 200}
gravity: [0, 0, -g]
triads:
  T: {turns: [[z, Omega*t], [x, theta]], vectors: [e1, e2, e3]}
points:
  O: [0, 0, 0]
bodies:
  disk: {shape: disk, mass: m, radius: r, at: L*e3, orientation: [T, [z, s*t]]}
questions:
  - steady_motion: {about: O, solve_for: Omega, for: s}
"""


def _precession_roots() -> list[float]:
    m, r, L, g, theta, s = 1.0, 0.05, 0.1, 9.81, math.pi / 3, 200.0
    A, C = m * r**2 / 4 + m * L**2, m * r**2 / 2
    a, b, c = (C - A) * math.cos(theta), C * s, -m * g * L
    root = math.sqrt(b * b - 4 * a * c)
    return sorted([(-b + root) / (2 * a), (-b - root) / (2 * a)])


def test_a_turn_by_a_parameter_times_t_makes_it_a_rate() -> None:
    dimensions = dict(load_text(TOP, "top.yaml").dimensions)
    assert dimensions["Omega"] == RATE and dimensions["s"] == RATE


def test_the_precession_rates_are_printed_in_rad_per_s(tmp_path) -> None:
    solution = solved_scene(tmp_path, TOP, "top.yaml")
    found = sorted(b["solved"]["Omega"] for b in solution.values["branches"])
    assert found == pytest.approx(_precession_roots(), rel=1e-9)
    assert [b["solved"]["Omega"] for b in solution.units["branches"]] == ["rad/s", "rad/s"]


@pytest.mark.parametrize("scene, rates", [
    # a frame's rate, and a pivot driven as a sin(w t): rates
    ("frames: {F: {axis: z, rate: W}}\npoints: {P: [a*sin(w*t), 0]}", {"W", "w"}),
    # v0 t in a position is a length, not an angle: no rate
    ("points: {P: [v0*t, 0]}", set()),
])
def test_where_a_parameter_times_t_is_an_angle(scene: str, rates: set[str]) -> None:
    text = f"""\
parameters: [W, w, a, v0, m]
coordinates: [x]
{scene}
bodies:
  b: {{shape: particle, mass: m, at: [x, 0]}}
questions: [eom]
"""
    dimensions = dict(load_text(text, "s.yaml").dimensions)
    assert {name for name, d in dimensions.items() if d == RATE} == rates


STRUCK = """\
parameters: [m, r, v0]
values: {m: 2 kg, r: 10 cm}
coordinates: [x]
points:
  C: [x, r]
bodies:
  disk: {shape: particle, mass: m, at: C}
questions:
  - kinematics: {points: [C], at: {x: 0, dot(x): v0}}
"""


def test_a_parameter_alone_as_a_state_s_rate_is_that_rate(tmp_path) -> None:
    """A point moving with x at ẋ = v0 (v0 left open): its velocity (v0, 0, 0) is
    written "(in m/s, v₀ in m/s)", the rate of a length, not "v₀ in SI units"."""
    solution = solved_scene(tmp_path, STRUCK, "struck.yaml")
    (line,) = [x for x in solution.solution.numbers if str(x.relation.lhs) == "v_C"]
    assert line.unit == "m/s" and line.note.open == ("v0", "m/s")


def test_a_rate_given_a_length_is_bad_input_that_names_where_it_is_a_rate() -> None:
    """A frame's rate is a rate: `Omega: 3 m` is refused at its place, saying why."""
    from rbdsolve.errors import InputError

    text = (PROBLEMS / "edges" / "rotating-hoop-critical.yaml").read_text(encoding="utf-8")
    with pytest.raises(InputError, match=r"'Omega' is a rate \(1/s\) \(frames\.hoop\.rate\), found '3 m', a length"):
        load_text(text.replace("Omega: 3}", "Omega: 3 m}"), "hoop.yaml")
