"""A cylinder segment's half_angle given by a parameter: that parameter is an angle, so
`alpha: 60 deg` is π/3 (a new user's segment on a drum was refused: "'alpha' is a
length (bodies.seg.half_angle), found '60 deg'"), and a length for it is refused."""

from __future__ import annotations

import math

import pytest

from rbdsolve.errors import InputError
from rbdsolve.problem import load_text

SEGMENT = """\
parameters: {m: mass, r: radius, h: length, alpha: half-angle of the arc}
values: {m: 2 kg, r: 10 cm, h: 20 cm, alpha: %s}
coordinates: [theta]
bodies:
  seg: {shape: cylinder_segment, mass: m, radius: r, height: h, half_angle: alpha, axis: -y, at: [0, 0], angle: theta}
questions:
  - inertia: {body: seg}
"""


def test_a_half_angle_parameter_takes_degrees() -> None:
    problem = load_text(SEGMENT % "60 deg", "segment.yaml")
    alpha = dict(problem.values)["alpha"]
    assert alpha.angle and math.isclose(alpha.approx, math.pi / 3)


def test_a_half_angle_parameter_given_a_length_is_refused() -> None:
    with pytest.raises(InputError, match="alpha"):
        load_text(SEGMENT % "5 cm", "segment.yaml")
