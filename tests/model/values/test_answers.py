"""One question's answers at the parameter values in one call (model/values/answers.py):
their numbers, the warnings on those that have none, their units and the numeric
block. Expected values by hand."""

from __future__ import annotations

import math
from fractions import Fraction

import sympy as sp

from conftest import PROBLEMS
from rbdsolve.model.build import build_model
from rbdsolve.model.values.answers import NOTHING, valued
from rbdsolve.problem import load_file
from rbdsolve.report.numbers import Named


def _pendulum():
    return build_model(load_file(PROBLEMS / "examples" / "pendulum.yaml"))


def _answers(model) -> dict:
    """ω = √(3g/(2l)) (the pendulum's), √(l − 4) (not real at l = 3), 1/(l − 3) (no finite value at l = 3)."""
    m, l, g = (model.symbols.parameters[n] for n in ("m", "l", "g"))
    return {"omega": sp.sqrt(3 * g / (2 * l)), "imaginary": sp.sqrt(l - 4), "blows_up": m / (l - 3)}


def test_the_numbers_units_warnings_and_lines_at_the_values() -> None:
    model = _pendulum().with_values({"m": 2, "l": 3, "g": Fraction(981, 100)})
    found = valued(_answers(model), model, "modes", lambda: [Named(("omega",), sp.Symbol("omega"))])
    assert math.isclose(found.values["omega"], math.sqrt(3 * 9.81 / 6), rel_tol=1e-12)
    assert found.values["imaginary"] is None and found.values["blows_up"] is None
    assert found.units["omega"] == "rad/s"  # √(g/l): 1/s, a rate
    assert [("blows_up" in w, "imaginary" in w) for w in found.warnings] == [(True, False), (False, True)]
    (line,) = found.lines
    assert line.unit == "rad/s" and math.isclose(float(line.relation.rhs), math.sqrt(4.905), rel_tol=1e-6)


def test_nothing_without_values_and_no_block_without_names() -> None:
    model = _pendulum()
    assert valued(_answers(model), model, "modes", lambda: []) == NOTHING
    given = model.with_values({"m": 2, "l": 3, "g": Fraction(981, 100)})
    assert valued(_answers(given), given, "modes", None).lines == ()


def test_a_critical_value_of_a_parameter_given_in_degrees_is_in_rad_with_its_degrees() -> None:
    """θ₀ given as 30 deg is an angle: a critical value of it, 2θ₀ here (π/3 = 1.0472 rad,
    60° by hand), prints in rad with its degrees, as a coordinate's angle does; m's in kg."""
    from rbdsolve.model.values.units import answer_units
    from rbdsolve.problem import load_text
    from rbdsolve.render.numbers import number_text
    from rbdsolve.solvers.conditions.conditions import CriticalValue
    from rbdsolve.solvers.routes.naming import criticals

    text = (PROBLEMS / "examples" / "pendulum.yaml").read_text()
    text = text.replace("parameters:", "parameters:\n  theta0: angle of release") + \
        "\nvalues: {m: 2, l: 3, g: 9.81, theta0: 30 deg}\n"
    model = build_model(load_text(text))
    theta0, m = model.symbols.parameters["theta0"], model.symbols.parameters["m"]
    answers = {"critical": [CriticalValue("theta0", 2 * theta0), CriticalValue("m", 3 * m)]}
    assert answer_units(answers, model)["critical"] == [{"parameter": None, "value": "rad"},
                                                        {"parameter": None, "value": "kg"}]
    found = valued(answers, model, "", lambda: tuple(criticals(("critical",), answers["critical"])))
    assert [number_text(n) for n in found.lines] == ["θ₀,c = 1.0472 rad (60°)", "m_c = 6 kg"]


def test_the_numeric_block_lists_critical_values_in_the_steps_order() -> None:
    """k_c1 before k_c2 (named in increasing order), whichever the answers found first."""
    from rbdsolve.render.numbers import number_text
    from rbdsolve.solvers.conditions.conditions import CriticalValue
    from rbdsolve.solvers.routes.naming import criticals

    model = _pendulum().with_values({"m": 2, "l": 3, "g": Fraction(981, 100)})
    m, g = (model.symbols.parameters[n] for n in ("m", "g"))
    answers = {"critical": [CriticalValue("l", 3 * m * g), CriticalValue("l", m * g)]}  # found larger first
    found = valued(answers, model, "", lambda: tuple(criticals(("critical",), answers["critical"])))
    assert [number_text(n).split(" = ")[0] for n in found.lines] == ["l_c1", "l_c2"]
    assert [float(n.relation.rhs) for n in found.lines] == [19.62, 58.86]
