"""A steady motion exists only where it is real (issue 38, item 1).

By hand, for a symmetric top on a fixed point O, G at a distance h from O on its axis,
I₁ the transverse moment about O, I₃ the axial one, spin s relative to the precessing
triad, tilt θ: the moment balance about O gives

    (I₁ − I₃) cos θ Ω² − I₃ s Ω + m g h = 0,

two real rates iff I₃² s² ≥ 4 (I₁ − I₃) m g h cos θ, i.e. where (I₁ − I₃) cos θ > 0,
s ≥ s_c = 2 √((I₁ − I₃) m g h cos θ)/I₃.

A solid cone (mass m, height H, base radius r) with its tip at O: G is 3H/4 from the
tip, I₃ = 3 m r²/10 and about G across the axis 3 m r²/20 + 3 m H²/80 (integrating the
discs of the cone), so I₁ = 3 m r²/20 + 3 m H²/80 + m (3H/4)² = 3 m (r² + 4 H²)/20.
A disk (mass m, radius R) whose centre is h from O along its axis: I₃ = m R²/2,
I₁ = m R²/4 + m h².
"""

from __future__ import annotations

import json
import math
import random

import pytest
import sympy as sp

from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.render.json import report_object
from rbdsolve.solvers import solve_problem

CONE = """\
title: A cone top
parameters:
  m: mass
  H: height
  r: base radius
  g: acceleration of gravity
  theta: tilt of the axis from the vertical
  s: spin rate relative to the precessing triad
{values}
unknowns: [Omega]
gravity: [0, 0, -g]
triads:
  T: {{turns: [[z, Omega*t], [x, theta]], vectors: [e1, e2, e3]}}
points:
  O: [0, 0, 0]
  K: H*e3
bodies:
  top: {{shape: cone, mass: m, radius: r, height: H, at: K, axis: -z, orientation: [T, [z, s*t]]}}
questions:
  - steady_motion: {{about: O, solve_for: Omega}}
"""

DISK = """\
title: A disk top
parameters:
  m: mass
  R: radius of the disk
  h: distance from O to the disk's centre
  g: acceleration of gravity
  theta: tilt of the axis from the vertical
  s: spin rate relative to the precessing triad
{values}
unknowns: [Omega]
gravity: [0, 0, -g]
triads:
  T: {{turns: [[z, Omega*t], [x, {tilt}]], vectors: [e1, e2, e3]}}
points:
  O: [0, 0, 0]
  G: h*e3
bodies:
  top: {{shape: disk, mass: m, radius: R, at: G, axis: z, orientation: [T, [z, s*t]]}}
questions:
  - steady_motion: {{about: O, solve_for: Omega}}
"""


def _cone(m, H, r):
    """(I₁ about O, I₃, h): by hand, see the module."""
    return 3 * m * (r**2 + 4 * H**2) / 20, 3 * m * r**2 / 10, 3 * H / 4


def _least_spin(I1, I3, m, g, h, theta):
    return 2 * math.sqrt((I1 - I3) * m * g * h * math.cos(theta)) / I3


def _rates(I1, I3, m, g, h, theta, s):
    a, b, c = (I1 - I3) * math.cos(theta), -I3 * s, m * g * h
    d = b * b - 4 * a * c
    return sorted(((-b - math.sqrt(d)) / (2 * a), (-b + math.sqrt(d)) / (2 * a)))


def _solve(text: str):
    report = solve_problem(build_model(load_text(text, "top.yaml")))
    return report, json.loads(json.dumps(report_object(report)))


def _pairs(tree) -> list:
    """Every list of two floats in a values tree (a complex number printed as a pair)."""
    if isinstance(tree, dict):
        return [p for v in tree.values() for p in _pairs(v)]
    if isinstance(tree, list):
        if len(tree) == 2 and all(isinstance(x, float) for x in tree):
            return [tree]
        return [p for v in tree for p in _pairs(v)]
    return []


CONE_VALUES = {"m": 2, "H": 0.1, "r": 0.05, "g": 9.81, "theta": math.pi / 6}


@pytest.mark.parametrize("side", [0.5, 0.97, 1.03, 2.0])
def test_a_cone_top_below_its_least_spin_has_no_steady_precession(side) -> None:
    v = CONE_VALUES
    I1, I3, h = _cone(v["m"], v["H"], v["r"])
    least = _least_spin(I1, I3, v["m"], v["g"], h, v["theta"])
    assert least == pytest.approx(159.647, abs=1e-3)  # by hand: 2 √(0.01125·2·9.81·0.075·cos 30°)/0.0015
    s = side * least
    values = f"values: {{m: 2, H: 1/10, r: 1/20, g: 9.81, theta: pi/6, s: {s!r}}}"
    report, got = _solve(CONE.format(values=values))
    (result,) = got["results"]
    assert result["ok"], result["error"]
    (critical,) = result["values"]["critical"]
    assert critical["value"] == pytest.approx(least, rel=1e-12)
    assert result["answers"]["critical"][0]["parameter"] == "s"
    assert not _pairs(result["values"]), "a complex value printed as a pair of reals"
    branches = result["values"]["branches"]
    assert len(branches) == 2
    if side < 1:
        assert all(b["exists_when"] is False and b["solved"]["Omega"] is None for b in branches)
        (warning,) = [w for w in result["warnings"] if w.startswith("no steady motion")]
        assert f"s = {s:.6g}" in warning and f"s_c = {least:.6g}" in warning, warning
    else:
        assert all(b["exists_when"] is True for b in branches)
        rates = sorted(b["solved"]["Omega"] for b in branches)
        assert rates == pytest.approx(_rates(I1, I3, v["m"], v["g"], h, v["theta"], s), rel=1e-10)
        assert not any(w.startswith("no steady motion") for w in result["warnings"])


def test_a_disk_top_with_only_the_spin_left_states_the_least_spin() -> None:
    """Every value given but s: the rates exist only for s ≥ s_c, sampled on both sides."""
    report, got = _solve(DISK.format(values="values: {m: 1, R: 1/10, h: 1/5, g: 9.81, theta: pi/6}", tilt="theta"))
    (result,) = got["results"]
    I1, I3 = 0.1**2 / 4 + 0.2**2, 0.1**2 / 2
    least = _least_spin(I1, I3, 1, 9.81, 0.2, math.pi / 6)
    (critical,) = result["values"]["critical"]
    assert (result["answers"]["critical"][0]["parameter"], critical["value"]) == ("s", pytest.approx(least, rel=1e-12))
    _sampled_both_sides(report, {"m": 1, "R": 0.1, "h": 0.2, "g": 9.81, "theta": math.pi / 6}, "s", least)


def test_a_disk_top_with_a_symbolic_tilt_bounded_by_assumptions() -> None:
    """m, R, h, g, θ and s symbolic, h > R/2 and θ < π/2 assumed: s ≥ s_c (I₁ − I₃ =
    m (h² − R²/4) > 0 and cos θ > 0), sampled on both sides at random admissible values."""
    report, got = _solve(DISK.format(values="assumptions: [h > R/2, theta < pi/2]", tilt="theta"))
    (result,) = got["results"]
    (critical,) = result["answers"]["critical"]
    assert critical["parameter"] == "s"
    rng = random.Random(38)
    for _ in range(12):
        R = rng.uniform(0.05, 1)
        v = {"m": rng.uniform(0.1, 5), "R": R, "h": R / 2 * rng.uniform(1.05, 4), "g": 9.81,
             "theta": rng.uniform(0.05, 1.5)}
        least = _least_spin(v["m"] * R**2 / 4 + v["m"] * v["h"] ** 2, v["m"] * R**2 / 2, v["m"], v["g"], v["h"],
                            v["theta"])
        _sampled_both_sides(report, v, "s", least)


def test_a_condition_no_parameter_splits_is_stated_as_it_is() -> None:
    """The cone with no values and no assumptions: whether s_c exists depends on
    4H² − r² and on cos θ, so no one parameter splits the discriminant; the condition is
    the discriminant ≥ 0 itself, never "True". Sampled on both sides of it."""
    report, got = _solve(CONE.format(values=""))
    (solution,) = report.solutions
    for branch in solution.answers.branches:
        assert branch.exists_when is not sp.true
    rng = random.Random(8)
    seen = set()
    for _ in range(40):
        v = {"m": rng.uniform(0.1, 3), "H": rng.uniform(0.01, 1), "r": rng.uniform(0.01, 1), "g": 9.81,
             "theta": rng.uniform(0.01, 3.1), "s": rng.uniform(0, 300)}
        I1, I3, h = _cone(v["m"], v["H"], v["r"])
        real = (I3 * v["s"]) ** 2 - 4 * (I1 - I3) * v["m"] * v["g"] * h * math.cos(v["theta"]) >= 0
        seen.add(real)
        at = {sp.Symbol(k, positive=True): x for k, x in v.items()}
        for branch in solution.answers.branches:
            assert bool(branch.exists_when.xreplace(at)) == real
    assert seen == {True, False}


def _sampled_both_sides(report, values: dict, name: str, critical: float) -> None:
    """Each branch's exists_when at the values, the parameter just below and above the
    critical value, against the hand-derived side."""
    (solution,) = report.solutions
    at = {sp.Symbol(k, positive=True): x for k, x in values.items()}
    for factor in (0.9, 0.999, 1.001, 1.1):
        at[sp.Symbol(name, positive=True)] = factor * critical
        for branch in solution.answers.branches:
            assert bool(branch.exists_when.xreplace(at)) == (factor > 1), (factor, branch.exists_when)


def test_no_numeric_printer_shows_a_complex_value_as_a_pair() -> None:
    """values.numbers: a complex value is None, named by not_real, except in a record
    whose own exists_when is false there."""
    from rbdsolve.model.values.values import not_real, numbers
    from rbdsolve.solvers.steady_motion.answers import Branch

    x = sp.Symbol("x", positive=True)
    found = numbers({"a": sp.sqrt(x - 2), "b": [Branch({"W": sp.sqrt(x - 3)}, sp.Ge(x, 3))]}, {x: 1})
    assert found.tree == {"a": None, "b": [{"solved": {"W": None}, "exists_when": False}]}
    assert not_real(found) == ("no numeric value for a: not a real number at the parameter values (a quantity "
                               "that exists only where it is real); shown as null")


def test_a_condition_the_assumptions_decide_is_true_or_false_not_split() -> None:
    """a > b assumed: a − b ≥ 0 always (true), b − a ≥ 0 never (false: the solution is
    never real and is not listed); a − 2b by a parameter (a ≥ 2b)."""
    from rbdsolve.solvers.steady_motion.existence import with_existence

    model = build_model(load_text(CONE.format(values="assumptions: [H > r]"), "top.yaml"))
    H, r = model.symbols.parameters["H"], model.symbols.parameters["r"]
    branches, critical = with_existence([{"W": sp.sqrt(H - r)}, {"W": sp.sqrt(r - H)}, {"W": sp.sqrt(H - 2 * r)}],
                                        [], model)
    assert [b.exists_when for b in branches[:2]] == [sp.true, sp.false]
    rng = random.Random(3)
    for _ in range(20):
        at = {H: rng.uniform(0.1, 2), r: rng.uniform(0.1, 2)}
        if at[H] > at[r]:
            assert bool(branches[2].exists_when.xreplace(at)) == (at[H] >= 2 * at[r])


@pytest.mark.parametrize(("values", "tilt"), [("values: {theta: pi/6}", "theta"), ("", "pi/6")],
                         ids=["tilt-given-as-a-value", "tilt-written-in"])
def test_a_disk_top_with_the_tilt_given_states_its_condition_in_the_spin(values, tilt) -> None:
    """m, R, h, g and s free, θ = π/6: the rates are real iff I₃² s² ≥ 4 (I₁ − I₃) m g h cos θ,
    I₁ − I₃ = m (h² − R²/4) of either sign, so a condition in the spin (s² ≥ …), not
    in R; sampled on both sides of it, with h < R/2 (always real) among the samples."""
    report, _ = _solve(DISK.format(values=values, tilt=tilt))
    (solution,) = report.solutions
    s = sp.Symbol("s", positive=True)
    rng = random.Random(37)
    seen = set()
    for _ in range(40):
        v = {"m": rng.uniform(0.1, 3), "R": rng.uniform(0.05, 1), "h": rng.uniform(0.05, 1), "g": 9.81,
             "s": rng.uniform(0, 200), "theta": math.pi / 6}
        I1, I3 = v["m"] * v["R"] ** 2 / 4 + v["m"] * v["h"] ** 2, v["m"] * v["R"] ** 2 / 2
        real = (I3 * v["s"]) ** 2 >= 4 * (I1 - I3) * v["m"] * v["g"] * v["h"] * math.cos(math.pi / 6)
        seen.add((real, v["h"] < v["R"] / 2))
        at = {sp.Symbol(k, positive=True): x for k, x in v.items()}
        for branch in solution.answers.branches:
            assert s in branch.exists_when.free_symbols
            assert bool(branch.exists_when.xreplace(at)) == real
    assert {(True, True), (True, False), (False, False)} <= seen
