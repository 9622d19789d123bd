"""The numeric search box: declared ranges, one turn for a periodic angle, the scene's
lengths for the rest (not the largest value of any kind), and the box printed."""

from __future__ import annotations

import math

import pytest
import sympy as sp

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
    assert any("x in [-3, 3] (±10 a; a = 0.3, the scene's largest length)" in w for w in solution.warnings)


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
                      (plain, "x in [-2, 2] (±10 r; r = 0.2, the scene's largest length)")):
        solution = equilibria_numeric.solve(None, build_model(load_file(file)), Options())
        assert [eq.at["x"] for eq in solution.answers.equilibria] == pytest.approx(
            [-0.48453720205778310, 0.0, 0.48453720205778310], abs=1e-12)
        assert [eq.stability.value for eq in solution.answers.equilibria] == ["stable", "unstable", "stable"]
        assert any(box in w for w in solution.warnings), solution.warnings


def test_a_travel_round_a_circle_is_searched_as_an_angle() -> None:
    """A wheel (disk m = 4, a particle mp = 5 at r/2 from its centre) rolling inside a
    cylinder, θ its travel round the circle: no length, though its kind is not said (the
    box was ±10 × r = ±3, which left out θ = π; neighbours seed 2027, scene 11). By hand,
    the wheel turns by φ = −(R − r) θ/r = −4θ, so V = −(m + mp) g (R − r) cos θ
    − mp g (r/2) cos 4θ; at θ = π, V' = 0 and V'' = −(m + mp) g (R − r) + 16 mp g r/2
    = 11.772 > 0: stable at the top of the cylinder, with the particle below the centre."""
    text = """\
parameters: {m: mass, mp: mass, r: length, g: gravity, R: length}
values: {m: 4, mp: 5, r: 0.3, g: 9.81, R: 1.5}
coordinates: [theta]
gravity: [0, -g]
bodies:
  wheel: {parts: {disk: {shape: disk, mass: m, radius: r}, bob: {shape: particle, mass: mp, at: "[0, -r/2]"}}}
contacts:
  C: {body: wheel, rolls_on: {circle: {centre: "[0, 0]", radius: R, side: inside}}, along: theta}
questions: [equilibria]
"""
    model = build_model(load_text(text, "wheel.yaml"))
    (box,) = search_box(model, periodic_angles(model))
    assert box.low <= -math.pi and box.high >= math.pi
    solution = equilibria_numeric.solve(None, model, Options())
    at_pi = [eq for eq in solution.answers.equilibria if abs(math.remainder(eq.at["theta"] - math.pi, 2 * math.pi)) < 1e-9]
    assert at_pi and {str(eq.stability) for eq in at_pi} <= {"Stability.STABLE", "stable"}, at_pi


@pytest.mark.parametrize("shape, m, r, R", [
    ("cylinder", 1, "1/3", 1),  # problems/contacts/cylinder-in-cylinder.yaml with m, g given
    ("ring", 2, "1/2", 2),  # next door: a ring, another ratio R/r
])
def test_a_travel_round_a_circle_whose_potential_repeats_is_wrapped_into_one_turn(shape, m, r, R) -> None:
    """Issue 43: a uniform body rolling inside a cylinder, θ its travel round the circle,
    on the numeric route: searched over ±10π, it listed θ = −9π, −7π, … and −8π, −6π, …
    as "the same configuration" of two equilibria, their representatives −28.27 and
    −25.13. By hand V = −m g (R − r) cos θ, which repeats after a turn: equilibria θ = 0,
    V'' = m g (R − r) > 0, stable, and θ = π, V'' = −m g (R − r), unstable; no others."""
    text = f"""\
parameters: {{m: mass, r: length, R: length, g: gravity}}
values: {{m: {m}, r: {r}, R: {R}, g: 9.81}}
coordinates: [theta]
gravity: [0, -g]
bodies:
  wheel: {{shape: {shape}, mass: m, radius: r{', height: 1' if shape == 'cylinder' else ''}}}
contacts:
  C: {{body: wheel, rolls_on: {{circle: {{centre: [0, 0], radius: R, side: inside}}}}, along: theta}}
questions: [equilibria]
"""
    model = build_model(load_text(text, "wheel.yaml"))
    (box,) = search_box(model, periodic_angles(model))
    assert (box.low, box.high) == pytest.approx((-math.pi, math.pi))
    solution = equilibria_numeric.solve(None, model, Options())
    found = sorted(solution.answers.equilibria, key=lambda eq: eq.at["theta"])
    assert [eq.at["theta"] for eq in found] == pytest.approx([0.0, math.pi], abs=1e-9)
    assert [eq.stability.value for eq in found] == ["stable", "unstable"]
    curvature = m * 9.81 * (R - float(sp.Rational(r)))
    assert [eq.curvatures[0] for eq in found] == pytest.approx([curvature, -curvature], rel=1e-9)
    assert all(not eq.equivalent for eq in found)


# The elastic pendulum (problems/forces/elastic-pendulum.yaml) with m = 1, k = 20, L = 1,
# g = 9.81, by hand: r ≥ 0 is a polar distance ((−r, θ) is the point (r, θ + π)), and
# ∂V/∂r = k (r − L) − m g cos θ = 0, ∂V/∂θ = m g r sin θ = 0 give r = L + m g/k = 1.4905 at
# θ = 0 (stable) and r = L − m g/k = 0.5095 at θ = π (unstable), as the exact route says.
# The numeric route searches r ≥ 0 too: before, it also listed (−1.4905, π) and (−0.5095, 0),
# the same two points again.
def test_a_polar_distance_is_searched_from_zero_and_each_equilibrium_listed_once() -> None:
    text = (PROBLEMS / "forces" / "elastic-pendulum.yaml").read_text() + "values: {m: 1, k: 20, L: 1, g: 9.81}\n"
    model = build_model(load_text(text, "elastic.yaml"))
    r_box, _ = search_box(model, periodic_angles(model))
    assert (r_box.low, r_box.high) == pytest.approx((0.0, 10.0))
    solution = equilibria_numeric.solve(None, model, Options())
    found = sorted((eq.at["r"], abs(eq.at["theta"]), eq.stability.value) for eq in solution.answers.equilibria)
    assert [x for r, th, _ in found for x in (r, th)] == pytest.approx([0.5095, math.pi, 1.4905, 0.0], abs=1e-9)
    assert [s for _, _, s in found] == ["unstable", "stable"]
    assert any("r in [0, 10] (≥ 0, a polar distance (spring 's'), to 10 × L = 10)" in w for w in solution.warnings)
