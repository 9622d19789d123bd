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

from rbdsolve.errors import InputError, Location, printable, shown
from rbdsolve.problem.loader import load_text
from rbdsolve.problem.schema import Problem
from rbdsolve.problem.yamlnodes import MAX_DEPTH, MAX_FILE_BYTES, MAX_NODES, read_text


def load_string(text: str, name: str = "<string>") -> Problem:
    """YAML text (a whole problem file's contents) -> Problem, under a file's limits."""
    _check_name(name)
    if not isinstance(text, str):
        raise InputError(f"expected the YAML text of a problem, found {type(text).__name__}", Location(name, 1, 1))
    if len(text) > MAX_FILE_BYTES:  # refused before it is encoded: the limit is in bytes, each character ≥ 1
        raise InputError(f"file is more than {MAX_FILE_BYTES} bytes; the limit is {MAX_FILE_BYTES} bytes",
                         Location(name, 1, 1))  # as a file's (problem/yamlnodes.py)
    try:
        data = text.encode("utf-8")
    except UnicodeEncodeError as exc:  # a lone surrogate ('\ud800'): no UTF-8 file holds one
        raise InputError(f"a lone surrogate ({printable(text[exc.start])}) in the text, which is not a character; "
                         "remove it", _place(text, exc.start, name)) from None
    return load_text(read_text(name, data), name)


def _check_name(name: object) -> None:
    if not isinstance(name, str):
        raise InputError(f"name: expected text to call the problem by in messages, found {shown(name)}")


def _place(text: str, index: int, name: str) -> Location:
    line = text.count("\n", 0, index) + 1
    return Location(name, line, index - (text.rfind("\n", 0, index) + 1) + 1)


def load_data(data: Mapping, name: str = "<dict>") -> Problem:
    """A mapping of plain data (text, numbers, booleans, None, lists, mappings), as
    ``yaml.safe_load`` would give for a problem file -> Problem."""
    return load_string(problem_yaml(data, name), name)


def problem_yaml(data: Mapping, name: str = "<dict>") -> str:
    """The mapping as the YAML text the loader reads (and its messages' lines refer to),
    under a file's limits: the data is measured as it is walked, so that a 5 MB title
    or a million entries are refused before any YAML is written."""
    _check_name(name)
    if not isinstance(data, Mapping):
        raise InputError(f"expected a mapping of a problem's sections, found {type(data).__name__}", Location(name, 1, 1))
    return yaml.safe_dump(_Walk(name).plain(data, ()), sort_keys=False, allow_unicode=True, width=10_000)


class _Walk:
    """``value`` as data safe_dump writes: mappings with text keys, lists, scalars; a
    Fraction as its text (3/4), which the expression parser reads exactly. Counts the
    characters of text and the entries met, against the limits of a file."""

    def __init__(self, name: str):
        self.name, self.size, self.nodes = name, 0, 0

    def plain(self, value: object, path: tuple[str | int, ...]) -> object:
        where = Location(self.name, 1, 1, path)
        if len(path) > MAX_DEPTH:
            raise InputError("the data is nested too deeply", where)
        self.nodes += 1
        if self.nodes > MAX_NODES:
            raise InputError(f"the data has more than {MAX_NODES} entries; the limit is {MAX_NODES}", where)
        if isinstance(value, Mapping):
            return {self._key(key, path): self.plain(item, (*path, str(key))) for key, item in value.items()}
        if isinstance(value, (list, tuple)):
            return [self.plain(item, (*path, i)) for i, item in enumerate(value)]
        if isinstance(value, bool) or value is None:
            return value
        if isinstance(value, Fraction):
            return self._text(str(self._finite(value, where)), where)
        if isinstance(value, (int, float)):
            self._text(str(self._finite(value, where)), where)  # counted as the text it becomes
            return value
        if isinstance(value, str):
            return self._text(value, where)
        raise InputError(f"expected text, a number, a list or a mapping, found {type(value).__name__}; "
                         "write an expression as text ('r/2 * sin(theta)')", where)

    def _key(self, key: object, path: tuple[str | int, ...]) -> str:
        if not isinstance(key, (str, int)) or isinstance(key, bool):
            raise InputError(f"expected text keys, found {shown(key)}", Location(self.name, 1, 1, path))
        return self._text(str(self._finite(key, Location(self.name, 1, 1, path))), Location(self.name, 1, 1, path))

    def _text(self, text: str, where: Location) -> str:
        self.size += len(text)
        if self.size > MAX_FILE_BYTES:
            raise InputError(f"the data holds more than {MAX_FILE_BYTES} characters of text; the limit of a file is "
                             f"{MAX_FILE_BYTES} bytes", where)
        return text

    @staticmethod
    def _finite(number, where: Location):
        """An integer (or a fraction's parts) within the parser's range: 10**5000 is
        refused here, where Python would refuse to write its 5,000 digits."""
        if isinstance(number, (int, Fraction)) and not isinstance(number, bool) and \
                max(abs(Fraction(number).numerator), Fraction(number).denominator) > 10**300:
            raise InputError("the number is too large (the limit is 1e300)", where)
        return number
