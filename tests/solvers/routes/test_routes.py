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
  the largest);
- steady motion: each solve_for value, and ω (the exact ω with the numeric unknowns
  put in: omega0, spin), within its own absolute bound, and within the relative
  error_estimate where it is not zero within that bound;
- equations of motion: both routes' equations (and each frame's) evaluated at random
  states (q, q̇, q̈, t and any prescribed function and its derivatives) agree within
  10 × the estimate relative to the sum of the terms' sizes (the exact route's
  equations hold no rounding, the numeric one's are in products of sines and cosines).
"""

from __future__ import annotations

import math
import re
import time
from fractions import Fraction

import pytest

from rbdsolve.errors import UnsolvedError
from rbdsolve.model.build import build_model
from rbdsolve.problem import load_file
from rbdsolve.problem.schema import QuestionKind
from rbdsolve.report.steps import Route
from rbdsolve.solvers import Options, RouteChoice, partial_by_structure, solve_file, solve_problem, solve_question
from rbdsolve.solvers.routes.budget import OutOfTime, available

from conftest import PROBLEMS, SIMPLE_PENDULUM, solved_file, spin

SAMPLES = [Fraction(13, 10), Fraction(7, 10), Fraction(17, 10), Fraction(11, 10), Fraction(9, 10), Fraction(23, 10)]
KINDS = {QuestionKind.MODES, QuestionKind.EQUILIBRIA, QuestionKind.INERTIA, QuestionKind.STEADY_SPIN,
         QuestionKind.IMPACT, QuestionKind.STEADY_MOTION, QuestionKind.EOM}


def _cases():
    for expected in sorted(PROBLEMS.rglob("*.expected.yaml")):
        path = expected.with_name(expected.name.replace(".expected.yaml", ".yaml"))
        problem = load_file(path)
        if any(q.kind in KINDS for q in problem.questions):
            yield pytest.param(path, id=str(path.relative_to(PROBLEMS)))


def _values(problem, shift: int = 0) -> dict[str, Fraction]:
    given = dict(problem.values)
    return {p.name: given.get(p.name, SAMPLES[(i + shift) % len(SAMPLES)]) for i, p in enumerate(problem.parameters)}


def _with_values(problem):
    """The model with the sample values, shifted along SAMPLES until they satisfy the
    problem's assumptions (J1 > J3, theta < pi/2)."""
    from rbdsolve.errors import InputError

    built = build_model(problem)
    for shift in range(len(SAMPLES)):
        try:
            return built.with_values(_values(problem, shift))
        except InputError:
            continue
    raise AssertionError(f"{problem.file}: no shift of the sample values satisfies its assumptions")


def _both(path):
    """Both routes' solutions, question by question; None for the exact route where the
    structure says it would answer only in part (``auto`` never runs it there: forced,
    a nutation about a steady rate with nested radicals spends its whole budget). Where
    the file gives every value, the model and its exact answers are the golden test's
    (``solved_file``, the same values: solved once in the process, not twice)."""
    problem = load_file(path)
    if all(p.name in dict(problem.values) for p in problem.parameters):
        model, report = solved_file(path)
        known = list(report.solutions)
        assert len(known) == len(problem.questions)
    else:
        model, known = _with_values(problem), [None] * len(problem.questions)
    exact = [None if partial_by_structure(q, model) else
             s if s is not None and s.route is Route.EXACT and s.error is None else
             solve_question(q, model, Options(route=RouteChoice.EXACT))
             for q, s in zip(problem.questions, known)]
    numeric = solve_problem(model, Options(route=RouteChoice.NUMERIC))
    return problem, model, exact, numeric


@pytest.mark.parametrize("path", list(_cases()))
def test_numeric_route_agrees_with_exact(path) -> None:
    problem, model, exact, numeric = _both(path)
    compared = 0
    for question, e, n in zip(problem.questions, exact, numeric.solutions):
        if question.kind not in KINDS or e is None or e.error is not None:
            continue
        if e.values.get("branches") and not any(b["exists_when"] for b in e.values["branches"]):
            # no branch is real at these values (a top spinning below its least spin):
            # the numeric route must find no solution either
            assert n.error is not None and "found no solution" in n.error, n.error
            compared += 1
            continue
        if question.kind is QuestionKind.EQUILIBRIA and not e.answers.equilibria and not e.answers.singular_points:
            # the exact route proved there is none at these values (every root of a polynomial
            # ∂V/∂q found, none real: a half-disk on an incline steeper than asin(4/(3π))):
            # the numeric route must find none either (an error, or its own "never balance")
            assert (n.error is not None and "found no equilibrium" in n.error) or (
                n.error is None and not n.answers.equilibria), n.error
            compared += 1
            continue
        if question.kind is QuestionKind.INERTIA and any(x is None for row in e.values["J"] for x in row):
            # a tensor that is a formula in the coordinates (no 'at:') has no numbers: the
            # numeric route asks for the configuration instead of answering
            assert n.error is not None and "depends on the configuration" in n.error, n.error
            compared += 1
            continue
        assert n.error is None, f"{question.kind.value}: numeric route failed: {n.error}"
        assert n.route.value == "numeric"  # no estimate only where a warning says why (a singular Hessian)
        assert n.error_estimate is not None or any(w.startswith("no error estimate") for w in n.warnings)
        if question.kind is QuestionKind.MODES:
            _same_modes(e, n)
        elif question.kind is QuestionKind.EQUILIBRIA:
            _same_equilibria(e, n, model)
        elif question.kind is QuestionKind.IMPACT:
            _same_tree(e.values, n.values, n.error_estimate)
        elif question.kind is QuestionKind.STEADY_MOTION:
            _same_steady_motion(e, n, model)
        elif question.kind is QuestionKind.EOM:
            _same_equations(e, n, model)
        elif question.kind is QuestionKind.INERTIA:
            _same_numbers(e.values["principal_moments"], n.answers.principal_moments, n.error_estimate,
                          n.answers.absolute_error)  # a zero moment (a rod's) has only the absolute bound
        else:
            _same_numbers(sorted(e.values["moments"]), n.answers.moments, n.error_estimate)
        compared += 1
    assert compared or all(s is None or s.error for s in exact), "nothing compared"


def _same_modes(e, n) -> None:
    if hasattr(e.answers, "modes"):  # about: each, matched equilibrium by equilibrium
        _same_modes_at_each(e, n)
        return
    if hasattr(e.answers, "G"):  # gyroscopic: the frequencies within the roots' bounds, the same stability
        assert n.answers.stability == e.answers.stability
        bound = max(n.answers.root_errors)
        assert len(e.values["frequencies"]) == len(n.answers.frequencies)
        for w, g in zip(e.values["frequencies"], n.answers.frequencies):
            assert abs(g - float(w)) <= bound, (g, w, bound)
        return
    want = [float(x) for x in e.values["eigenvalues"]]
    got = list(n.answers.eigenvalues)
    assert len(got) == len(want)
    for w, g, bound in zip(want, got, n.answers.absolute_errors):
        assert abs(g - w) <= bound, (g, w, bound)
    assert n.answers.motions == tuple(e.answers.motions)
    for shape_e, shape_n, lam in zip(e.values["shapes"], n.answers.shapes, want):
        if shape_e and all(x is not None for x in shape_e) and want.count(lam) == 1:
            assert all(abs(a - b) <= 1e-8 * max(1.0, abs(a)) for a, b in zip(shape_e, shape_n))


def _same_modes_at_each(e, n) -> None:
    """Each equilibrium the exact route answered has the numeric route's equilibrium at
    the same place (angles modulo 2π), with the same eigenvalues within their bounds."""
    numeric = list(n.answers.modes)
    assert len(numeric) == len(e.answers.modes)
    for values, exact in zip(e.values["modes"], e.answers.modes):
        where = [float(x) for x in values["about"].values()]
        (match,) = [m for m in numeric if all(abs(math.remainder(a - b, 2 * math.pi)) < 1e-7
                                                for a, b in zip(where, m.about.values()))]
        for w, g, bound in zip(values["eigenvalues"], match.eigenvalues, match.absolute_errors):
            assert abs(g - float(w)) <= bound, (g, w, bound)


def _same_numbers(want, got, estimate: float, absolute: float = 0.0) -> None:
    assert len(want) == len(got)
    for w, g in zip(want, got):
        assert abs(w - g) <= max(max(10 * estimate, 1e-14) * abs(w), 10 * absolute), (w, g, estimate)


def _same_steady_motion(e, n, model) -> None:
    """Every numeric solution against the exact answers at its unknowns: the exact
    solve_for values hold no unknown; the exact ω may hold omega0 or spin."""
    import sympy as sp

    assert n.answers.solutions
    branches = [b["solved"] for b in e.values.get("branches", [])] or [e.values["solved"]]
    for solution in n.answers.solutions:
        found = {model.symbols.parameters[u]: sp.Float(v, 17) for u, v in solution.unknowns.items() if v is not None}
        # the branch this solution is (several: a heavy top's two precession rates)
        solved = min(branches, key=lambda b: sum(abs(float(v) - solution.solved[q]) for q, v in b.items()
                                                 if v is not None))
        want = {q: float(v) for q, v in solved.items()}
        want.update({f"omega{i}": float(sp.N(w.xreplace({**model.values, **found}), 30))
                     for i, w in enumerate(e.answers.angular_velocity, 1)})
        got = {**solution.solved, **dict(zip(("omega1", "omega2", "omega3"), solution.angular_velocity))}
        assert set(want) == set(got)
        for name, w in want.items():
            bound = solution.absolute_errors[name]
            assert abs(got[name] - w) <= bound, (name, w, got[name], bound)
            if abs(w) > bound:
                assert abs(got[name] - w) <= n.error_estimate * abs(w), (name, w, got[name], n.error_estimate)


def _same_equations(e, n, model) -> None:
    pairs = list(zip(e.answers.equations, n.answers.equations))
    pairs += [(a, b) for fe, fn in zip(e.answers.frames, n.answers.frames) for a, b in zip(fe.equations, fn.equations)]
    assert len(e.answers.frames) == len(n.answers.frames) and all(f.equivalent for f in n.answers.frames)
    for seed in range(3):
        for want, got in pairs:
            at = _random_state((want, got), seed)
            w, g = _at(want, at, model), _at(got, at, model)
            size = sum(abs(_at(term, at, model)) for term in _expanded_terms(want, model))
            assert abs(w - g) <= max(10 * n.error_estimate, 1e-15) * max(size, 1e-300), (want, got, w, g)


def _random_state(exprs, seed: int) -> list[tuple]:
    """A number for t and for every function of t and derivative in ``exprs``, in the
    order to put them in: derivatives first (putting q(t) first would leave
    Derivative(0.7, t)), t last."""
    import random

    import sympy as sp
    from sympy.core.function import AppliedUndef

    from rbdsolve.model.state import t

    rng = random.Random(seed)
    atoms = set().union(*(x.atoms(sp.Derivative, AppliedUndef) for x in exprs))
    ordered = sorted(atoms, key=lambda a: -(a.derivative_count if isinstance(a, sp.Derivative) else 0))
    return [(a, sp.Float(rng.uniform(-2, 2), 30)) for a in ordered] + [(t, sp.Float(rng.uniform(0, 3), 30))]


def _at(expr, at: list[tuple], model) -> float:
    import sympy as sp

    value = expr.xreplace(model.values)
    for atom, number in at:
        value = value.xreplace({atom: number})
    return float(sp.N(value, 30))


def _expanded_terms(expr, model):
    import sympy as sp

    return sp.Add.make_args(sp.expand(expr.xreplace(model.values)))


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


# --- auto's fallback, the budget, and missing values ------------------------------------
#
# A particle at height y under gravity: V = m g y, ∂V/∂y = m g ≠ 0, so no route can find
# an equilibrium. A pendulum: V = −m g l cos θ, equilibria θ = 0 (stable) and θ = π.

# ∂V/∂y = m g (tanh y + 2) > 0 (V = m g (log cosh y + 2 y)): no real root, and (unlike a falling
# particle's constant m g, which the loads never balance, or a polynomial's roots all found,
# none real — a square root of y too, now a polynomial unknown: answers, equilibria/uniform.py
# and exact.py) one neither route can prove absent: tanh y is transcendental, and a numeric
# search covers a box
FALLING = """\
parameters: {m: mass, g: gravity}
coordinates: [y]
gravity: [0, -g]
points:
  P: [0, log(cosh(y)) + 2*y]
bodies:
  b: {shape: particle, mass: m, at: P}
questions:
  - equilibria
values: {m: 1, g: 2}
"""

PENDULUM = SIMPLE_PENDULUM + """\
questions:
  - equilibria
values: {m: 1, l: 1, g: 2}
"""


def _problem(text: str):
    from rbdsolve.problem import load_text

    return load_text(text, "scene.yaml")


def _replace_exact(monkeypatch, exact) -> None:
    from rbdsolve import solvers

    family = solvers.FAMILIES[QuestionKind.EQUILIBRIA]
    monkeypatch.setitem(solvers.FAMILIES, QuestionKind.EQUILIBRIA, solvers.Family(exact, family.numeric))


def test_when_both_routes_fail_both_reasons_are_kept_and_the_route_is_the_last() -> None:
    (solution,) = solve_problem(build_model(_problem(FALLING)), Options(route=RouteChoice.AUTO)).solutions
    assert solution.route.value == "numeric"
    assert solution.error.startswith("the exact route could not answer (the equilibrium equations are transcendental")
    assert "nor could the numeric route (a sign-change scan of ∂V/∂q at" in solution.error
    assert solution.error.endswith("found no equilibrium)")


def test_the_route_tag_says_the_numeric_route_answered(monkeypatch) -> None:
    def refuse(question, model, options):
        raise UnsolvedError("too hard")

    _replace_exact(monkeypatch, refuse)
    (solution,) = solve_problem(build_model(_problem(PENDULUM)), Options()).solutions
    assert solution.error is None and solution.route.value == "numeric"
    assert solution.warnings[0].startswith("the exact route could not answer (too hard)")
    assert [eq.stability.value for eq in solution.answers.equilibria] == ["stable", "unstable"]


@pytest.mark.skipif(not available(), reason="no SIGPROF on this platform")
def test_the_numeric_fallback_gets_the_rest_of_the_questions_share(monkeypatch) -> None:
    """Documented (--help, docs/format.md Limits): one budget for the run; on auto with
    every value given the exact route gets half of the question's share. The exact route
    spends all of its half of 1.5 s; the numeric one, with the other half, waiting 0.2 s
    (which spends no processor time), still answers, and the run spends no more than
    its 1.5 s."""
    from rbdsolve import solvers

    def endless(question, model, options):
        spin(float("inf"))

    def slow_numeric(question, model, options):
        time.sleep(0.2)
        return numeric(question, model, options)

    numeric = solvers.FAMILIES[QuestionKind.EQUILIBRIA].numeric
    monkeypatch.setitem(solvers.FAMILIES, QuestionKind.EQUILIBRIA, solvers.Family(endless, slow_numeric))
    start = time.process_time()
    (solution,) = solve_problem(build_model(_problem(PENDULUM)), Options(budget=1.5)).solutions
    assert solution.error is None and solution.route.value == "numeric"
    assert re.search(r"'equilibria' ran out of its share \(0\.7\d s\) of the 1\.5 s budget", solution.warnings[0])
    assert time.process_time() - start < 1.5 + 0.5  # the exact route's half, the numeric answer, the timer's rings


def test_missing_values_names_them_in_order_and_auto_does_not_fall_back(monkeypatch) -> None:
    from rbdsolve.solvers.routes.needed import missing_values

    def refuse(question, model, options):
        raise UnsolvedError("too hard")

    problem = _problem(PENDULUM.replace("values: {m: 1, l: 1, g: 2}\n", "values: {l: 1}\n"))
    model = build_model(problem)
    assert missing_values(model) == ("m", "g")
    assert missing_values(model.with_values({"m": Fraction(1), "g": Fraction(2)})) == ()
    _replace_exact(monkeypatch, refuse)
    (auto,) = solve_problem(model, Options()).solutions
    assert (auto.route.value, auto.error) == ("exact", "too hard")
    (numeric,) = solve_problem(model, Options(route=RouteChoice.NUMERIC)).solutions
    assert numeric.route.value == "numeric"
    assert numeric.error.startswith("the numeric route needs a value for every parameter the answer depends on; give m, g ")


def _summary_out_of_time(monkeypatch) -> None:
    from rbdsolve.solvers.routes import routes

    def out_of_time(model):
        raise OutOfTime(0.5, "the model (T and V)")

    monkeypatch.setattr(routes, "summarize_model", out_of_time)


def test_auto_shows_the_coordinates_only_when_t_and_v_run_out(monkeypatch) -> None:
    _summary_out_of_time(monkeypatch)
    report = solve_file(_problem(PENDULUM), Options(budget=0.5))
    assert report.model.T is None and report.model.V is None
    note, coordinates = report.model.steps
    assert note.text.startswith("warning: the model (T and V) ran out of its 0.5 s budget")
    assert "numeric route" in coordinates.text
    (solution,) = report.solutions
    assert solution.error is None  # the questions still run


@pytest.mark.parametrize("route, values", [(RouteChoice.EXACT, "values: {m: 1, l: 1, g: 2}\n"),
                                           (RouteChoice.AUTO, "values: {l: 1}\n")])
def test_without_a_numeric_fallback_a_model_out_of_time_fails_the_file(monkeypatch, route, values) -> None:
    _summary_out_of_time(monkeypatch)
    problem = _problem(PENDULUM.replace("values: {m: 1, l: 1, g: 2}\n", values))
    with pytest.raises(UnsolvedError, match=r"scene.yaml: the model \(T and V\) ran out of its 0.5 s budget"):
        solve_file(problem, Options(route=route, budget=0.5))


@pytest.mark.skipif(not available(), reason="no SIGPROF on this platform")
def test_auto_falls_back_when_the_real_alarm_rings_in_the_summary(monkeypatch) -> None:
    from rbdsolve.solvers.routes import routes

    def endless(model):
        spin(float("inf"))

    monkeypatch.setattr(routes, "summarize_model", endless)
    report = solve_file(_problem(PENDULUM), Options(budget=1.0))
    assert report.model.T is None and report.model.steps[0].text.startswith("warning: the model (T and V) ran out")


def test_one_reason_both_routes_give_is_said_once(monkeypatch) -> None:
    """A scene that moves with time is refused by both routes alike: one sentence."""
    from rbdsolve import solvers

    def refuse(question, model, options):
        raise UnsolvedError("the scene depends explicitly on time t")

    monkeypatch.setitem(solvers.FAMILIES, QuestionKind.EQUILIBRIA, solvers.Family(refuse, refuse))
    (solution,) = solve_problem(build_model(_problem(PENDULUM)), Options()).solutions
    assert solution.error == "the scene depends explicitly on time t (the exact and the numeric route alike)"


# A rod hinged to a turning arm (problems/frames/rod-on-turning-arm.yaml): its equilibria
# reduce to an irreducible quartic, and no evident root (0, π, ±π/2) solves them. The
# structure says so before any solving: on auto with the values given, the numeric route
# answers first, and its note quotes the reason without asking for values it was given;
# on the exact route alone the refusal says what the numeric route would do.
def test_the_numeric_routes_note_does_not_ask_for_values_it_was_given() -> None:
    from rbdsolve.errors import NUMERIC_REMEDY

    path = PROBLEMS / "frames" / "rod-on-turning-arm.yaml"
    auto = solve_file(load_file(path))
    (equilibria,) = [s for s in auto.solutions if s.question == "equilibria"]
    assert equilibria.solved and equilibria.route.value == "numeric"
    (note,) = [w for w in equilibria.warnings if w.startswith("the exact route would answer only in part")]
    assert "degree 4" in note and NUMERIC_REMEDY not in note
    exact = solve_file(load_file(path), Options(route=RouteChoice.EXACT))
    (refused,) = [s for s in exact.solutions if s.question == "equilibria"]
    assert not refused.solved and "no evident root" in refused.error
    assert "with a value for every parameter the numeric route searches" in refused.error


def test_the_exact_routes_refusal_names_the_parameter_without_a_value() -> None:
    """The same rod with m left open: the exact route's remedy names m, the one the
    numeric route would need, not "the parameters" (a new user's rod on a side spring
    with only m open was told to give values it had); the reason before it unchanged."""
    from rbdsolve.errors import NUMERIC_REMEDY
    from rbdsolve.problem import load_text

    path = PROBLEMS / "frames" / "rod-on-turning-arm.yaml"
    text = path.read_text().replace("values: {m: 1 kg, ", "values: {")
    report = solve_file(load_text(text, "rod.yaml"))
    (refused,) = [s for s in report.solutions if s.question == "equilibria"]
    assert not refused.solved and NUMERIC_REMEDY not in refused.error
    assert "degree 4" in refused.error
    assert "with a value for m the numeric route searches" in refused.error
