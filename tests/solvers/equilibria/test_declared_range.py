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


COLLAR = """\
parameters: [m, k, L0, d, g]
values: {m: 0.5 kg, k: 40 N/m, L0: 50 cm, g: 9.81 m/s^2}
coordinates:
  s: {kind: length, range: [0, 4*L0]}
gravity: [0, -g]
points:
  A: [0, -d]
  P: [s, 0]
bodies:
  collar: {shape: particle, mass: m, at: P}
springs:
  spring: {stiffness: k, between: [P, A], natural_length: L0}
questions:
  - equilibria
"""


@pytest.mark.parametrize("depth", [0.1, 0.3, 0.45])
def test_with_a_parameter_open_the_range_still_holds(tmp_path, depth: float) -> None:
    """A collar on a horizontal rod with a stop at s = 0 (s in [0, 4 L₀]), on a spring
    (k, L₀) to A, d below the rod, d left open (a new user's trial). By hand V = ½ k
    (√(d² + s²) − L₀)², ∂V/∂s = k (√(d² + s²) − L₀) s/√(d² + s²): s = 0 and s = ±√(L₀² −
    d²), the minus one below the stop wherever it exists (d < L₀); it was listed, stable,
    with its frequency. Sampled at three depths below L₀."""
    solution = solved_scene(tmp_path, COLLAR, "collar.yaml")
    places = []
    for e in solution.answers.equilibria:
        (s,) = e.at.values()
        places.append(float(s.subs({x: {"L0": 0.5, "d": depth}[x.name] for x in s.free_symbols})))
    assert sorted(places) == pytest.approx([0.0, (0.25 - depth**2) ** 0.5], abs=1e-12)
    assert len([w for w in solution.warnings if "outside the range declared for s" in w]) == 1
