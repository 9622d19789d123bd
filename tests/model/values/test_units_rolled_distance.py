"""A coordinate a rolling contact measures along a straight line is a distance, however
the body it rolls turns: a disk of radius 1/10 written as a number turns by −10 x, and x
was read as an angle, so a new user's ẍ printed in rad/s². By hand, a uniform disk
rolling down a 30° incline: ẍ = −(2/3) g sin 30° = −g/3 = −3.27 m/s² (x up the slope),
N = m g cos 30° and |F| = (m/3) g sin 30°, in newtons."""

from __future__ import annotations

import pytest

import rbdsolve

DISK = """\
parameters: {g: acceleration of gravity}
values: {g: 9.81 m/s^2}
coordinates: [x]
gravity: [0, -g]
bodies:
  disk: {shape: disk, mass: 2, radius: RADIUS}
contacts:
  C: {body: disk, rolls_on: {line: {through: [0, 0], angle: pi/6}}, along: x}
questions:
  - reactions: {forces: [C], from_rest: {x: 1}}
"""


@pytest.mark.parametrize("radius", ["1/10", "10 cm"])
def test_a_distance_rolled_along_a_line_is_in_metres(tmp_path, radius) -> None:
    path = tmp_path / "disk.yaml"
    path.write_text(DISK.replace("RADIUS", radius))
    (solution,) = rbdsolve.solve(path, budget=1200.0)  # a budget far from the work
    assert solution.values["accelerations"]["x"] == pytest.approx(-9.81 / 3, rel=1e-12)
    assert solution.units["accelerations"]["x"] == "m/s²"
    assert solution.units["at"]["C"]["components"]["N_C"] == "N"


def test_a_distance_rolled_along_a_planks_top_is_in_metres(tmp_path) -> None:
    """A cylinder (m, radius 1/10, a number) pushed by m g along a plank's top edge (the
    plank held: a review's scene, by hand): (3/2) m s̈ = m g, s̈ = 2 g/3 — in m/s²."""
    path = tmp_path / "plank.yaml"
    path.write_text("""\
parameters: {m: mass, g: gravity}
values: {m: 2 kg, g: 9.81 m/s^2}
coordinates: [s]
gravity: [0, -g]
bodies:
  plank: {shape: plate, mass: 5, width: 4, height: 1/10, at: [0, 0]}
  cylinder: {shape: cylinder, mass: m, radius: 1/10, height: 1}
contacts:
  C: {body: cylinder, rolls_on: {body: plank, edge: top}, along: s}
forces:
  push: {on: cylinder, force: [m*g, 0]}
questions: [eom]
""")
    (solution,) = rbdsolve.solve(path, budget=1200.0)
    assert solution.values["accelerations"]["s"] == pytest.approx(2 * 9.81 / 3, rel=1e-12)
    assert solution.units["accelerations"]["s"] == "m/s²"
