"""Walk an answers tree (frozen dataclasses, mappings, tuples, matrices) leaf by leaf.

A walk, not vocabulary: report/ holds the answers as data (and ``Path``, the address of
an answer in them, report/numbers.py); its callers are here beside it (numbers and
units of the answers), and above: render/ (JSON), teaching/ (keys, variants, grading)."""

from __future__ import annotations

import dataclasses
from typing import TYPE_CHECKING, Callable, Iterator, Mapping

import sympy as sp

if TYPE_CHECKING:
    from rbdsolve.report.numbers import Path


def map_leaves(value: object, leaf: Callable[[object], object]) -> object:
    """The same tree as plain JSON-like data, with ``leaf`` applied to each leaf:
    dataclasses and mappings become dicts, tuples and matrices (nested) lists."""
    return map_paths(value, lambda _, x: leaf(x))


def leaves(value: object, path: Path = (), floats: bool = True) -> Iterator[tuple[Path, object]]:
    """Each leaf of an answers tree with its path, in the order ``map_leaves`` walks;
    with ``floats`` False, a tuple of floats (a row of a numeric route's n×n matrix) is
    passed over whole, for a caller that looks only at the other leaves."""
    if type(value) is float:  # most leaves of a numeric route (an n×n matrix): no type tests
        if floats:
            yield path, value
    elif dataclasses.is_dataclass(value) and not isinstance(value, type):
        for f in dataclasses.fields(value):
            yield from leaves(getattr(value, f.name), (*path, f.name), floats)
    elif isinstance(value, Mapping):
        for k, v in value.items():
            yield from leaves(v, (*path, str(k)), floats)
    elif isinstance(value, sp.MatrixBase):
        for i, row in enumerate(value.tolist()):
            for j, x in enumerate(row):
                yield from leaves(x, (*path, i, j), floats)
    elif isinstance(value, (list, tuple)):
        if floats or not all(type(v) is float for v in value):
            for i, v in enumerate(value):
                yield from leaves(v, (*path, i), floats)
    else:
        yield path, value


def label(path: Path) -> str:
    """'eigenvalues[1]', 'equilibria[2].at.theta': keys joined by '.', indices 1-based in
    brackets. The one spelling of an answer's name, for the numeric lines of every
    renderer and the columns of the variants table."""
    out = ""
    for part in path:
        if isinstance(part, int):
            out += f"[{part + 1}]"
        else:
            out += f".{part}" if out else part
    return out


Row = Callable[["Path", tuple], list]  # a tuple of floats at a path -> what ``leaf`` gives for each, as a list


def map_paths(value: object, leaf: Callable[[Path, object], object], path: Path = (), row: Row | None = None) -> object:
    """``map_leaves`` with each leaf's path given to ``leaf`` too. ``row``, where given,
    maps a whole tuple of floats (a row of a numeric route's n×n matrix) in one call,
    instead of ``leaf`` on each of its entries, and must give the same list."""
    if type(value) is float:  # most leaves of a numeric route (an n×n matrix): no type tests
        return leaf(path, value)
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        return {f.name: map_paths(getattr(value, f.name), leaf, (*path, f.name), row) for f in dataclasses.fields(value)}
    if isinstance(value, Mapping):
        return {str(k): map_paths(v, leaf, (*path, str(k)), row) for k, v in value.items()}
    if isinstance(value, sp.MatrixBase):
        return [[map_paths(x, leaf, (*path, i, j), row) for j, x in enumerate(r)] for i, r in enumerate(value.tolist())]
    if isinstance(value, (list, tuple)):
        if row is not None and value and all(type(v) is float for v in value):
            return row(path, value)
        return [map_paths(v, leaf, (*path, i), row) for i, v in enumerate(value)]
    return leaf(path, value)
