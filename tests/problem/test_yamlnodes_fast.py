"""problem/yamlnodes.py: libyaml's parser under PyYAML's composer gives PyYAML's nodes."""

from __future__ import annotations

from pathlib import Path

import pytest

from rbdsolve.problem import yamlnodes

pytestmark = pytest.mark.skipif(not yamlnodes._CParser, reason="PyYAML without libyaml")  # noqa: SLF001

ROOT = Path(__file__).resolve().parents[2]
FILES = sorted(str(p) for p in (ROOT / "problems/sg2150-2015-10-29").glob("*.yaml"))[:4] + [
    str(ROOT / "tests/problem/bad/023-coordinates-is-a-number.yaml")]


def _shape(node) -> list:
    """Each node's kind, tag, marks (line, column, index), style and value, in order."""
    out = [(type(node).__name__, node.tag, node.start_mark.line, node.start_mark.column, node.start_mark.index,
            node.end_mark.line, node.end_mark.column, node.end_mark.index, getattr(node, "style", None),
            getattr(node, "flow_style", None))]
    if isinstance(node.value, list):
        for item in node.value:
            for x in (item if isinstance(item, tuple) else (item,)):
                out += _shape(x)
    else:
        out.append(node.value)
    return out


@pytest.mark.parametrize("path", FILES)
def test_the_fast_loader_composes_the_same_nodes(path: str) -> None:
    text = open(path, encoding="utf-8").read()
    fast = yamlnodes._compose_with(yamlnodes._FastLoader, text, path)  # noqa: SLF001
    slow = yamlnodes._compose_with(yamlnodes._ShallowLoader, text, path)  # noqa: SLF001
    assert _shape(fast) == _shape(slow)


def test_bad_yaml_is_reported_as_pyyaml_says_it() -> None:
    # An unclosed flow sequence: PyYAML's own words, located at the line of the '['.
    with pytest.raises(Exception) as fast:
        yamlnodes.parse_yaml("a: [1, 2\nb: 3\n", "x.yaml")
    with pytest.raises(Exception) as slow:
        yamlnodes._compose_with(yamlnodes._ShallowLoader, "a: [1, 2\nb: 3\n", "x.yaml")  # noqa: SLF001
    assert "x.yaml:1:" in str(fast.value) and type(slow.value).__name__ in ("ParserError", "ScannerError")
