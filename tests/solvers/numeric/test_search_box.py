"""The numeric search box: declared ranges, one turn for a periodic angle, the scene's
lengths for the rest (not the largest value of any kind), and the box printed."""

from __future__ import annotations

import math

import pytest

from rbdsolve.model.build import build_model
from rbdsolve.problem import load_file, load_text
from rbdsolve.solvers.equilibria import numeric as equilibria_numeric
from rbdsolve.solvers.routes.options import Options
from rbdsolve.solvers.numeric.numeric_model import periodic_angles
from rbdsolve.solvers.numeric.search_box import search_box

from conftest import PROBLEMS

# A heavy bead (1000 kg) on a short horizontal wire between two springs of zero natural
# length anchored at ±a (a = 3/10 m). By hand: V = ½ k (x + a)² + ½ k (a − x)², V' = 2 k x,
# so x = 0 is the only equilibrium.
WIRE = """\
parameters: {{m: mass, k: stiffness, a: length, g: gravity}}
values: {{m: 1000, k: 50, a: 3/10, g: 9.81}}
coordinates: {coordinates}
gravity: [0, -g]
points:
  P: [x, 0]
  A: [-a, 0]
  B: [a, 0]
bodies:
  bead: {{shape: particle, mass: m, at: P}}
springs:
  s1: {{stiffness: k, between: [A, P]}}
  s2: {{stiffness: k, between: [P, B]}}
questions: [equilibria]
"""


def _model(coordinates: str):
    return build_model(load_text(WIRE.format(coordinates=coordinates), "w.yaml"))


def test_a_length_box_comes_from_the_scene_lengths_not_the_mass() -> None:
    model = _model("[x]")
    (box,) = search_box(model, periodic_angles(model))
    assert (box.low, box.high) == pytest.approx((-3.0, 3.0))  # ±10 × a, not ±10 × 1000
    solution = equilibria_numeric.solve(None, model, Options())
    assert [eq.at["x"] for eq in solution.answers.equilibria] == pytest.approx([0.0], abs=1e-12)
    assert any("x in [-3, 3] (±10 × a = ±0.3, the scene's largest length)" in w for w in solution.warnings)


def test_a_declared_range_is_the_box() -> None:
    model = _model("{x: {kind: length, range: [-a/2, 2*a]}}")
    (box,) = search_box(model, periodic_angles(model))
    assert (box.low, box.high) == pytest.approx((-0.15, 0.6))
    solution = equilibria_numeric.solve(None, model, Options())
    assert any("x in [-0.15, 0.6] (declared)" in w for w in solution.warnings)


def test_a_periodic_angle_searches_one_turn() -> None:
    text = WIRE.format(coordinates="{x: angle}").replace("P: [x, 0]", "P: a*[cos(x), sin(x)]")
    model = build_model(load_text(text, "w.yaml"))
    (box,) = search_box(model, periodic_angles(model))
    assert (box.low, box.high) == pytest.approx((-math.pi, math.pi))


def test_a_rolling_wheel_s_declared_range_and_its_default(tmp_path) -> None:
    """problems/edges/eccentric-wheel-soft-spring.yaml: x/r = K sin(x/r), K = 3.67875, so
    every root has |x| ≤ K r = 0.73575 m (declared); without the range the box is ±10 × r
    (r = 0.2 m, the largest length; M = 2 kg plays no part). Both find 0 and
    ±x* = ±0.48453720205778310 m (mpmath, by hand in the expected file)."""
    path = PROBLEMS / "edges" / "eccentric-wheel-soft-spring.yaml"
    text = path.read_text(encoding="utf-8")
    plain = tmp_path / "w.yaml"
    plain.write_text(text.replace("x: {kind: length, range: [-m*g*e/(k*r), m*g*e/(k*r)]}", "x: length"))
    for file, box in ((path, "x in [-0.73575, 0.73575] (declared)"),
                      (plain, "x in [-2, 2] (±10 × r = ±0.2, the scene's largest length)")):
        solution = equilibria_numeric.solve(None, build_model(load_file(file)), Options())
        assert [eq.at["x"] for eq in solution.answers.equilibria] == pytest.approx(
            [-0.48453720205778310, 0.0, 0.48453720205778310], abs=1e-12)
        assert [eq.stability.value for eq in solution.answers.equilibria] == ["stable", "unstable", "stable"]
        assert any(box in w for w in solution.warnings), solution.warnings
