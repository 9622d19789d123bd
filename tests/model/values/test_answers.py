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
