"""problem/usage.py: which declared parameters a file uses (issue 38): every expression of
the scene and the questions counts; values and assumptions do not."""

from __future__ import annotations

from conftest import PROBLEMS
from rbdsolve.problem import load_file, load_text
from rbdsolve.problem.usage import unused_parameters

SCENE = """\
parameters: {m: mass, l: length, g: gravity, theta0: start, c: unused, k: bounded only}
values: {c: 2}
assumptions: [k > 1]
coordinates: [theta]
gravity: [0, -g]
points:
  P: l*[sin(theta), -cos(theta)]
bodies:
  bob: {shape: particle, mass: m, at: P}
questions:
  - energy: {from_rest: {theta: theta0}}
"""


def test_a_value_or_an_assumption_is_no_use_but_a_question_is() -> None:
    """theta0 appears only in a question: used; c only in values, k only in assumptions: not."""
    assert [p.name for p in unused_parameters(load_text(SCENE, "scene.yaml"))] == ["c", "k"]


def test_no_example_declares_a_parameter_it_does_not_use() -> None:
    files = [p for p in PROBLEMS.rglob("*.yaml") if not p.name.endswith(".expected.yaml")]
    assert {str(p.relative_to(PROBLEMS)): [x.name for x in unused_parameters(load_file(p))]
            for p in files if unused_parameters(load_file(p))} == {}
