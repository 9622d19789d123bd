"""A spring's length |u| is written ±u by u's sign over the coordinate's declared range
first, and at the reference configuration (every coordinate 0) only where that lies
inside the range (a new user's trial: two springs drawn upside down at q = 0 gave
equilibria outside the range, printed as if right).

By hand:
- a block (mass m, its top face a/2 above its centre) hangs by that face from a ceiling
  point on a spring (k, natural length L0), y the centre's depth, range [0, 5]: the
  length is y − a/2, and m g = k (y − a/2 − L0) at rest, y = a/2 + L0 + m g/k = 0.6481
  m at a = 0.1, L0 = 0.5, m = 1, k = 100, g = 9.81 (rbdsolve took a/2 − y, positive at
  y = 0, and printed y = −0.3519 m);
- a rod (m, l) sliding in a tube turning at Ω, its inner end x − l/2 from the axis
  tied there by a spring (k, L0), x in [l/2, 10]: in the turning frame k (x − l/2 − L0)
  = m Ω² x, so x = k (l/2 + L0)/(k − m Ω²) = 0.416667 m at m = 0.2, l = 0.1, k = 50,
  L0 = 0.2, Ω = 10 (rbdsolve took l/2 − x, its sign at x = 0, outside the range, and
  printed x = −0.25 m)."""

from __future__ import annotations

import pytest

from conftest import solved_scene

HUNG = """\
parameters: [m, a, k, L0, g]
values: {m: 1 kg, a: 10 cm, k: 100 N/m, L0: 50 cm, g: 9.81 m/s^2}
coordinates:
  y: {kind: length, range: [0, 5]}
gravity: [0, -g]
points:
  O: [0, 0]
  G: [0, -y]
  A: G + [0, a/2]
bodies:
  block: {shape: particle, mass: m, at: G}
springs:
  s: {stiffness: k, between: [O, A], natural_length: L0}
questions:
  - equilibria
"""

TUBE = """\
parameters: [m, l, k, L0, Omega]
values: {m: 0.2 kg, l: 10 cm, k: 50 N/m, L0: 20 cm, Omega: 10 rad/s}
coordinates:
  x: {kind: length, range: [l/2, 10]}
frames:
  table: {axis: z, rate: Omega}
points:
  O: [0, 0, 0]
  G: x*[cos(Omega*t), sin(Omega*t), 0]
  A: (x - l/2)*[cos(Omega*t), sin(Omega*t), 0]
bodies:
  rod: {shape: rod, mass: m, length: l, at: G, angle: Omega*t}
springs:
  s: {stiffness: k, between: [O, A], natural_length: L0}
questions:
  - equilibria: {frame: table}
"""


@pytest.mark.parametrize("text, name, expected, route", [
    (HUNG, "y", 0.05 + 0.5 + 9.81 / 100, "numeric"),  # |y − a/2| kept: y = a/2 lies inside [0, 5]
    (TUBE, "x", 50 * (0.05 + 0.2) / (50 - 0.2 * 100), "exact"),  # x − l/2 ≥ 0 over [l/2, 10] at l = 10 cm
])
def test_the_equilibrium_is_the_one_on_the_spring_s_drawn_side(tmp_path, text: str, name: str, expected: float,
                                                                 route: str) -> None:
    solution = solved_scene(tmp_path, text)
    assert solution.solved and solution.route == route
    places = [e["at"][name] for e in solution.values["equilibria"]]
    assert places == [pytest.approx(expected, rel=1e-9)]


@pytest.mark.parametrize("rate", [3.0, 12.0, 20.0])
def test_with_the_rate_open_the_tube_s_equilibrium_is_exact(tmp_path, rate: float) -> None:
    """x = k (l/2 + L0)/(k − m Ω²), which exists (x ≥ l/2) only where Ω < √(k/m) = 15.8
    rad/s: its condition sampled on both sides of that Ω_c, the place below it."""
    solution = solved_scene(tmp_path, TUBE.replace(", Omega: 10 rad/s", ""))
    assert solution.solved and solution.route == "exact"
    (equilibrium,) = solution.answers.equilibria
    (x,) = equilibrium.at.values()
    given = {"m": 0.2, "l": 0.1, "k": 50, "L0": 0.2, "Omega": rate}
    at = {s: given[s.name] for s in x.free_symbols}
    exists = bool(equilibrium.exists_when.subs({s: given[s.name] for s in equilibrium.exists_when.free_symbols}))
    assert exists is (rate < (50 / 0.2) ** 0.5)
    if exists:
        assert float(x.subs(at)) == pytest.approx(50 * (0.05 + 0.2) / (50 - 0.2 * rate**2), rel=1e-12)
    (critical,) = solution.answers.critical
    assert float(critical.value.subs({s: given[s.name] for s in critical.value.free_symbols})) == pytest.approx(
        (50 / 0.2) ** 0.5, rel=1e-12)
