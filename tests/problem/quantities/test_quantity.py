"""Values as exams write them (problem/quantities/quantity.py): exact constants and SI units.

Expected values are worked out by hand: 30 cm = 30/100 m, 1200 rev/min = 1200·2π/60
rad/s = 40π rad/s, 45° = 45·π/180 = π/4.
"""

from __future__ import annotations

from fractions import Fraction

import pytest
import sympy as sp

from conftest import SIMPLE_PENDULUM
from rbdsolve.errors import InputError, Location
from rbdsolve.model.symbols import exact_number
from rbdsolve.problem import load_text
from rbdsolve.problem.quantities.quantity import LENGTH, MASS, Dimension, parse_value

HERE = Location("p.yaml", 2, 13, ("values", "m"))
RATE = Dimension(time=Fraction(-1))


@pytest.mark.parametrize("text, exact, dimension", [
    ("pi/6", sp.pi / 6, None),
    ("5*pi/36", 5 * sp.pi / 36, None),
    ("sqrt(2)", sp.sqrt(2), None),
    ("2/3", sp.Rational(2, 3), None),
    ("30 cm", sp.Rational(3, 10), LENGTH),
    ("200 g", sp.Rational(1, 5), MASS),
    ("1200 rev/min", 40 * sp.pi, RATE),
    ("1200 rpm", 40 * sp.pi, RATE),
    ("45 deg", sp.pi / 4, Dimension()),
    ("45°", sp.pi / 4, Dimension()),
    ("9.81 m/s^2", sp.Rational(981, 100), Dimension(length=Fraction(1), time=Fraction(-2))),
    ("1e-3 m", sp.Rational(1, 1000), LENGTH),
    ("3 kg*m**2", sp.Integer(3), Dimension(mass=Fraction(1), length=Fraction(2))),
    ("2 N m/rad", sp.Integer(2), Dimension(mass=Fraction(1), length=Fraction(2), time=Fraction(-2))),
    ("0.5 km/h", sp.Rational(5, 36), Dimension(length=Fraction(1), time=Fraction(-1))),
])
def test_values_are_exact_and_in_si(text, exact, dimension) -> None:
    value = parse_value(text, HERE)
    assert sp.simplify(exact_number(value) - exact) == 0
    assert value.approx == pytest.approx(float(exact), rel=1e-15)
    assert value.dimension == dimension


@pytest.mark.parametrize("text, message, column", [
    ("30 cmm", "unknown unit 'cmm' (did you mean 'mm'?)", 16),
    ("heavy", "expected a number, found 'heavy'", 13),
    ("2 A", "the unit 'A' measures [current]", 15),
    ("1 m/", "the unit 'm/' ends with an operator", 17),
    ("1e400", "the number 1e400 is out of range", 13),
    ("sqrt(-1)", "'sqrt(-1)' is not a real number", 13),
    ("2 m^9", "the power 9 of a unit is refused", 17),
    ("__import__('os')", "", 13),
    # issue 39: the number's own trouble, not an unknown unit 'e999' or a power 0
    ("1e999 m", "the number 1e999 is out of range (the limit is 1e±300)", 13),
    ("1 m**0.5", "the power 0.5 of a unit is refused: a unit's power is a whole number from -4 to 4", 18),
    ("1 m^-.5", "the power -.5 of a unit is refused", 17),
    ("1e300 ly", "the number 1e300 ly is too large (the limit is 1e300)", 13),  # 9.5e315 m: an overflow
    ("1e200 * 1e200", "the number 1e200 * 1e200 is too large (the limit is 1e300)", 13),
])
def test_bad_values_are_located(text, message, column) -> None:
    with pytest.raises(InputError) as err:
        parse_value(text, HERE)
    assert message in err.value.message and err.value.location.column == column


PENDULUM = "title: Pendulum\nvalues: VALUES\n" + SIMPLE_PENDULUM + "questions:\n  - modes: {about: {theta: 0}}\n"


def test_the_scene_fixes_dimensions_and_a_unit_that_does_not_fit_is_refused() -> None:
    problem = load_text(PENDULUM.replace("VALUES", "{m: 200 g, l: 30 cm, g: 9.81 m/s^2}"))
    assert dict(problem.dimensions) == {"m": MASS, "l": LENGTH, "g": Dimension(length=Fraction(1), time=Fraction(-2))}
    with pytest.raises(InputError) as err:
        load_text(PENDULUM.replace("VALUES", "{m: 2 m}"), "p.yaml")
    assert str(err.value) == "p.yaml:2:13: values.m: 'm' is a mass (bodies.bob.mass), found '2 m', a length"
    with pytest.raises(InputError) as err:
        load_text(PENDULUM.replace("VALUES", "{l: 1 s}"), "p.yaml")
    assert "'l' is a length (bodies.bob" not in err.value.message and "'l' is a length (points)" in err.value.message


def test_a_declared_unit_is_the_unit_of_a_bare_value() -> None:
    text = PENDULUM.replace("{m: mass, l: length, g: gravity}", "{m: mass, l: {unit: cm}, g: gravity}")
    problem = load_text(text.replace("VALUES", "{l: 30, m: 1}"))
    assert problem.value_map()["l"].rational == Fraction(3, 10)
    with pytest.raises(InputError, match="'l' is a length \\(its unit cm\\), found '2 kg', a mass"):
        load_text(text.replace("VALUES", "{l: 2 kg}"))


def test_ranges_take_exact_values_with_units() -> None:
    problem = load_text(PENDULUM.replace("VALUES", "{l: {range: [20 cm, 50 cm], step: 10 cm}, m: {choices: [pi/6, sqrt(2)]}}"))
    length, mass = problem.ranges
    assert length.size == 4 and [length.value(k).rational for k in range(4)] == [
        Fraction(1, 5), Fraction(3, 10), Fraction(2, 5), Fraction(1, 2)]
    assert [sp.simplify(exact_number(v)) for v in mass.choices] == [sp.pi / 6, sp.sqrt(2)]
    angles = load_text(PENDULUM.replace("VALUES", "{m: 1, l: 1, g: {range: [pi/12, pi/3], step: pi/12}}"))
    (g,) = angles.ranges
    assert g.size == 4 and sp.simplify(exact_number(g.value(3)) - sp.pi / 3) == 0


@pytest.mark.parametrize("text, angle", [
    ("30 deg", True), ("30°", True), ("2 rev", True), ("0.5 rad", True), ("30 degree", True),
    ("pi/6", False), ("30", False), ("1200 rev/min", False), ("2 rad/s", False), ("2 N m/rad", False),
    ("30 cm", False),
])
def test_a_value_in_angle_units_alone_is_an_angle(text, angle) -> None:
    """An angle is what the parameter values beside the answers show in degrees too."""
    assert parse_value(text, HERE).angle is angle
