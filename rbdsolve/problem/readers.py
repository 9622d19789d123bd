"""Small readers over located YAML nodes: a mapping, a scalar, a boolean, known keys.

Each raises an :class:`InputError` that says what was expected and what was found.
"""

from __future__ import annotations

from rbdsolve.errors import InputError, did_you_mean
from rbdsolve.problem.yamlnodes import Map, Node, Scalar


def expect_mapping(node: Node, what: str) -> Map:
    if isinstance(node, Map):
        return node
    raise InputError(f"expected {what} (a mapping), found {describe(node)}", node.loc)


def expect_scalar(node: Node, what: str) -> Scalar:
    if isinstance(node, Scalar) and not node.null:
        return node
    raise InputError(f"expected {what}, found {describe(node)}", node.loc)


def describe(node: Node) -> str:
    if isinstance(node, Scalar):
        return "nothing" if node.null else f"'{node.text}'"
    return node.kind_name


def check_keys(node: Map, required: tuple[str, ...], optional: tuple[str, ...], what: str) -> None:
    allowed = tuple(dict.fromkeys((*required, *optional)))
    for key, _ in node.entries:
        if key.text not in allowed:
            hint = did_you_mean(key.text, allowed) or f" (expected one of: {', '.join(allowed)})"
            raise InputError(f"unknown key '{key.text}' in {what}{hint}", key.loc)
    for key in required:
        if node.get(key) is None:
            raise InputError(f"missing required key '{key}' in {what}", node.loc)


def read_bool(node: Node, what: str) -> bool:
    text = expect_scalar(node, what).text.lower()
    if text in ("true", "yes", "on"):
        return True
    if text in ("false", "no", "off"):
        return False
    raise InputError(f"expected true or false, found '{node.text}'", node.loc)
