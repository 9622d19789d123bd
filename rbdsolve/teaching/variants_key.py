"""The variants table read back for grading: ``read_key(variants.json) -> Key``.

The table is the JSON ``rbdsolve variants -o variants.json`` writes (one row per
variant: its parameter values, its numeric answers, its kinds). It may have been edited
by hand or come from elsewhere, so everything in it is checked: strict JSON (no NaN),
numbers a float holds (``10**400`` and ``1e999`` are refused where they stand, not
turned into an OverflowError or an infinity), no more variants than ``rbdsolve
variants`` makes, every row of the declared width. Each refusal is one located line.
"""

from __future__ import annotations

import json
import math
import re
from dataclasses import dataclass

from rbdsolve.errors import InputError, Location, clipped
from rbdsolve.teaching.files import read_file

MAX_VARIANTS = 100_000  # as rbdsolve variants' --count
MAX_DIGITS = 308  # an integer longer than this is past a float's range: refused before int() reads it


@dataclass(frozen=True)
class Key:
    """The variants table as read back: per variant number, its numbers and kinds."""

    file: str
    problem: str
    columns: tuple[str, ...]
    kind_columns: tuple[str, ...]
    numbers: dict[int, tuple[float | None, ...]]
    kinds: dict[int, tuple[str | None, ...]]


def read_key(path: str) -> Key:
    """The JSON table of ``rbdsolve variants``; an InputError for anything else."""
    text = read_file(path)
    try:
        body = json.loads(text, parse_constant=_refuse_constant, parse_int=_integer, parse_float=_decimal)
    except json.JSONDecodeError as exc:
        raise InputError(f"not JSON: {exc.msg}", Location(path, exc.lineno, exc.colno)) from None
    except _OutOfRange as exc:
        raise InputError(f"the number {clipped(exc.literal)} is out of range (a float holds magnitudes up to "
                         "about 1e308)", _found(text, exc.literal, path)) from None
    except ValueError as exc:  # NaN or Infinity, refused by _refuse_constant
        raise InputError(f"not strict JSON: {exc}", Location(path, 1, 1)) from None
    except RecursionError:
        raise InputError("the JSON is nested too deeply", Location(path, 1, 1)) from None
    if not isinstance(body, dict) or not isinstance(body.get("rows"), list) or "columns" not in body:
        raise InputError("not a variants table (write one with: rbdsolve variants PROBLEM -o variants.json)",
                         Location(path, 1, 1))
    if len(body["rows"]) > MAX_VARIANTS:
        raise InputError(f"{len(body['rows']):,} variants; the limit is {MAX_VARIANTS:,}, as rbdsolve variants'",
                         Location(path, 1, 1, ("rows",)))
    columns = _strings(body, "columns", path)
    kind_columns = _strings(body, "kind_columns", path)
    numbers, kinds = {}, {}
    for i, row in enumerate(body["rows"]):
        variant, values, words = _row(row, i, len(columns), len(kind_columns), path)
        numbers[variant], kinds[variant] = values, words
    return Key(path, str(body.get("file", "")), columns, kind_columns, numbers, kinds)


class _OutOfRange(ValueError):
    """A JSON number no float holds (10**400, 1e999), or an integer past Python's
    4,300-digit limit for reading one: its literal, to find it in the text."""

    def __init__(self, literal: str):
        super().__init__(literal)
        self.literal = literal


def _integer(literal: str) -> int:
    if len(literal.lstrip("-")) > MAX_DIGITS:
        raise _OutOfRange(literal)
    return int(literal)


def _decimal(literal: str) -> float:
    value = float(literal)
    if not math.isfinite(value):
        raise _OutOfRange(literal)
    return value


def _refuse_constant(name: str) -> float:
    raise ValueError(f"{name} is not a number in strict JSON")


def _found(text: str, literal: str, path: str) -> Location:
    """Where ``literal`` first stands in ``text`` as a whole number (not inside a longer
    one or a word): the line and column of a refusal the JSON reader cannot place."""
    match = re.search(rf"(?<![\w.+-]){re.escape(literal)}(?![\w.])", text)
    if match is None:
        return Location(path, 1, 1)
    start = match.start()
    return Location(path, text.count("\n", 0, start) + 1, start - (text.rfind("\n", 0, start) + 1) + 1)


def _strings(body: dict, key: str, path: str) -> tuple[str, ...]:
    value = body.get(key, [])
    if not isinstance(value, list) or not all(isinstance(v, str) for v in value):
        raise InputError(f"'{key}' must be a list of names", Location(path, 1, 1, (key,)))
    return tuple(value)


def _row(row: object, i: int, width: int, kind_width: int, path: str):
    where = Location(path, 1, 1, ("rows", i))
    if not isinstance(row, dict) or not isinstance(row.get("variant"), int) or isinstance(row.get("variant"), bool):
        raise InputError("expected {\"variant\": N, \"answers\": [...]}", where)
    values, words = row.get("answers"), row.get("kinds", [None] * kind_width)
    if not isinstance(values, list) or len(values) != width or not all(
            v is None or (isinstance(v, (int, float)) and not isinstance(v, bool)) for v in values):
        raise InputError(f"'answers' must be {width} numbers (or null), one per column", where)
    if not isinstance(words, list) or len(words) != kind_width or not all(w is None or isinstance(w, str) for w in words):
        raise InputError(f"'kinds' must be {kind_width} words (or null), one per kind column", where)
    return row["variant"], tuple(None if v is None else float(v) for v in values), tuple(words)
