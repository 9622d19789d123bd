"""A singular K of one coordinate: V's first nonzero derivative past the second decides
(equilibria/higher_order.py). A bob of mass m at height y(φ) in gravity has V = m g y,
so by hand, at φ = 0:

- y = l (1 − cos φ)² ≈ l φ⁴/4: V⁽⁴⁾(0) = 6 m g l > 0, a strict minimum: stable;
- y = −l (1 − cos φ)²: V⁽⁴⁾(0) = −6 m g l, a strict maximum: unstable;
- y = l sin³φ: V'''(0) = 6 m g l, an inflection: unstable.

And a new user's hoop with a particle on top of its centre, rolling inside a cylinder of
radius 3R: V = −4 m g R cos φ + m g R cos 2φ, V''(0) = 0, V⁽⁴⁾(0) = 12 m g R: stable, which
rbdsolve called undetermined ("higher-order terms decide"), so plain `modes` found no
stable equilibrium.
"""

from __future__ import annotations

import pytest

import rbdsolve
from tests.conftest import BOB_AT_HEIGHT

HOOP = """\
parameters: [m, R, g]
coordinates: [phi]
gravity: [0, -g]
points:
  O: [0, 0]
bodies:
  wheel:
    parts:
      hoop: {shape: ring, mass: m, radius: R}
      bead: {shape: particle, mass: m, at: [0, R]}
contacts:
  C: {body: wheel, rolls_on: {circle: {centre: O, radius: 3*R, side: inside}}, along: phi}
questions:
  - equilibria
  - modes
"""


def _solved(tmp_path, text):
    path = tmp_path / "scene.yaml"
    path.write_text(text)
    return rbdsolve.solve(path, budget=1200.0)  # a budget far from the work


@pytest.mark.parametrize("height, stability, shown", [
    ("l*(1 - cos(phi))**2", "stable", "∂⁴V/∂φ⁴ = 6 g l m, is of even order and positive"),
    ("-l*(1 - cos(phi))**2", "unstable", "∂⁴V/∂φ⁴ = −6 g l m, is of even order and negative"),
    ("l*sin(phi)**3", "unstable", "∂³V/∂φ³ = 6 g l m, is of odd order"),
])
def test_the_first_nonzero_derivative_decides(tmp_path, height, stability, shown) -> None:
    (solution,) = _solved(tmp_path, BOB_AT_HEIGHT.replace("{HEIGHT}", height))
    (at_zero,) = [e for e in solution.answers.equilibria if e.at["phi"] == 0]
    assert at_zero.stability.value == stability
    assert shown in at_zero.reason


def test_the_hoop_with_a_particle_on_top_is_stable_and_its_modes_say_why(tmp_path) -> None:
    equilibria, modes = _solved(tmp_path, HOOP)
    (top,) = [e for e in equilibria.answers.equilibria if e.at["phi"] == 0]
    assert top.stability.value == "stable" and "∂⁴V/∂φ⁴ = 12 R g m" in top.reason
    assert modes.solved and tuple(modes.answers.eigenvalues) == (0,)
    assert any("λ = 0 is no free direction here" in w for w in modes.warnings)
