"""The JSON contract: every exact answer of every problem reads back with sympify."""

from __future__ import annotations

import json

import pytest
import sympy as sp

from rbdsolve.render.json import render_report

from conftest import PROBLEMS, solved_file

FILES = sorted(p for p in PROBLEMS.rglob("*.yaml") if not p.name.endswith(".expected.yaml"))


PROSE = {"reason", "stability", "motions", "point", "between"}  # words and the file's names, not expressions


def strings(tree):
    if isinstance(tree, str):
        yield tree
    elif isinstance(tree, dict):
        for key, value in tree.items():
            if key not in PROSE:
                yield from strings(value)
    elif isinstance(tree, list):
        for value in tree:
            yield from strings(value)


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.name)
def test_answers_read_back(path) -> None:
    line = json.loads(render_report(solved_file(path)[1]))
    names = {n: sp.Symbol(n, positive=True) for n in line["symbols"]}
    for text in [line["model"]["T"], line["model"]["V"]]:
        if text is not None:
            sp.sympify(text, locals=names)
    for result in line["results"]:
        for text in strings(result["answers"] or {}):
            expr = sp.sympify(text, locals=names)  # raises if not readable
            assert isinstance(expr, (sp.Basic, bool)), text  # a condition that always holds is "True"


def test_a_number_that_is_not_finite_is_a_bug_not_a_nan_token() -> None:
    # Strict JSON has no NaN or Infinity: the renderer refuses them (allow_nan=False)
    # instead of writing tokens that strict readers reject.
    from rbdsolve.errors import InternalError
    from rbdsolve.report.steps import ModelSummary, ProblemReport, Route, Solution

    bad = Solution("modes", Route.NUMERIC, None, (), error_estimate=float("inf"))
    report = ProblemReport("f.yaml", "t", "", "", ModelSummary((), None, None, ()), (bad,))
    with pytest.raises(InternalError, match="not finite"):
        render_report(report)
