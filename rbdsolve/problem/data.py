"""A problem given as Python data (the Python API's ``load_dict``) or as YAML text,
read by the same loader as a file, under the same limits.

A mapping is written out as YAML and read back: one reader, one schema, one set of
messages. Its errors name ``<dict>`` and the key path (``bodies.rod.mass``); their
line and column are those of the mapping written as YAML (``problem_yaml`` shows it).
"""

from __future__ import annotations

from fractions import Fraction
from typing import Mapping

import yaml

from rbdsolve.errors import InputError, Location
from rbdsolve.problem.loader import load_text
from rbdsolve.problem.schema import Problem
from rbdsolve.problem.yamlnodes import MAX_DEPTH, read_text

_SCALARS = (str, int, float, bool, type(None))


def load_string(text: str, name: str = "<string>") -> Problem:
    """YAML text (a whole problem file's contents) -> Problem, under a file's limits."""
    if not isinstance(text, str):
        raise InputError(f"expected the YAML text of a problem, found {type(text).__name__}", Location(name, 1, 1))
    return load_text(read_text(name, text.encode("utf-8")), name)


def load_data(data: Mapping, name: str = "<dict>") -> Problem:
    """A mapping of plain data (text, numbers, booleans, None, lists, mappings), as
    ``yaml.safe_load`` would give for a problem file -> Problem."""
    return load_string(problem_yaml(data, name), name)


def problem_yaml(data: Mapping, name: str = "<dict>") -> str:
    """The mapping as the YAML text the loader reads (and its messages' lines refer to)."""
    if not isinstance(data, Mapping):
        raise InputError(f"expected a mapping of a problem's sections, found {type(data).__name__}", Location(name, 1, 1))
    return yaml.safe_dump(_plain(data, (), name), sort_keys=False, allow_unicode=True, width=10_000)


def _plain(value: object, path: tuple[str | int, ...], name: str) -> object:
    """``value`` as data safe_dump writes: mappings with text keys, lists, scalars; a
    Fraction as its text (3/4), which the expression parser reads exactly."""
    if len(path) > MAX_DEPTH:
        raise InputError("the data is nested too deeply", Location(name, 1, 1, path))
    if isinstance(value, Mapping):
        out = {}
        for key, item in value.items():
            if not isinstance(key, (str, int)) or isinstance(key, bool):
                raise InputError(f"expected text keys, found {type(key).__name__} {key!r}", Location(name, 1, 1, path))
            out[str(key)] = _plain(item, (*path, str(key)), name)
        return out
    if isinstance(value, (list, tuple)):
        return [_plain(item, (*path, i), name) for i, item in enumerate(value)]
    if isinstance(value, Fraction):
        return str(value)
    if isinstance(value, _SCALARS):
        return value
    raise InputError(f"expected text, a number, a list or a mapping, found {type(value).__name__}; "
                     "write an expression as text ('r/2 * sin(theta)')", Location(name, 1, 1, path))
