"""A parameter's entry in ``values:``: a number, or what to draw per exam variant.

    values: {g: 9.81, m: {range: [1, 5], step: 0.5}, r: {choices: [0.5, 1, 2]}}

A number is the parameter's value; a range (with its step, so that students get tidy
numbers) or a list of choices is read into a :class:`ValueRange` for ``rbdsolve
variants``. Numbers are read by ``parse_number`` only: no text from the file reaches
an expression parser.
"""

from __future__ import annotations

from fractions import Fraction

from rbdsolve.errors import InputError
from rbdsolve.problem import expr as ex
from rbdsolve.problem.readers import check_keys, describe, expect_scalar
from rbdsolve.problem.schema import Parameter, ValueRange
from rbdsolve.problem.yamlnodes import Map, Node, Seq

MAX_GRID = 10**6  # values in one range's grid: a finer step is a typo, not an exam


def number(node: Node) -> Fraction:
    """A plain number, located: '9.81', '1/2', '-3'."""
    if isinstance(node, Map):
        raise InputError("expected a number, or a range such as {range: [1, 5], step: 0.5}, "
                         "found a mapping", node.loc)
    scalar = expect_scalar(node, "a number")
    return ex.parse_number(scalar.text, scalar.loc, scalar.plain)


def value_range(param: Parameter, node: Map) -> ValueRange:
    """``{range: [low, high], step: s}`` or ``{choices: [a, b, …]}`` for ``param``."""
    check_keys(node, (), ("range", "step", "choices"), f"the values of '{param.name}'")
    if node.get("choices") is not None:
        if node.get("range") is not None or node.get("step") is not None:
            raise InputError("give either 'range' (with 'step') or 'choices', not both", node.loc)
        return _choices(param, node.get("choices"), node)
    if node.get("range") is None:
        raise InputError(f"missing 'range' in the values of '{param.name}': write "
                         f"{{range: [low, high], step: s}} or {{choices: [a, b]}}", node.loc)
    low, high = _bounds(node.get("range"))
    step = _step(node, low, high)
    if param.positive and low <= 0:
        raise InputError(f"'{param.name}' is declared positive, but its range starts at "
                         f"{_text(low)}", node.get("range").loc)
    return ValueRange(param.name, low, high, step, (), node.loc)


def _bounds(node: Node) -> tuple[Fraction, Fraction]:
    if not isinstance(node, Seq) or len(node.items) != 2:
        found = f"a list of {len(node.items)}" if isinstance(node, Seq) else describe(node)
        raise InputError(f"expected [low, high], found {found}", node.loc)
    low, high = (number(item) for item in node.items)
    if low >= high:
        raise InputError(f"the range's low end {_text(low)} must be below its high end {_text(high)}",
                         node.loc)
    return low, high


def _step(node: Map, low: Fraction, high: Fraction) -> Fraction:
    """The step: required, so that the values drawn are the tidy ones a teacher means."""
    raw = node.get("step")
    if raw is None:
        raise InputError(f"missing 'step' for the range [{_text(low)}, {_text(high)}]: values are "
                         "low + k·step, e.g. step: 0.5", node.loc)
    step = number(raw)
    if step <= 0:
        raise InputError(f"the step must be positive, found {_text(step)}", raw.loc)
    if step > high - low:
        raise InputError(f"a step of {_text(step)} leaves only the value {_text(low)} in "
                         f"[{_text(low)}, {_text(high)}]; use a smaller step, or a number", raw.loc)
    if (high - low) / step >= MAX_GRID:
        raise InputError(f"a step of {_text(step)} gives more than {MAX_GRID} values; use a larger step",
                         raw.loc)
    return step


def _choices(param: Parameter, node: Node, where: Map) -> ValueRange:
    if not isinstance(node, Seq) or not node.items:
        found = "an empty list" if isinstance(node, Seq) else describe(node)
        raise InputError(f"expected a list of numbers to choose from, found {found}", node.loc)
    values = tuple(number(item) for item in node.items)
    for item, value in zip(node.items, values):
        if param.positive and value <= 0:
            raise InputError(f"'{param.name}' is declared positive, found {_text(value)}", item.loc)
    return ValueRange(param.name, min(values), max(values), Fraction(0), values, where.loc)


def _text(value: Fraction) -> str:
    """A number as a file would write it: 2, 0.25, 9.81; 1/3 where no decimal is exact."""
    decimal = repr(float(value)).removesuffix(".0")
    return decimal if Fraction(decimal) == value else str(value)
