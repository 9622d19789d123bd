"""The numeric routes agree with the exact ones on every golden problem, within the
numeric route's own error estimate.

For each problem in problems/ with a golden file and a question that has a numeric
route, every parameter gets a number (the file's value, else a fixed sample), both
routes run, and:

- modes: each numeric λ is within its absolute error bound of the exact λ evaluated
  to 30 digits, with the same motion (a zero λ neutral); shapes agree to 1e-8 (both
  scaled so the first nonzero entry is 1);
- equilibria: the same set of configurations (angles modulo 2π) to 1e-8, with the
  same stability, unless the exact route found a continuum or conditions;
- inertia and steady spin: the principal moments within 10 × the estimate;
- impact: every number of the exact answers within 10 × the estimate (relative to
  the largest).
"""

from __future__ import annotations

import math
from fractions import Fraction

import pytest

from conftest import PROBLEMS
from rbdsolve.model.build import build_model
from rbdsolve.problem import load_file
from rbdsolve.problem.schema import QuestionKind
from rbdsolve.solvers import Options, RouteChoice, solve_problem

SAMPLES = [Fraction(13, 10), Fraction(7, 10), Fraction(17, 10), Fraction(11, 10), Fraction(9, 10), Fraction(23, 10)]
KINDS = {QuestionKind.MODES, QuestionKind.EQUILIBRIA, QuestionKind.INERTIA, QuestionKind.STEADY_SPIN,
         QuestionKind.IMPACT}


def _cases():
    for expected in sorted(PROBLEMS.rglob("*.expected.yaml")):
        path = expected.with_name(expected.name.replace(".expected.yaml", ".yaml"))
        problem = load_file(path)
        if any(q.kind in KINDS for q in problem.questions):
            yield pytest.param(path, id=str(path.relative_to(PROBLEMS)))


def _values(problem) -> dict[str, Fraction]:
    given = dict(problem.values)
    return {p.name: given.get(p.name, SAMPLES[i % len(SAMPLES)]) for i, p in enumerate(problem.parameters)}


def _both(path):
    problem = load_file(path)
    values = _values(problem)
    model = build_model(problem).with_values(values)
    exact = solve_problem(model, Options(route=RouteChoice.EXACT))
    numeric = solve_problem(model, Options(route=RouteChoice.NUMERIC))
    return problem, model, exact, numeric


@pytest.mark.parametrize("path", list(_cases()))
def test_numeric_route_agrees_with_exact(path) -> None:
    problem, model, exact, numeric = _both(path)
    compared = 0
    for question, e, n in zip(problem.questions, exact.solutions, numeric.solutions):
        if question.kind not in KINDS or e.error is not None:
            continue
        assert n.error is None, f"{question.kind.value}: numeric route failed: {n.error}"
        assert n.route.value == "numeric" and n.error_estimate is not None
        if question.kind is QuestionKind.MODES:
            _same_modes(e, n)
        elif question.kind is QuestionKind.EQUILIBRIA:
            _same_equilibria(e, n, model)
        elif question.kind is QuestionKind.IMPACT:
            _same_tree(e.values, n.values, n.error_estimate)
        elif question.kind is QuestionKind.INERTIA:
            _same_numbers(e.values["principal_moments"], n.answers.principal_moments, n.error_estimate)
        else:
            _same_numbers(sorted(e.values["moments"]), n.answers.moments, n.error_estimate)
        compared += 1
    assert compared or all(s.error for s in exact.solutions), "nothing compared"


def _same_modes(e, n) -> None:
    want = [float(x) for x in e.values["eigenvalues"]]
    got = list(n.answers.eigenvalues)
    assert len(got) == len(want)
    for w, g, bound in zip(want, got, n.answers.absolute_errors):
        assert abs(g - w) <= bound, (g, w, bound)
    assert n.answers.motions == tuple(e.answers.motions)
    for shape_e, shape_n, lam in zip(e.values["shapes"], n.answers.shapes, want):
        if shape_e and all(x is not None for x in shape_e) and want.count(lam) == 1:
            assert all(abs(a - b) <= 1e-8 * max(1.0, abs(a)) for a, b in zip(shape_e, shape_n))


def _same_numbers(want, got, estimate: float) -> None:
    assert len(want) == len(got)
    for w, g in zip(want, got):
        assert abs(w - g) <= max(10 * estimate, 1e-14) * abs(w), (w, g, estimate)


def _leaves(tree, path=""):
    if isinstance(tree, dict):
        for k, v in tree.items():
            yield from _leaves(v, f"{path}.{k}")
    elif isinstance(tree, list):
        for i, v in enumerate(tree):
            yield from _leaves(v, f"{path}[{i}]")
    elif isinstance(tree, float):
        yield path, tree


def _same_tree(want: dict, got: dict, estimate: float) -> None:
    """Every number the exact route gives, the numeric route gives too, within 10 × its
    estimate relative to the largest number of the tree."""
    want_leaves, got_leaves = dict(_leaves(want)), dict(_leaves(got))
    want_leaves.pop(".centre_of_percussion", None)  # the exact route's alone: it solves for a parameter
    scale = max((abs(v) for v in want_leaves.values()), default=1.0)
    assert want_leaves and set(want_leaves) <= set(got_leaves)
    for path, w in want_leaves.items():
        assert abs(got_leaves[path] - w) <= max(10 * estimate, 1e-13) * scale, (path, w, got_leaves[path])


def _same_equilibria(e, n, model) -> None:
    if any(eq.conditions for eq in e.answers.equilibria) or e.warnings:
        pytest.skip("the exact equilibria exist under conditions or form a continuum")
    names = model.coordinate_names()
    angles = {name for q, name in zip(model.q, names) if q in model.angles}
    want = [(tuple(v["at"][name] for name in names), eq.stability.value)
            for v, eq in zip(e.values["equilibria"], e.answers.equilibria)]
    got = [(tuple(eq.at[name] for name in names), eq.stability.value) for eq in n.answers.equilibria]
    assert len(got) == len(want), (got, want)
    for qw, sw in want:
        match = [s for qg, s in got if all(_close(a, b, name in angles) for a, b, name in zip(qw, qg, names))]
        assert match == [sw], (qw, sw, got)


def _close(a: float, b: float, angle: bool) -> bool:
    d = a - b
    if angle:
        d = (d + math.pi) % (2 * math.pi) - math.pi
    return abs(d) <= 1e-8 * max(1.0, abs(a))


ZERO_LENGTH = """\
parameters: {m: mass, l: length, k: stiffness, a: offset}
coordinates: [theta]
values: {m: 2, l: 1/2, k: 3, a: 1}
points:
  A: [a, 0]
  P: 2*l * [cos(theta), sin(theta)]
bodies:
  b: {shape: particle, mass: m, at: P}
springs:
  s: {stiffness: k, between: [P, A], natural_length: l}
questions:
  - modes: {about: {theta: 0}}
"""


def test_numeric_route_refuses_where_v_has_no_value() -> None:
    """At θ = 0 the spring's two ends meet (|PA| = 0): its direction, and K, are undefined
    there. The numeric route says so instead of dividing by zero (found by the fuzzer)."""
    from rbdsolve.problem import load_text

    model = build_model(load_text(ZERO_LENGTH, "scene.yaml"))
    (solution,) = solve_problem(model, Options(route=RouteChoice.NUMERIC)).solutions
    assert solution.answers is None and "cannot be evaluated at q = (0)" in solution.error
