"""The planar sketch: positions and sizes against hand values, refusals of 3D scenes."""

from __future__ import annotations

import math
from fractions import Fraction

import pytest

from rbdsolve.model.build import build_model
from rbdsolve.problem import load_file, load_text
from rbdsolve.render.drawing.sketch import (
    Circle,
    Dot,
    NotDrawable,
    Polygon,
    Segment,
    convex_hull,
    sketch,
)

from conftest import PROBLEMS

EXAM = PROBLEMS / "sg2150-2015-10-29"


def model_of(path, **values):
    model = build_model(load_file(str(path)))
    return model.with_values({k: Fraction(v) for k, v in values.items()}) if values else model


def close(a, b, tol=1e-12) -> bool:
    return all(abs(x - y) <= tol for x, y in zip(a, b))


def segment_of(drawing, body: str) -> Segment:
    return next(s for s in drawing.shapes if s.body == body)


def test_p1_at_rest_hand_values() -> None:
    # r = 1: G1 = (0, -r/2); the chord of length √3 r is horizontal at θ = 0, its ends
    # (±√3/2, -1/2); the short rod of length r hangs from G1 down to (0, -3/2).
    drawing = sketch(model_of(EXAM / "p1-two-rods.yaml", r=1), {"theta": 0.0, "phi": 0.0})
    long_rod, short_rod = segment_of(drawing, "long_rod"), segment_of(drawing, "short_rod")
    ends = sorted([long_rod.start, long_rod.end])
    assert close(ends[0], (-math.sqrt(3) / 2, -0.5)) and close(ends[1], (math.sqrt(3) / 2, -0.5))
    assert close(sorted([short_rod.start, short_rod.end])[0], (0, -1.5))
    assert close(sorted([short_rod.start, short_rod.end])[1], (0, -0.5))
    points = {p.name: p.at for p in drawing.points}
    assert close(points["G2"], (0, -1.0)) and drawing.gravity == (0.0, -1.0)
    assert drawing.notes == ("m = g = 1: no values given",)


def test_p1_scales_with_r_and_turns_with_theta() -> None:
    # r = 2, θ = π/2: G1 = r/2 (1, 0) = (1, 0); the chord turned a quarter turn is vertical.
    drawing = sketch(model_of(EXAM / "p1-two-rods.yaml", r=2), {"theta": math.pi / 2, "phi": 0.0})
    ends = sorted([segment_of(drawing, "long_rod").start, segment_of(drawing, "long_rod").end], key=lambda p: p[1])
    assert close(ends[0], (1, -math.sqrt(3)), 1e-9) and close(ends[1], (1, math.sqrt(3)), 1e-9)


def test_pendulum_is_horizontal_at_a_quarter_turn() -> None:
    # G = l/2 (sin θ, -cos θ): at θ = π/2 the rod (axis y, turned by θ) lies along x from O to (l, 0).
    drawing = sketch(model_of(PROBLEMS / "examples" / "pendulum.yaml", l=2), {"theta": math.pi / 2})
    rod = segment_of(drawing, "rod")
    assert close(sorted([rod.start, rod.end])[0], (0, 0), 1e-9)
    assert close(sorted([rod.start, rod.end])[1], (2, 0), 1e-9)


def test_default_configuration_is_the_modes_equilibrium_or_the_impact() -> None:
    assert dict(sketch(model_of(EXAM / "p1-two-rods.yaml")).configuration) == {"theta": 0.0, "phi": 0.0}
    falling = sketch(model_of(PROBLEMS / "impact" / "falling-rod-hits-floor.yaml", alpha=Fraction(1, 2)))
    assert dict(falling.configuration) == {"x": 0.0, "y": 0.0, "theta": 0.5}


def test_plate_with_a_hole() -> None:
    # a = 1: the plate 2a × 2a about O, the hole a disk of radius a/2 at (a/2, 0), seen face-on.
    drawing = sketch(model_of(PROBLEMS / "inertia" / "plate-with-hole.yaml", a=1))
    plate, hole = drawing.shapes
    assert isinstance(plate, Polygon) and sorted(plate.vertices) == [(-1, -1), (-1, 1), (1, -1), (1, 1)]
    assert hole == Circle((0.5, 0.0), 0.5, "holed_plate", True, True)


SHAPES = """
title: shapes
parameters:
  r: radius
coordinates: [x]
points:
  A: [x, 0]
bodies:
  wheel: {shape: disk, mass: 1, radius: r, at: A}
  edge: {shape: disk, mass: 1, radius: r, at: [0, 3], axis: x}
  block: {shape: box, mass: 1, width: 2, depth: 1, height: 4, at: [5, 0], angle: pi/2}
  bob: {shape: particle, mass: 1, at: [0, -2]}
questions: [eom]
"""


def test_shapes_seen_along_z() -> None:
    model = build_model(load_text(SHAPES, "shapes.yaml")).with_values({"r": Fraction(1)})
    wheel, edge, block, bob = sketch(model, {"x": 2.0}).shapes
    assert wheel == Circle((2.0, 0.0), 1.0, "wheel")  # in the plane: a circle
    # own axis along x: the disk stands in the yz-plane, seen edge-on as a segment along y
    assert isinstance(edge, Polygon) and close(sorted(edge.vertices)[0], (0, 2)) and close(sorted(edge.vertices)[-1], (0, 4))
    assert len(edge.vertices) == 2
    # 2 (x) by 1 (y), turned a quarter turn: 1 wide, 2 tall about (5, 0)
    corners = sorted((round(x, 9), round(y, 9)) for x, y in block.vertices)
    assert corners == [(4.5, -1), (4.5, 1), (5.5, -1), (5.5, 1)]
    assert bob == Dot((0.0, -2.0), "bob")


@pytest.mark.parametrize("path, words", [
    (EXAM / "p3-rolling-ring.yaml", "turns in 3D"),
    (EXAM / "p2-rod-impact.yaml", "velocity at one instant"),
    (PROBLEMS / "frames" / "rotating-hoop-slow.yaml", "leaves the xy-plane"),
])
def test_scenes_that_are_not_planar_are_refused(path, words) -> None:
    with pytest.raises(NotDrawable, match=words):
        sketch(model_of(path))


def test_convex_hull_drops_inner_points() -> None:
    square = [(0, 0), (1, 0), (1, 1), (0, 1), (0.5, 0.5), (0.5, 0)]
    assert convex_hull(square) == ((0, 0), (1, 0), (1, 1), (0, 1))


def test_contacts_draw_their_surfaces_and_contact_points() -> None:
    # cylinder in a cylinder, R = 1, r = 1/3, θ = π/2: the track is the unit circle about
    # the origin; C is where the line of centres meets it, (1, 0); the cylinder's centre
    # is at (R − r)(sin θ, −cos θ) = (2/3, 0).
    drawing = sketch(model_of(PROBLEMS / "contacts" / "cylinder-in-cylinder.yaml"), {"theta": math.pi / 2})
    (track,) = drawing.grounds
    assert track.centre == (0.0, 0.0) and track.radius == 1.0 and track.inside
    assert close({p.name: p.at for p in drawing.points}["C"], (1.0, 0.0), 1e-12)
    circle = next(s for s in drawing.shapes if isinstance(s, Circle))
    assert close(circle.centre, (2 / 3, 0.0), 1e-12)


def test_a_floor_is_a_stretch_of_line_through_the_contact_and_a_string_ends_at_its_fixed_point() -> None:
    # the rocking half-disk at θ = 0.3 on the floor: C at (−R θ, 0) = (−0.3, 0) (R = 1);
    # the floor is horizontal, with the body above it (normal +y)
    drawing = sketch(model_of(PROBLEMS / "contacts" / "half-disk-rocking.yaml"), {"theta": 0.3})
    (floor,) = drawing.grounds
    assert floor.start[1] == floor.end[1] == 0.0 and floor.normal == (0.0, 1.0)
    assert close({p.name: p.at for p in drawing.points}["C"], (-0.3, 0.0), 1e-12)
    # the yo-yo at y = 2 (r = 1): the string runs from A = (0, 0) down to S = (0, −2)
    (string,) = sketch(model_of(PROBLEMS / "contacts" / "yo-yo.yaml"), {"y": 2.0}).grounds
    assert string.string and close(string.start, (0.0, 0.0)) and close(string.end, (0.0, -2.0))


def test_a_string_over_a_pulley_is_drawn_to_the_pulley_and_down_to_the_block() -> None:
    # the cylinder at x = 1 (r = 1/2, d = 3): its top S at (1, 1), the pulley P at (3, 1);
    # the block hangs d + 2x = 5 below P, at (3, −4) (by hand: the top moves twice as far)
    drawing = sketch(model_of(PROBLEMS / "contacts" / "cylinder-pulley-block.yaml"), {"x": 1.0})
    floor, straight, hanging = drawing.grounds
    assert straight.string and close(straight.start, (3.0, 1.0)) and close(straight.end, (1.0, 1.0))
    assert hanging.string and close(hanging.start, (3.0, 1.0)) and close(hanging.end, (3.0, -4.0))


def test_an_incline_and_a_drum_are_drawn_where_the_body_touches_them() -> None:
    # the wheel at x = 1 on the incline at α = 1/2 down to the right (r = 1 drawn as 1):
    # C = x (cos α, −sin α), the line along (cos α, −sin α), the wheel on its upper side,
    # normal (sin α, cos α), and the wheel's centre r along it from C
    a = 0.5
    drawing = sketch(model_of(PROBLEMS / "contacts" / "wheel-on-incline.yaml"), {"x": 1.0})
    (incline,) = drawing.grounds
    C = (math.cos(a), -math.sin(a))
    assert close({p.name: p.at for p in drawing.points}["C"], C)
    direction = (incline.end[0] - incline.start[0], incline.end[1] - incline.start[1])
    assert abs(direction[0] * math.sin(a) + direction[1] * math.cos(a)) < 1e-12  # along the incline
    assert close(incline.normal, (math.sin(a), math.cos(a)))
    wheel = next(s for s in drawing.shapes if isinstance(s, Circle))
    assert close(wheel.centre, (C[0] + math.sin(a), C[1] + math.cos(a)))
    # the ring off the top of a drum at θ = 0.4 (R = r = 1 drawn): the drum whole, outside;
    # C = R (−sin θ, cos θ) on it, the ring's centre (R + r)(−sin θ, cos θ)
    drawing = sketch(model_of(PROBLEMS / "contacts" / "ring-on-drum.yaml"), {"theta": 0.4})
    (drum,) = drawing.grounds
    assert drum.centre == (0.0, 0.0) and drum.radius == 1.0 and not drum.inside
    assert close({p.name: p.at for p in drawing.points}["C"], (-math.sin(0.4), math.cos(0.4)))
    ring = next(s for s in drawing.shapes if isinstance(s, Circle))
    assert close(ring.centre, (-2 * math.sin(0.4), 2 * math.cos(0.4)))


def test_a_pivot_is_marked_whether_or_not_a_point_is_named_there() -> None:
    """By hand: the pinned rod turns about its top end (0, 0), with no point named
    there; seed problem 1's long rod slides in a circle, turning about its centre O,
    which is not on the rod (no support there); a cylinder rolling inside a cylinder
    has no fixed point (its contact point is still for an instant only), and the
    accelerated pendulum's pivot A moves."""
    assert sketch(model_of(EXAM / "p1-two-rods.yaml")).pivots == ()
    pinned = sketch(model_of(PROBLEMS / "impact" / "ball-hits-pinned-rod.yaml"))
    assert pinned.pivots == ((0.0, 0.0),) and all(p.at != (0.0, 0.0) for p in pinned.points)
    assert sketch(model_of(PROBLEMS / "contacts" / "cylinder-in-cylinder.yaml")).pivots == ()
    assert sketch(model_of(EXAM / "p5-accelerated-pendulum.yaml")).pivots == ()


def test_a_body_s_own_points_and_strings_straight_from_a_pulley() -> None:
    # problems/forces/atwood-massive-pulley.yaml at θ = 0 (R = 0.1, l = 1): each block
    # hangs l below the rim, its string drawn from the rim straight down to it.
    drawing = sketch(model_of(PROBLEMS / "forces" / "atwood-massive-pulley.yaml"), {"theta": 0.0})
    strings = sorted((g.start, g.end) for g in drawing.grounds if g.string)
    assert len(strings) == 2
    assert close(strings[0][0], (-0.1, 0)) and close(strings[0][1], (-0.1, -1))
    assert close(strings[1][0], (0.1, 0)) and close(strings[1][1], (0.1, -1))
    # a rod's own point B (l/2 below its centre along the rod) is labelled where it is
    rod = load_text("parameters: {m: mass, l: length}\ncoordinates: [theta]\nbodies:\n  rod: {shape: rod, "
                    "mass: m, length: l, at: [0, 0], angle: theta, axis: y, points: {B: [0, -l/2]}}\n"
                    "questions: [eom]\n", "r.yaml")
    points = {p.name: p.at for p in sketch(build_model(rod), {"theta": math.pi / 2}).points}
    assert close(points["B"], (0.5, 0.0)) and "rod" not in points


def test_an_impact_draws_its_particle_touching_the_point_and_its_velocity_behind_it() -> None:
    """The ball hits the rod's end A = (0, −l) moving along +x at v0: drawn at the instant
    (θ = 0) just left of A, touching it, its arrow left of the ball pointing along +x;
    the bullet comes in along (v0, −v1), so its arrow points down and right."""
    drawing = sketch(model_of(PROBLEMS / "impact" / "ball-hits-pinned-rod.yaml", l=2))
    (strike,) = drawing.strikes
    assert strike.point == "A" and strike.label == "v₀"
    assert close((strike.ball[0] + strike.radius, strike.ball[1]), (0.0, -2.0))  # touching A from the left
    assert strike.tail[0] < strike.head[0] < strike.ball[0] and strike.tail[1] == strike.head[1] == strike.ball[1]
    bullet = sketch(model_of(PROBLEMS / "impact" / "bullet-embeds-in-hanging-rod.yaml")).strikes[0]
    dx, dy = bullet.head[0] - bullet.tail[0], bullet.head[1] - bullet.tail[1]
    assert dx > 0 and dy < 0


def test_an_impact_s_particle_is_not_drawn_away_from_the_instant() -> None:
    model = model_of(PROBLEMS / "impact" / "ball-hits-pinned-rod.yaml")
    assert sketch(model, {"theta": 0.4}).strikes == ()
