"""A continuum of equilibria that holds only at the values given, on the numeric route.

An inverted rod (m, l) on a pivot, two zero-length springs (k each) from the point A at
a above the pivot to (±d, a). By hand, with A = a (sin θ, cos θ),

    |A − (d, a)|² + |A − (−d, a)|² = 4 a² + 2 d² − 4 a² cos θ,
    V = ½ m g l cos θ + ½ k (4 a² + 2 d² − 4 a² cos θ) = const + (½ m g l − 2 k a²) cos θ,

so at k = m g l/(4 a²) V is constant: every θ is an equilibrium, and neutral. ∂V/∂θ is
then rounding noise (~1e-16 of its terms, each ~5 N·m) over the whole turn; a root
tolerance relative to that noise took each of its sign changes for a root, and the
route ran through any budget (a new user's trial: 60 s, and 120 s, without an answer)."""

from __future__ import annotations

from fractions import Fraction

import rbdsolve
from rbdsolve.solvers.equilibria.answers import Stability
from rbdsolve.solvers.modes.answers import Motion

SCENE = """\
title: an inverted rod on two zero-length springs at the critical stiffness
parameters: {m: mass, l: length, a: length, d: length, k: stiffness, g: acceleration}
values: {m: 1 kg, l: 1 m, a: 80 cm, d: 50 cm, k: 3.83203125 N/m, g: 9.81 m/s^2}
coordinates: [theta]
gravity: [0, -g]
points:
  A: a*[sin(theta), cos(theta)]
  G: l/2*[sin(theta), cos(theta)]
bodies:
  rod: {shape: rod, mass: m, length: l, at: G, angle: theta, axis: y}
springs:
  left: {stiffness: k, between: [A, [-d, a]]}
  right: {stiffness: k, between: [A, [d, a]]}
questions:
  - equilibria
  - modes: {about: each}
"""


def test_every_angle_is_one_neutral_equilibrium(tmp_path) -> None:
    assert Fraction("3.83203125") == Fraction("9.81") / (4 * Fraction("0.8") ** 2)  # k = m g l/(4 a²), by hand
    path = tmp_path / "rod.yaml"
    path.write_text(SCENE, encoding="utf-8")
    # a budget far from the work (about a second): the old search never ended within it
    equilibria, modes = (s.answers for s in rbdsolve.solve(path, route="numeric", budget=120.0))
    (only,) = equilibria.equilibria
    assert only.free == ((1.0,),)
    assert only.stability is Stability.NEUTRAL
    (about,) = modes.modes
    assert about.motions == (Motion.NEUTRAL,)
    assert abs(about.eigenvalues[0]) <= about.absolute_errors[0]


def test_the_exact_route_says_every_angle_is_an_equilibrium_at_these_values(tmp_path) -> None:
    """In the parameters the exact route lists θ = 0 and π with their cases in k; at the
    values, k = k_c, it must say that every θ is an equilibrium too."""
    path = tmp_path / "rod.yaml"
    path.write_text(SCENE.replace("  - modes: {about: each}\n", ""), encoding="utf-8")
    (equilibria,) = rbdsolve.solve(path, route="exact", budget=120.0)
    assert any("every configuration is an equilibrium (a continuum)" in w for w in equilibria.warnings)
    path.write_text(SCENE.replace("k: 3.83203125 N/m", "k: 4 N/m").replace("  - modes: {about: each}\n", ""),
                    encoding="utf-8")
    (off,) = rbdsolve.solve(path, route="exact", budget=120.0)
    assert not any("a continuum" in w for w in off.warnings)
