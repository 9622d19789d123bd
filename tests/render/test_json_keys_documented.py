"""Every key the JSON of a few problems holds is documented in docs/json.md (names of the
problem's own parameters, coordinates, points and bodies aside): `conditions`, `lamda`'s
polynomial, the accuracy steps..."""

from __future__ import annotations

import json
import re

import pytest

from rbdsolve.model.build import build_model
from rbdsolve.problem import load_file
from rbdsolve.render.json import render_report
from rbdsolve.solvers import solve_problem

from conftest import PROBLEMS

DOCS = (PROBLEMS.parent / "docs" / "json.md").read_text(encoding="utf-8")
CASES = ["conditions/bead-on-turning-hoop.yaml", "sg2150-2015-10-29/p2-rod-impact.yaml",
         "examples/pendulum.yaml"]


def keys(tree, out: set) -> set:
    if isinstance(tree, dict):
        out.update(tree)
        for value in tree.values():
            keys(value, out)
    elif isinstance(tree, list):
        for value in tree:
            keys(value, out)
    return out


def names(problem) -> set[str]:
    own = {p.name for p in problem.parameters} | set(problem.unknowns) | {c.name for c in problem.coordinates}
    own |= {p.name for p in problem.points} | {b.name for b in problem.bodies}
    return own | {f"{d}({n})" for n in own for d in ("dot", "ddot")}


@pytest.mark.parametrize("case", CASES)
def test_every_key_is_documented(case) -> None:
    problem = load_file(PROBLEMS / case)
    body = json.loads(render_report(solve_problem(build_model(problem))))
    undocumented = {k for k in keys(body, set()) - names(problem) if not re.search(rf"[`\"]{re.escape(k)}[`\"]", DOCS)}
    assert not undocumented, f"keys missing from docs/json.md: {sorted(undocumented)}"
