"""Parameter values given from outside a problem file (``--set NAME=VALUE`` on the
command line, ``values={...}`` in the Python API), read by the file's own parsers and
checked against the problem: one home for both, so the two say the same things.

Nothing here imports sympy.
"""

from __future__ import annotations

import math
from fractions import Fraction
from typing import Mapping

from rbdsolve.errors import InputError, Location, did_you_mean, shown
from rbdsolve.problem.quantities.quantity import Value, parse_value
from rbdsolve.problem.quantities.ranges import parameter_value
from rbdsolve.problem.schema import Problem

OPTION = "--set {}"  # how a value given on the command line is named in a message
LIMIT = 10**300  # as a file's numbers (problem/quantities/quantity.py): 10**5000 is refused before it is written out


def read_value(name: str, text: str, said: str = OPTION) -> Value:
    """``text`` (9.81, pi/6, 30 cm) as a value, an error named as ``said`` names it."""
    try:
        return parse_value(text, _where(name))
    except InputError as exc:  # said as the option, not as a place in a file
        raise InputError(f"{said.format(name)}: {exc.message}") from None


def value_text(name: str, value: object, said: str) -> str:
    """A value given in Python (an int, a float, a Fraction, a sympy number, or text as
    in ``values:``) as the text the file's parser reads: a float by its repr, which
    reads back to the same float."""
    if isinstance(value, bool) or value is None:
        raise InputError(f"{said.format(name)}: expected a number, found {value!r}")
    if isinstance(value, float) and not math.isfinite(value):
        raise InputError(f"{said.format(name)}: expected a finite number, found {value!r}")
    if isinstance(value, (int, Fraction)) and max(abs(Fraction(value).numerator), Fraction(value).denominator) > LIMIT:
        raise InputError(f"{said.format(name)}: the number is too large (the limit is 1e300)")
    if isinstance(value, (str, int, Fraction)):
        return str(value)
    if isinstance(value, float):
        return repr(value)
    if hasattr(value, "is_number") and getattr(value, "is_number"):  # a sympy number: pi/6, sqrt(2)
        try:
            return str(value)
        except ValueError:  # an Integer of more than 4,300 digits: Python will not write it
            raise InputError(f"{said.format(name)}: the number is too large (the limit is 1e300)") from None
    raise InputError(f"{said.format(name)}: expected a number or its text (9.81, 'pi/6', '30 cm'), "
                     f"found {type(value).__name__}")


def given_values(values: object, said: str) -> dict[str, Value]:
    """Values given in Python (the API's ``values={'m': 2, 'l': '30 cm'}``), each read as
    ``--set`` reads its text: a mapping of parameter names (text) to numbers or text."""
    if values is None:
        return {}
    if not isinstance(values, Mapping):
        raise InputError(f"values: expected a mapping of parameter names to values (values={{'m': 2}}), "
                         f"found {shown(values)}")
    out = {}
    for name, value in values.items():
        if not isinstance(name, str):
            raise InputError(f"values: a parameter's name is text, found {shown(name)}")
        out[name] = read_value(name, value_text(name, value, said), said)
    return out


def checked_values(values: Mapping[str, Value], problem: Problem, said: str = OPTION) -> dict[str, Value]:
    """Every value names a parameter of ``problem``, positive ones positive, of the
    parameter's dimension where it is known; a bare number takes its declared unit."""
    names = [p.name for p in problem.parameters]
    dimensions = problem.dimension_map()
    out = {}
    for name, value in values.items():
        if name not in names:
            raise InputError(f"{said.format(name)}: {problem.file} has no parameter '{name}'{did_you_mean(name, names)}")
        param = next(p for p in problem.parameters if p.name == name)
        known = (dimensions[name], "in " + problem.file) if name in dimensions else None
        try:
            out[name] = parameter_value(param, value.text, _where(name), True, known)
        except InputError as exc:
            message = exc.message.replace(f"'{name}' is declared positive", "the parameter is positive")
            raise InputError(f"{said.format(name)}: {message}") from None
    return out


def _where(name: str) -> Location:
    return Location("--set", 1, len(name) + 2)
