"""Relative equilibria and small oscillations in a turning frame, against hand
derivations, and the refusals where the frame does not make the scene still."""

from __future__ import annotations

import random

import pytest
import sympy as sp

from conftest import TURNING_ROD
from rbdsolve.errors import InputError
from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.solvers import solve_problem

Omega, m, L, d, k, a = sp.symbols("Omega m L d k a", positive=True)

# A rod pivoted at distance d from the axis of a horizontal turntable. By hand, in the
# table's frame: r_G = (d + L/2 cos φ, L/2 sin φ), V' = −½ m Ω² |r_G|², so
# V' = −½ m Ω² d L cos φ + const, J_P = m L²/3: λ = 3 Ω² d/(2 L) about φ = 0.
TURNTABLE = """
parameters: {m: mass, L: length, d: pivot distance, Omega: rate}
coordinates: [phi]
frames:
  table: {axis: z, rate: Omega}
points:
  P: d*[cos(Omega*t), sin(Omega*t)]
bodies:
  rod:
    at: P
    angle: phi + Omega*t
    parts:
      bar: {shape: rod, mass: m, length: L, at: [L/2, 0]}
questions:
  - equilibria: {frame: table}
  - modes: {frame: table, about: {phi: 0}}
"""

# A bead in a radial slot, on a spring to the axis: V' = ½ k r² − ½ m Ω² r²,
# λ = (k − m Ω²)/m about r = 0.
SLOT = """
parameters: {m: mass, k: stiffness, Omega: rate}
values: {m: 1, k: 10, Omega: 1}
coordinates: [r]
frames:
  table: {axis: z, rate: Omega}
points:
  A: [0, 0]
  P: r*[cos(Omega*t), sin(Omega*t)]
bodies:
  bead: {shape: particle, mass: m, at: P}
springs:
  s: {between: [P, A], stiffness: k}
questions:
  - modes: {frame: table, about: {r: 0}}
"""


def solve(text: str):
    return solve_problem(build_model(load_text(text, "scene.yaml"))).solutions


def test_a_rigid_body_still_in_the_turning_frame() -> None:
    equilibria, modes = solve(TURNTABLE)
    found = {e.at[next(iter(e.at))]: e.stability.value for e in equilibria.answers.equilibria}
    assert found == {0: "stable", sp.pi: "unstable"}
    assert sp.simplify(modes.answers.eigenvalues[0] - 3 * Omega**2 * d / (2 * L)) == 0


def test_a_spring_to_the_axis_in_the_turning_frame() -> None:
    (modes,) = solve(SLOT)
    assert modes.error is None, modes.error
    assert sp.simplify(modes.answers.eigenvalues[0] - (k - m * Omega**2) / m) == 0


def test_a_spring_anchored_off_the_axis_is_not_still_in_the_frame() -> None:
    (modes,) = solve(SLOT.replace("A: [0, 0]", "A: [1, 0]"))
    assert modes.error is not None and "still depends on t: spring 's' moves in it" in modes.error
    assert "planar 'angle'" not in modes.error  # no body turns: no word on orientations


def test_a_planar_angle_in_a_turning_frame_is_refused_with_the_orientation_that_follows_it() -> None:
    """The disk hinged to a turning shaft (DISK_ON_SHAFT below), written with ``angle:
    theta`` (a turn about z in the scene's axes) where it swings about the pin that turns with the shaft: in the
    frame its angle is θ − Ω t, so it is not still there; the message names the disk's
    angle and the way out, its orientation as turns, the frame's first."""
    equilibria = solve(DISK_ON_SHAFT.replace("axis: x, orientation: [[z, Omega*t], [y, -theta]]", "angle: theta"))[0]
    assert "the angle of body 'disk' moves in it" in equilibria.error
    assert "orientation: [[z, Omega*t], [y, -theta]]" in equilibria.error


def test_gyroscopic_coupling_is_answered_with_g() -> None:
    """A bead held to the axis of a turntable by a spring, free in the plane (x, y in
    the table's frame). By hand: L' = ½ m (ẋ² + ẏ²) + m Ω (x ẏ − y ẋ) − ½ (k − m Ω²)(x² + y²),
    so c = m Ω (−y, x), G = 2 m Ω [[0, −1], [1, 0]] (Gᵢⱼ = ∂cᵢ/∂qⱼ − ∂cⱼ/∂qᵢ), and
    det(K − ω²M + iωG) = (k − m Ω² − m ω²)² − 4 m² Ω² ω² = 0: ω = √(k/m) ± Ω, stable for
    every Ω (k = 10, m = 1, Ω = 1: ω = √10 ∓ 1)."""
    text = SLOT.replace("coordinates: [r]", "coordinates: [x, y]").replace(
        "P: r*[cos(Omega*t), sin(Omega*t)]",
        "P: [x*cos(Omega*t) - y*sin(Omega*t), x*sin(Omega*t) + y*cos(Omega*t)]").replace(
        "about: {r: 0}", "about: {x: 0, y: 0}")
    (modes,) = solve(text)
    assert modes.error is None, modes.error
    a = modes.answers
    assert sp.simplify(a.G - sp.Matrix([[0, -2 * m * Omega], [2 * m * Omega, 0]])) == sp.zeros(2)
    assert a.stability.value == "stable"
    assert sorted(float(x.subs({m: 1, k: 10, Omega: 1})) for x in a.frequencies) == \
        pytest.approx([10**0.5 - 1, 10**0.5 + 1], rel=1e-12)


@pytest.mark.parametrize(
    "old, new, words",
    [
        ("{axis: z, rate: Omega}", "{axis: z, rate: null}", "needs both 'axis' and 'rate'"),
        ("{axis: z, rate: Omega}", "{axis: [Omega - Omega, 0, 0], rate: Omega}", "turns about the zero vector"),
        ("{axis: z, rate: Omega}", "{origin: P}", "its origin depends on the coordinate r"),
    ],
)
def test_bad_frames_are_located(old, new, words) -> None:
    with pytest.raises(InputError, match=words) as info:
        solve(SLOT.replace(old, new))
    assert info.value.location.key_path().startswith("frames.table")


# A disk hinged at a point O of its rim to a vertical shaft turning at Ω, the pin
# horizontal, tangent to the rim and turning with the shaft (the disk's plane holds the
# pin and OG). By hand, with θ the angle of OG from the downward vertical: about O the
# disk's moments are m r²/4 along OG, 5 m r²/4 about the pin and 3 m r²/2 about its
# normal; the vertical lies in the plane of OG and the normal, so ½ Ω² n·J_O n =
# ½ Ω² m r² (1/4 + 5/4 sin²θ) and V' = −m g r cos θ − (5/8) Ω² m r² sin²θ + const:
# cos θ₀ = 4 g/(5 Ω² r), Ω_c = √(4g/(5r)) (a particle at G would give √(g/r)), and with
# M = 5 m r²/4, λ = 4g/(5r) − Ω² about θ = 0.
DISK_ON_SHAFT = """
parameters: {m: mass, r: radius, g: gravity, Omega: rate}
coordinates: [theta]
gravity: [0, 0, -g]
frames:
  shaft: {axis: z, rate: Omega}
points:
  G: r*[sin(theta)*cos(Omega*t), sin(theta)*sin(Omega*t), -cos(theta)]
bodies:
  disk: {shape: disk, mass: m, radius: r, at: G, axis: x, orientation: [[z, Omega*t], [y, -theta]]}
questions:
  - equilibria: {frame: shaft}
  - modes: {frame: shaft, about: {theta: 0}}
"""


def test_a_disk_hinged_to_a_turning_shaft_uses_its_inertia_tensor() -> None:
    gr, r = sp.symbols("g r", positive=True)
    equilibria, modes = solve(DISK_ON_SHAFT)
    assert equilibria.error is None, equilibria.error
    (critical,) = equilibria.answers.critical
    assert sp.simplify(critical.value - sp.sqrt(4 * gr / (5 * r))) == 0
    found = {e.at["theta"] for e in equilibria.answers.equilibria}
    assert sp.acos(4 * gr / (5 * Omega**2 * r)) in found
    assert sp.simplify(modes.answers.M[0, 0] - 5 * m * r**2 / 4) == 0
    assert sp.simplify(modes.answers.eigenvalues[0] - (4 * gr / (5 * r) - Omega**2)) == 0


def test_a_rod_pinned_at_its_centre_turns_across_the_shaft() -> None:
    """No gravity moment: V' = −½ Ω² (m l²/12) sin²θ alone, the centre giving nothing;
    θ = ±π/2 stable with λ = Ω² (by hand), θ = 0, π unstable."""
    text = DISK_ON_SHAFT.replace("r: radius", "l: length").replace(
        "  G: r*[sin(theta)*cos(Omega*t), sin(theta)*sin(Omega*t), -cos(theta)]\n", "  G: [0, 0, 0]\n").replace(
        "disk: {shape: disk, mass: m, radius: r, at: G, axis: x,",
        "rod: {shape: rod, mass: m, length: l, at: G, axis: z,")
    text = text.replace("about: {theta: 0}", "about: {theta: pi/2}")
    equilibria, modes = solve(text)
    found = {e.at["theta"]: e.stability.value for e in equilibria.answers.equilibria}
    assert found == {0: "unstable", sp.pi: "unstable", sp.pi / 2: "stable", -sp.pi / 2: "stable"}
    assert sp.simplify(modes.answers.eigenvalues[0] - Omega**2) == 0


def test_a_planar_angle_in_a_frame_turning_about_another_axis_names_the_orientation() -> None:
    text = """
parameters: {m: mass, l: length, g: gravity, Omega: rate}
coordinates: [theta]
gravity: [0, -g, 0]
frames:
  shaft: {axis: y, rate: Omega}
points:
  G: l/2*[sin(theta)*cos(Omega*t), -cos(theta), -sin(theta)*sin(Omega*t)]
bodies:
  rod: {shape: rod, mass: m, length: l, at: G, angle: theta, axis: y}
questions:
  - equilibria: {frame: shaft}
"""
    (equilibria,) = solve(text)
    assert "planar 'angle'" in equilibria.error and "orientation: [[y, Omega*t], [z, theta]]" in equilibria.error
    fixed = text.replace("angle: theta, axis: y}", "axis: -y, orientation: [[y, Omega*t], [z, theta]]}")
    (equilibria,) = solve(fixed)
    assert equilibria.error is None, equilibria.error
    l = sp.Symbol("l", positive=True)
    assert {e.at["theta"] for e in equilibria.answers.equilibria} >= {0, sp.acos(3 * sp.Symbol("g", positive=True)
                                                                           / (2 * l * Omega**2))}


# The bead on a turning rod held by a spring from the axis (tests/conftest.py TURNING_ROD,
# with its derivation by hand).


def _true_slope(x0, values) -> float:
    """∂V'/∂x of the true potential, the spring's length |a + x|, at x0."""
    x = sp.Symbol("x", real=True)
    V = k * (sp.Abs(a + x) - a) ** 2 / 2 - m * Omega**2 * (a + x) ** 2 / 2
    return float(sp.diff(V, x).subs(values).subs(x, x0.subs(values)))


def test_a_sprung_bead_on_a_turning_rod_exists_below_the_critical_rate() -> None:
    equilibria, modes = solve(TURNING_ROD)
    (found,) = equilibria.answers.equilibria
    x0 = m * Omega**2 * a / (k - m * Omega**2)
    assert sp.simplify(found.at["x"] - x0) == 0
    assert found.stability.value == "stable"
    rng = random.Random(38)
    sides = set()
    for _ in range(30):
        values = {m: rng.uniform(0.1, 2), k: rng.uniform(1, 100), a: rng.uniform(0.1, 2)}
        values[Omega] = (values[k] / values[m]) ** 0.5 * rng.choice([rng.uniform(0.2, 0.99), rng.uniform(1.01, 3)])
        exists = bool(found.exists_when.subs(values))
        assert exists is (float((a + x0).subs(values)) > 0), values
        sides.add(exists)
        scale = values[k] * values[a]
        assert (abs(_true_slope(x0, values)) < 1e-9 * scale) is exists, values
    assert sides == {True, False}
    (about,) = modes.answers.modes
    assert sp.simplify(about.eigenvalues[0] - (k - m * Omega**2) / m) == 0
    assert about.motions[0].value == "oscillation" and not any(about.cases)


# The same bead with its distance r from the axis as the coordinate: the spring's length
# |r| is zero at r = 0, so its sign there is not decided and |r| stays. By hand, for
# r > 0, V' = ½ k (r − a)² − ½ m Ω² r², ∂V'/∂r = (k − m Ω²) r − k a = 0 at
# r = k a/(k − m Ω²), and by symmetry −k a/(k − m Ω²) for r < 0, both stable (K = k − m Ω²)
# where k > m Ω². r = 0 is no equilibrium: V' has a kink there (≈ −k a |r|), and sympy's
# and numpy's sign(0) = 0 made it look like one (listed as an evident root, 'undetermined'
# with DiracDelta(0) in K; on the numeric route 'stable').
RADIAL = TURNING_ROD.replace("coordinates: [x]", "coordinates: [r]").replace("(a + x)*", "r*").replace(
    "  - modes: {frame: rod, about: each}\n", "")


def test_a_spring_through_zero_length_is_no_equilibrium() -> None:
    (equilibria,) = solve(RADIAL)
    assert equilibria.error is not None and "no evident root" in equilibria.error
    (numeric,) = solve(RADIAL.replace("coordinates:", "values: {m: 0.2, k: 50, a: 0.3, Omega: 5}\ncoordinates:"))
    assert numeric.error is None, numeric.error
    found = sorted(e.at["r"] for e in numeric.answers.equilibria)
    by_hand = 50 * 0.3 / (50 - 0.2 * 25)  # k a/(k − m Ω²) = 1/3
    assert found == pytest.approx([-by_hand, by_hand], rel=1e-9)
    assert all(e.stability.value == "stable" for e in numeric.answers.equilibria)
    assert any("r = 0 solves ∂V/∂q = 0 only through sign(0) = 0" in w for w in numeric.warnings)
