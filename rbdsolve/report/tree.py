"""Walk an answers tree (frozen dataclasses, mappings, tuples, matrices) leaf by leaf."""

from __future__ import annotations

import dataclasses
from typing import Callable, Mapping

import sympy as sp


def map_leaves(value: object, leaf: Callable[[object], object]) -> object:
    """The same tree as plain JSON-like data, with ``leaf`` applied to each leaf:
    dataclasses and mappings become dicts, tuples and matrices (nested) lists."""
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        return {f.name: map_leaves(getattr(value, f.name), leaf) for f in dataclasses.fields(value)}
    if isinstance(value, Mapping):
        return {str(k): map_leaves(v, leaf) for k, v in value.items()}
    if isinstance(value, sp.MatrixBase):
        return [[map_leaves(x, leaf) for x in row] for row in value.tolist()]
    if isinstance(value, (list, tuple)):
        return [map_leaves(v, leaf) for v in value]
    return leaf(value)
