"""The exact route keeps to a coordinate's declared range, as the numeric route's search
does: a block (m) hung on a spring (k, natural length L0) from a point above it, y its
depth. By hand, k (y − L0) = m g at rest, y = L0 + m g/k = 0.5981 m at m = 1 kg,
k = 100 N/m, L0 = 0.5 m: inside [0.5, 5], listed; outside [0.7, 5], said and not listed
(the exact route listed it whatever the range; the numeric route found none)."""

from __future__ import annotations

import pytest

from conftest import solved_scene

HUNG = """\
parameters: [m, k, L0, g]
values: {m: 1 kg, k: 100 N/m, L0: 50 cm, g: 9.81 m/s^2}
coordinates:
  y: {kind: length, range: [LOW, 5]}
gravity: [0, -g]
points:
  O: [0, 0]
  G: [0, -y]
bodies:
  block: {shape: particle, mass: m, at: G}
springs:
  s: {stiffness: k, between: [O, G], natural_length: L0}
questions:
  - equilibria
"""


@pytest.mark.parametrize("low, listed", [("0.5", [0.5 + 9.81 / 100]), ("0.7", [])])
def test_an_equilibrium_outside_the_range_is_said_and_not_listed(tmp_path, low: str, listed: list) -> None:
    solution = solved_scene(tmp_path, HUNG.replace("LOW", low), "hung.yaml")
    assert solution.solved and solution.route == "exact"
    assert [e["at"]["y"] for e in solution.values.get("equilibria", [])] == pytest.approx(listed, rel=1e-12)
    said = [w for w in solution.warnings if "outside the range declared for y" in w]
    assert len(said) == (0 if listed else 1)
