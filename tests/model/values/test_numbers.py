"""The numeric block (model/values/numbers.py): each named answer's value under its
printed name, with what a reader wants beside it. Expected values by hand."""

from __future__ import annotations

import math

import sympy as sp

from rbdsolve.form.printers import relation_text, significant_digits
from rbdsolve.render.numbers import note_text, tail_text
from rbdsolve.report.numbers import Meaning, Named
from rbdsolve.model.values.numbers import numbers

W1, M = sp.Symbol("omega_1"), sp.Symbol("M")


def _text(n) -> str:
    return relation_text(n.relation) + tail_text(n)


def test_a_frequency_has_its_period_beside_it() -> None:
    (line,) = numbers([Named(("frequencies", 0), W1, meaning=Meaning.FREQUENCY)],
                      {"frequencies": [sp.Symbol("w")]}, {"frequencies": [2.0]}, {"frequencies": ["rad/s"]})
    assert line.unit == "rad/s"
    assert math.isclose(float(note_text(line.note).split()[1]), math.pi, rel_tol=1e-5)  # 2π/2 s
    assert _text(line).startswith("ω₁ = 2")


def test_a_period_is_printed_to_the_digits_asked_like_its_frequency() -> None:
    """--digits reaches the note beside a number (the period was printed to 6 digits
    whatever was asked): ω = 2 rad/s has the period π s."""
    (line,) = numbers([Named(("frequencies", 0), W1, meaning=Meaning.FREQUENCY)],
                      {"frequencies": [sp.Symbol("w")]}, {"frequencies": [2.0]}, {"frequencies": ["rad/s"]})
    with significant_digits(3):
        assert _text(line) == "ω₁ = 2 rad/s (period 3.14 s)"
    with significant_digits(10):
        assert _text(line) == "ω₁ = 2 rad/s (period 3.141592654 s)"


def test_an_angle_is_also_given_in_degrees() -> None:
    (line,) = numbers([Named(("at",), sp.Symbol("theta"))], {"at": sp.Symbol("x")}, {"at": math.pi / 3}, {"at": "rad"})
    assert note_text(line.note) == "60°"


def test_a_negative_energy_lost_reads_as_an_energy_gained() -> None:
    T_i, T_f = sp.Symbol("T_i"), sp.Symbol("T_f")
    (line,) = numbers([Named(("lost",), T_i - T_f, meaning=Meaning.ENERGY_LOST)], {"lost": sp.Symbol("x")},
                      {"lost": -3.0}, {"lost": "J"})
    assert line.relation.lhs == T_f - T_i and float(line.relation.rhs) == 3 and note_text(line.note) == "an energy gained"


def test_a_fraction_is_also_a_percentage() -> None:
    (line,) = numbers([Named(("f",), sp.Symbol("f"), meaning=Meaning.FRACTION)], {"f": sp.Symbol("x")},
                      {"f": 0.2}, {"f": ""})
    assert note_text(line.note) == "20 %"


def test_a_matrix_of_one_unit_is_one_line_of_mixed_units_one_per_entry() -> None:
    answers = {"M": sp.Matrix([[1, 2], [2, 3]])}
    (one,) = numbers([Named(("M",), M)], answers, {"M": [[1.0, 2.0], [2.0, 3.0]]},
                     {"M": [["kg·m²", "kg·m²"], ["kg·m²", "kg·m²"]]})
    assert one.unit == "kg·m²" and one.relation.rhs == sp.ImmutableMatrix([[1.0, 2.0], [2.0, 3.0]])
    mixed = numbers([Named(("M",), M)], answers, {"M": [[1.0, 2.0], [2.0, 3.0]]}, {"M": [["kg", "kg·m"], ["kg·m", "kg·m²"]]})
    assert [(str(n.relation.lhs), n.unit) for n in mixed] == [("M_11", "kg"), ("M_12", "kg·m"), ("M_22", "kg·m²")]


def test_a_value_not_known_gives_no_line_and_no_dash() -> None:
    assert numbers([Named(("w",), sp.Symbol("omega"))], {"w": sp.Symbol("x")}, {"w": [0.0, None, 120.0]}, {}) == ()
    assert numbers([Named(("w",), sp.Symbol("omega"))], {}, {}, {}) == ()


def test_a_state_is_printed_as_its_names_tuple() -> None:
    theta, phi = sp.symbols("theta phi")
    (line,) = numbers([Named(("at",), sp.Tuple(theta, phi))], {"at": {}}, {"at": {"theta": 0.0, "phi": math.pi}},
                      {"at": {"theta": "rad", "phi": "rad"}})
    assert line.relation.lhs == sp.Tuple(theta, phi) and line.unit == "rad" and note_text(line.note) == "(0°, 180°)"
    assert tail_text(line) == " rad = (0°, 180°)"  # not "rad ((0°, 180°))"


def test_a_value_with_one_parameter_left_open_is_written_with_the_others_put_in() -> None:
    """ω = √(k/m) with m = 2 kg and k left open: ω = 0.707107 √k (1/√2 = 0.7071067811…),
    its unit and k's beside it; with two left open, or a coordinate in it, no line."""
    k, m, x = sp.symbols("k m x", positive=True)
    omega = sp.Symbol("omega")
    (line,) = numbers([Named(("w",), omega)], {"w": sp.sqrt(k / m)}, {"w": None}, {"w": "rad/s"},
                      {m: sp.Integer(2)}, {k: "N/m"})
    coefficient, root = line.relation.rhs.as_coeff_Mul()
    assert math.isclose(float(coefficient), 1 / math.sqrt(2), rel_tol=1e-12) and root == sp.sqrt(k)
    assert line.unit == "rad/s" and note_text(line.note) == "k in N/m"
    assert tail_text(line) == " (in rad/s, k in N/m)"  # the unit in the note: after a sum it would read as a term's
    assert numbers([Named(("w",), omega)], {"w": sp.sqrt(k / m)}, {"w": None}, {"w": None}, {}, {k: "N/m", m: "kg"}) == ()
    assert numbers([Named(("w",), omega)], {"w": sp.sqrt(k * x / m)}, {"w": None}, {"w": "rad/s"},
                   {m: sp.Integer(2)}, {k: "N/m"}) == ()
    assert numbers([Named(("w",), omega)], {"w": sp.sqrt(k / m)}, {"w": None}, {"w": None},
                   {m: sp.Integer(2)}, {k: "N/m"}) == ()  # its unit not known: no line
