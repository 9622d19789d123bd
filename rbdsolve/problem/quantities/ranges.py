"""A parameter's entry in ``values:``: a value, or what to draw per exam variant.

    values: {g: 9.81 m/s^2, theta0: pi/6, m: {range: [1, 5], step: 0.5}, r: {choices: [20 cm, 30 cm]}}

A value is the parameter's value (exact: ``pi/6``, ``30 cm``, read by
``problem.quantities.quantity``); a range (with its step, so that students get tidy numbers) or a
list of choices is read into a :class:`ValueRange` for ``rbdsolve variants``. No text
from the file reaches anything but rbdsolve's own parsers.
"""

from __future__ import annotations

from rbdsolve.errors import InputError, Location
from rbdsolve.problem.quantities.quantity import Dimension, Value, parse_value
from rbdsolve.problem.readers import check_keys, describe, expect_scalar
from rbdsolve.problem.schema import Parameter, ValueRange
from rbdsolve.problem.yamlnodes import Map, Node, Seq

MAX_GRID = 10**6  # values in one range's grid: a finer step is a typo, not an exam

# What the reader knows of a parameter's dimension: (dimension, where it was seen).
Known = tuple[Dimension, str] | None


def parameter_value(param: Parameter, text: str, loc: Location, plain: bool, known: Known) -> Value:
    """``text`` as ``param``'s value: in its declared unit when bare, of its dimension
    where that is known, positive when it is declared positive."""
    value = parse_value(text, loc, plain, param.unit)
    check_dimension(param.name, value, loc, known)
    if param.positive and value.approx <= 0:
        raise InputError(f"'{param.name}' is declared positive, found {text.strip()}", loc)
    return value


def check_dimension(name: str, value: Value, loc: Location, known: Known) -> None:
    """A unit that does not fit: a mass given in metres."""
    if known is None or value.dimension is None or value.dimension == known[0]:
        return
    dimension, where = known
    raise InputError(f"'{name}' is {dimension.describe()} ({where}), found '{value.text}', "
                     f"{value.dimension.describe()}", loc)


def number(param: Parameter, node: Node, known: Known = None) -> Value:
    """One value of ``param``'s range or choices, located: '9.81', 'pi/6', '30 cm'."""
    if isinstance(node, Map):
        raise InputError("expected a number, or a range such as {range: [1, 5], step: 0.5}, "
                         "found a mapping", node.loc)
    scalar = expect_scalar(node, "a number")
    value = parse_value(scalar.text, scalar.loc, scalar.plain, param.unit)
    check_dimension(param.name, value, scalar.loc, known)
    return value


def value_range(param: Parameter, node: Map, known: Known = None) -> ValueRange:
    """``{range: [low, high], step: s}`` or ``{choices: [a, b, …]}`` for ``param``."""
    check_keys(node, (), ("range", "step", "choices"), f"the values of '{param.name}'")
    if node.get("choices") is not None:
        if node.get("range") is not None or node.get("step") is not None:
            raise InputError("give either 'range' (with 'step') or 'choices', not both", node.loc)
        return _choices(param, node.get("choices"), node, known)
    if node.get("range") is None:
        raise InputError(f"missing 'range' in the values of '{param.name}': write "
                         f"{{range: [low, high], step: s}} or {{choices: [a, b]}}", node.loc)
    low, high = _bounds(param, node.get("range"), known)
    step = _step(param, node, low, high, known)
    if param.positive and low.approx <= 0:
        raise InputError(f"'{param.name}' is declared positive, but its range starts at "
                         f"{_text(low)}", node.get("range").loc)
    return ValueRange(param.name, low, high, step, (), node.loc)


def _bounds(param: Parameter, node: Node, known: Known) -> tuple[Value, Value]:
    if not isinstance(node, Seq) or len(node.items) != 2:
        found = f"a list of {len(node.items)}" if isinstance(node, Seq) else describe(node)
        raise InputError(f"expected [low, high], found {found}", node.loc)
    low, high = (number(param, item, known) for item in node.items)
    if low.approx >= high.approx:
        raise InputError(f"the range's low end {_text(low)} must be below its high end {_text(high)}",
                         node.loc)
    return low, high


def _step(param: Parameter, node: Map, low: Value, high: Value, known: Known) -> Value:
    """The step: required, so that the values drawn are the tidy ones a teacher means."""
    raw = node.get("step")
    if raw is None:
        raise InputError(f"missing 'step' for the range [{_text(low)}, {_text(high)}]: values are "
                         "low + k·step, e.g. step: 0.5", node.loc)
    step = number(param, raw, known)
    if step.approx <= 0:
        raise InputError(f"the step must be positive, found {_text(step)}", raw.loc)
    if step.approx > (high.approx - low.approx) * (1 + 1e-12):
        raise InputError(f"a step of {_text(step)} leaves only the value {_text(low)} in "
                         f"[{_text(low)}, {_text(high)}]; use a smaller step, or a number", raw.loc)
    if (high.approx - low.approx) / step.approx >= MAX_GRID:
        raise InputError(f"a step of {_text(step)} gives more than {MAX_GRID} values; use a larger step",
                         raw.loc)
    return step


def _choices(param: Parameter, node: Node, where: Map, known: Known) -> ValueRange:
    if not isinstance(node, Seq) or not node.items:
        found = "an empty list" if isinstance(node, Seq) else describe(node)
        raise InputError(f"expected a list of numbers to choose from, found {found}", node.loc)
    values = tuple(number(param, item, known) for item in node.items)
    for item, value in zip(node.items, values):
        if param.positive and value.approx <= 0:
            raise InputError(f"'{param.name}' is declared positive, found {_text(value)}", item.loc)
    by_size = sorted(values, key=float)
    return ValueRange(param.name, by_size[0], by_size[-1], None, values, where.loc)


def _text(value: Value) -> str:
    """A value as the file wrote it: 2, 0.25, 9.81, pi/6, 30 cm."""
    return value.text
