"""examples/notebook.py, run headless as a notebook would run it (issue 24): it loads
the seed exam through the API, solves it, substitutes values into a returned sympy
expression and displays results typeset. No network, no Jupyter needed."""

from __future__ import annotations

import math
import runpy
import xml.etree.ElementTree as ET

import pytest

from conftest import ROOT


@pytest.fixture(scope="module")
def run():
    shown: list = []
    namespace = runpy.run_path(str(ROOT / "examples" / "notebook.py"), init_globals={"display": shown.append})
    return namespace, shown


def test_the_whole_seed_exam_is_solved(run) -> None:
    namespace, _ = run
    results = namespace["results"]
    assert len(results) == 6 and all(r.solved for r in results)


def test_values_go_into_a_returned_sympy_expression(run) -> None:
    """ω₁² = 24g/(25r) and ω₂² = 2g/r, the exam's own solution, at g = 9.81, r = 0.4."""
    namespace, _ = run
    got = [float(w) for w in namespace["at_lab"]]
    assert got == pytest.approx([math.sqrt(24 * 9.81 / (25 * 0.4)), math.sqrt(2 * 9.81 / 0.4)], rel=1e-12)


def test_results_are_displayed_typeset(run) -> None:
    _, shown = run
    assert len(shown) == 2
    for obj in shown:
        html = obj._repr_html_()
        root = ET.fromstring(html)  # well-formed: a notebook's HTML is XML too
        assert root.find(".//math/mrow") is not None and root.find(".//span[@class='result']/math") is not None
