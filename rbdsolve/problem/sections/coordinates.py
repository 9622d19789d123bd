"""The ``coordinates:`` section: names, each with its kind and, optionally, whether an
angle is periodic and the range a numeric search covers.

    coordinates: [theta, x]                       # kinds decided from the scene
    coordinates: {theta: angle, x: length}
    coordinates:
      x: {kind: length, range: [0, 2*l]}
      theta: {kind: angle, periodic: false, range: [-2*pi, 2*pi]}   # a spring counts turns

A range is two constants (parameters and numbers, or values with units as a state's:
``[-90 deg, 90 deg]``, ``[0, 50 cm]``), read once the names are declared
(``declared_ranges``). A periodic angle is searched over one turn, so a range needs
``periodic: false``.
"""

from __future__ import annotations

from dataclasses import replace

from rbdsolve.errors import InputError, did_you_mean
from rbdsolve.problem import expr as ex
from rbdsolve.problem.context import Reading
from rbdsolve.problem.readers import check_keys, describe, read_bool
from rbdsolve.problem.schema import Coordinate, CoordinateKind
from rbdsolve.problem.yamlnodes import Map, Node, Scalar, Seq

KINDS = [k.value for k in CoordinateKind]  # auto: decided from how it enters (docs/format.md)


def coordinate(reading: Reading, name: str, key: Scalar, options: Node | None) -> tuple[Coordinate, Node | None]:
    """The coordinate with its kind and 'periodic'; its range node, read later."""
    if options is None:
        return Coordinate(name, CoordinateKind.AUTO, key.loc), None
    if isinstance(options, Scalar):
        return Coordinate(name, _kind(options), key.loc), None
    if not isinstance(options, Map):
        raise InputError(f"expected a coordinate kind (angle or length) or {{kind: …, range: [low, high]}}, "
                         f"found {describe(options)}", options.loc)
    check_keys(options, (), ("kind", "periodic", "range"), f"coordinate '{name}'")
    kind = _kind(options.get("kind")) if options.get("kind") is not None else CoordinateKind.AUTO
    periodic_node, range_node = options.get("periodic"), options.get("range")
    periodic = read_bool(periodic_node, "true or false") if periodic_node is not None else None
    if periodic is not None and kind is not CoordinateKind.ANGLE:
        raise InputError(f"'periodic' is for an angle: declare 'kind: angle' for '{name}', or leave "
                         "'periodic' out", periodic_node.loc)
    if range_node is not None and kind is CoordinateKind.ANGLE and periodic is not False:
        raise InputError(f"a periodic angle is searched over one turn, (−π, π]; to search '{name}' over "
                         f"a range, add 'periodic: false' ({{kind: angle, periodic: false, range: [0, pi/2]}}: "
                         "a ladder between the floor and the wall, an angle that winds up)", range_node.loc)
    return Coordinate(name, kind, key.loc, periodic), range_node


def _kind(node: Node) -> CoordinateKind:
    if not isinstance(node, Scalar) or node.text not in KINDS:
        text = node.text if isinstance(node, Scalar) else describe(node)
        hint = did_you_mean(text, KINDS) if isinstance(node, Scalar) else ""
        raise InputError(f"unknown coordinate kind '{text}' (expected angle, length or auto){hint}", node.loc)
    return CoordinateKind(node.text)


def declared_ranges(reading: Reading, coordinates: tuple[Coordinate, ...], nodes: dict[str, Node]) -> tuple[Coordinate, ...]:
    """Each declared range read as two constants, low < high where both are numbers."""
    return tuple(replace(c, range=_range(reading, c.name, nodes[c.name])) if c.name in nodes else c
                 for c in coordinates)


def _range(reading: Reading, name: str, node: Node) -> tuple[ex.Expr, ex.Expr]:
    if not isinstance(node, Seq) or len(node.items) != 2:
        raise InputError(f"a range is [low, high], two constants (parameters and numbers, or values such as "
                         f"30 deg or 20 cm); found "
                         f"{describe(node)}", node.loc)
    low, high = (reading.coordinate_value(item, f"the range of '{name}'") for item in node.items)
    a, b = ex.constant_value(low.tree), ex.constant_value(high.tree)
    if a is not None and b is not None and a >= b:
        raise InputError(f"the range of '{name}' is empty: its low end {low.text} is not below its high "
                         f"end {high.text}", node.loc)
    return low, high
