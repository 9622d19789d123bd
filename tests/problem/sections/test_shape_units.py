"""A shape's mass and dimensions with units, as a statement gives them (``mass: 2 kg``,
``radius: 20 cm``, ``half_angle: 60 deg``): read in SI, the same body as the numbers in
SI. Expected moments from scipy's quadrature of the cross-section, not from rbdsolve."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import integrate

from rbdsolve.errors import InputError
from rbdsolve.problem import load_text

SEGMENT = """\
title: a cylinder segment with its sizes in units
bodies:
  seg: {{shape: cylinder_segment, mass: {mass}, radius: {radius}, height: {height}, half_angle: {half},
         at: [0, 0, 0]}}
questions:
  - inertia: {{body: seg}}
"""


def _segment_moments(m: float, r: float, h: float, alpha: float) -> list[float]:
    """J about G in the body's own axes (x across, y into the material, z along), by
    quadrature over the section y ≥ r cos α of the disk of radius r."""
    half = lambda y: math.sqrt(max(r * r - y * y, 0.0))
    def mean(f):
        return integrate.dblquad(lambda x, y: f(x, y), r * math.cos(alpha), r, lambda y: -half(y), half,
                                 epsabs=1e-13, epsrel=1e-11)[0]
    area = mean(lambda x, y: 1.0)
    ybar = mean(lambda x, y: y) / area
    xx = mean(lambda x, y: x * x) / area
    yy = mean(lambda x, y: (y - ybar) ** 2) / area
    return [m * (yy + h * h / 12), m * (xx + h * h / 12), m * (xx + yy)]


def test_units_in_a_shape_are_read_in_si():
    import rbdsolve

    text = SEGMENT.format(mass="2 kg", radius="20 cm", height="100 mm", half="60 deg")
    J = rbdsolve.solve(rbdsolve.loads(text, "seg.yaml"))["inertia"].answers.J_G
    expected = _segment_moments(2.0, 0.2, 0.1, math.pi / 3)
    got = [float(J[k, k]) for k in range(3)]
    assert np.allclose(got, expected, rtol=1e-9, atol=0)
    assert all(J[i, j] == 0 for i in range(3) for j in range(3) if i != j)


def test_a_unit_is_the_same_as_the_number_in_si():
    with_units = load_text(SEGMENT.format(mass="500 g", radius="20 cm", height="1 m", half="90 deg"), "a.yaml")
    in_si = load_text(SEGMENT.format(mass="1/2", radius="1/5", height="1", half="pi/2"), "b.yaml")
    (a,), (b,) = with_units.bodies[0].parts, in_si.bodies[0].parts
    assert _float(a.mass) == _float(b.mass) == 0.5
    for (name, x), (_, y) in zip(a.dimensions, b.dimensions):
        assert abs(_float(x) - _float(y)) < 1e-15, name


def _float(expr) -> float:
    from rbdsolve.problem.quantities.quantity import approximate
    return approximate(expr.tree)


@pytest.mark.parametrize("key, value, words", [
    ("radius", "2 kg", "'2 kg' is a quantity in kg, not a radius (write a length such as 20 cm)"),
    ("half", "3 m", "'3 m' is a quantity in m, not a half_angle (write an angle such as 60 deg)"),
    ("mass", "2 m", "'2 m' is a quantity in m, not a mass (write a mass such as 2 kg)"),
    ("half", "181 deg", "a half_angle is an angle between 0 and π, or 0 and 180 deg"),
    ("half", "4", "a half_angle is an angle between 0 and π, or 0 and 180 deg"),
])
def test_a_unit_of_the_wrong_kind_is_refused_at_its_key(key, value, words):
    sizes = {"mass": "2 kg", "radius": "20 cm", "height": "10 cm", "half": "60 deg", key: value}
    with pytest.raises(InputError) as caught:
        load_text(SEGMENT.format(**sizes), "p.yaml")
    assert words in str(caught.value)
