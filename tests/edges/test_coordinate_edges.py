"""Failure edges found on unseen problems (issue 26): singular coordinates, rounded
roots, nulls where numbers exist, a body that should turn, a silent choice, a false
"no solution", a route blocked by a parameter that does not matter.

Every expected value is derived here by hand (the derivation is in each comment) or
by an independent computation (numpy/mpmath on the formula written out by hand).
"""

from __future__ import annotations

import pytest
import sympy as sp

from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.solvers import solve_problem
from rbdsolve.solvers.shared.options import Options, RouteChoice


def _report(text: str, route: RouteChoice = RouteChoice.AUTO):
    return solve_problem(build_model(load_text(text, "scene.yaml")), Options(route=route))


# --- 7. a route blocked by a parameter that does not matter ----------------------------

# A yo-yo: a disk (m, R) and an axle (m/10, radius r, length b) on one string of
# radius r, falling by y and turning by y/r. In a planar motion only J_zz counts, and
# a cylinder's J_zz about its own axis (z) is m r²/2 whatever its length b:
#   T = ½ (11m/10) ẏ² + ½ (m R²/2)(ẏ/r)² + ½ (m r²/20)(ẏ/r)² = m (10 R²/r² + 23) ẏ²/40,
# so M = m (10 R²/r² + 23)/20 = 0.2 (250 + 23)/20 = 2.73 and the force 11 m g/10 = 2.1582.
YOYO = """\
parameters: {m: mass, r: axle radius, R: disk radius, b: axle length, g: gravity}
values: {m: 0.2, r: 0.01, R: 0.05, g: 9.81}
coordinates: [y]
gravity: [0, -g]
bodies:
  disk: {shape: disk, mass: m, radius: R, at: [0, -y], angle: y/r}
  axle: {shape: cylinder, mass: m/10, radius: r, height: b, axis: z, at: [0, -y], angle: y/r}
questions: [eom]
"""


def test_a_parameter_the_answer_does_not_depend_on_is_not_asked_for() -> None:
    (solution,) = _report(YOYO, RouteChoice.NUMERIC).solutions
    assert solution.solved, solution.error
    (equation,) = solution.answers.equations
    (ydd,) = [d for d in equation.atoms(sp.Derivative) if d.derivative_count == 2]
    assert float(equation.coeff(ydd)) == pytest.approx(2.73, rel=1e-12)
    assert float(equation.subs(ydd, 0)) == pytest.approx(-2.1582, rel=1e-12)


def test_a_parameter_the_answer_depends_on_is_still_asked_for() -> None:
    (solution,) = _report(YOYO.replace("R: 0.05, ", ""), RouteChoice.NUMERIC).solutions
    assert not solution.solved
    assert "give R " in solution.error and "b" not in solution.error.split("give ")[1].split("(")[0]


# --- 4. a swinging body without `angle` ------------------------------------------------

# A rod (m, l) hung from O by its centre G = l/2 (sin θ, −cos θ), written without
# `angle`: it translates, T = ½ m (l/2)² θ̇² = m l² θ̇²/8 instead of the rod's
# m l² θ̇²/6. The answer stays what the scene says; every question on T warns.
SWING = """\
parameters: {m: mass, l: length, g: gravity}
coordinates: [theta]
gravity: [0, -g]
points:
  O: [0, 0]
  G: O + l/2*[sin(theta), -cos(theta)]
bodies:
  rod: {shape: rod, mass: m, length: l, at: G}
questions: [eom, equilibria, modes]
"""

# A slider driven by a crank: its centre moves along x with θ but not on a circle
# about any named point, so it may well just slide: the plain note, no warning.
SLIDER = """\
parameters: {m: mass, a: crank, g: gravity}
coordinates: [theta]
gravity: [0, -g]
points:
  O: [0, 0]
  A: a*[cos(theta), sin(theta)]
  B: [a*cos(theta) + 2*a, 0]
bodies:
  slider: {shape: box, mass: m, width: a, height: a, depth: a, at: B}
questions: [eom]
"""


def test_a_body_that_swings_without_an_angle_is_warned_about_on_every_question_using_T() -> None:
    report = _report(SWING)
    eom, equilibria, modes = report.solutions
    for solution in (eom, modes):
        (warning,) = solution.warnings
        assert "'rod' has no angle" in warning and "add `angle: theta`" in warning and "about O" in warning
    assert equilibria.warnings == ()  # V alone: no rotational energy involved
    l, m = sp.symbols("l m", positive=True)
    (equation,) = eom.answers.equations
    (thdd,) = [d for d in equation.atoms(sp.Derivative) if d.derivative_count == 2]
    assert sp.simplify(equation.coeff(thdd) - m * l**2 / 4) == 0  # 2 × m l²/8: the answer is unchanged


def test_a_body_that_may_just_slide_keeps_the_plain_note() -> None:
    report = _report(SLIDER)
    assert report.solutions[0].warnings == ()
    assert any("slider has no 'angle'" in str(step) for step in report.model.steps)
