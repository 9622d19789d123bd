"""Golden solutions: the printed text of the seed exam and of a dozen examples, kept as
files under tests/golden_text/ (input → expected output, as black's tests keep them),
so that any change to a printed solution shows as a diff to review.

The text is `rbdsolve solve -q FILE` at 80 columns, with the solver's timings masked
("(exact, … s)"). After a change that is meant to alter the text, rewrite the files with

    RBDSOLVE_UPDATE_GOLDEN=1 python3 -m pytest tests/test_golden_text.py

and read the diff (git diff tests/golden_text) before committing it. The answers
themselves are checked against independent derivations in test_golden.py; these files
guard the form.
"""

from __future__ import annotations

import os
import re
from pathlib import Path

import pytest
from click.testing import CliRunner

from rbdsolve.cli import main

from conftest import PROBLEMS, ROOT

GOLDEN = Path(__file__).parent / "golden_text"

CASES = [
    *sorted(p.relative_to(PROBLEMS) for p in (PROBLEMS / "sg2150-2015-10-29").glob("p*.yaml")
            if not p.name.endswith(".expected.yaml")),
    *map(Path, [
        "examples/pendulum.yaml",
        "examples/double-pendulum.yaml",
        "examples/bead-on-ring-spring.yaml",
        "contacts/cylinder-in-cylinder.yaml",
        "contacts/half-disk-rocking.yaml",
        "contacts/yo-yo.yaml",
        "conditions/bead-on-turning-hoop.yaml",
        "impact/ball-hits-pinned-rod.yaml",
        "impact/falling-rod-hits-floor.yaml",
        "inertia/cube-corner.yaml",
        "spin/box-three-sides.yaml",
        "forces/particle-on-sphere.yaml",
        "forces/spool-pulled-at-angle.yaml",
        "forces/atwood-massive-pulley.yaml",
        "kinematics/double-pendulum-tip.yaml",
        "spin/sleeping-top.yaml",
        "frames/rod-on-turning-shaft.yaml",
    ]),
]

TIMING = re.compile(r"\((exact|numeric), [0-9.]+ s")


def solution_text(problem: Path) -> str:
    """Run from the repository's root, so the header names problems/… as a user sees it."""
    result = CliRunner().invoke(main, ["solve", "-q", str(Path("problems") / problem)], env={"COLUMNS": "80"})
    assert result.exit_code == 0, result.output
    return TIMING.sub(r"(\1, … s", result.stdout)


@pytest.mark.parametrize("problem", CASES, ids=str)
def test_printed_solution_is_the_golden_one(problem: Path, monkeypatch) -> None:
    monkeypatch.chdir(ROOT)
    golden = GOLDEN / (str(problem.with_suffix("")).replace("/", "__") + ".txt")
    text = solution_text(problem)
    if os.environ.get("RBDSOLVE_UPDATE_GOLDEN"):
        golden.parent.mkdir(exist_ok=True)
        golden.write_text(text, encoding="utf-8")
    assert golden.exists(), f"no golden file {golden.name}: run with RBDSOLVE_UPDATE_GOLDEN=1"
    assert text == golden.read_text(encoding="utf-8"), (
        f"the printed solution of {problem} changed: if meant, rewrite with RBDSOLVE_UPDATE_GOLDEN=1 "
        "and review the diff")
