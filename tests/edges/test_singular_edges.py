"""Issue 8, case 5: singular models. A coordinate that moves no mass, two coordinates
that move the masses only together, a mass that is zero at the given values: every
route and question kind that meets the singular mass matrix says so, naming the cause,
and never prints a number for it.

Expected facts, by hand: a junction J = (x, 0) between two springs carries no mass, so
M = diag(0, m) (null vector (1, 0)); a particle at (x + y, 0) gives M = m [[1, 1], [1, 1]]
(null vector (1, −1)); an impulse at the particle then has no unique split between ẋ and ẏ.
"""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

from rbdsolve.errors import InputError
from rbdsolve.problem import load_text
from rbdsolve.solvers import Options, RouteChoice, solve_file

HEAD = """\
parameters: {m: mass, k: stiffness}
values: {m: 1, k: 1}
coordinates: {x: length, y: length}
"""
QUESTIONS = """\
questions:
  - eom
  - modes: {about: {x: 0, y: 0}}
  - impact: {at: {x: 0, y: 0}, impulses: {P: [m, 0]}}
"""
JUNCTION = HEAD + """\
points:
  O: [0, 0]
  J: [x, 0]
  P: [y, 0]
bodies:
  block: {shape: particle, mass: m, at: P}
springs:
  s1: {stiffness: k, between: [O, J]}
  s2: {stiffness: k, between: [J, P]}
""" + QUESTIONS
REDUNDANT = HEAD + """\
points:
  O: [0, 0]
  P: [x + y, 0]
bodies:
  block: {shape: particle, mass: m, at: P}
springs:
  s: {stiffness: k, between: [O, P]}
""" + QUESTIONS
# Two coordinates redundant at the instant of an impact, a scene given by velocities.
INSTANT = """\
parameters: {m: mass}
values: {m: 1}
coordinates: [x, y]
points:
  P: {velocity: [dot(x) + dot(y), 0]}
bodies:
  block: {mass: m, velocity: P, angular_velocity: 0}
questions:
  - impact: {impulses: {P: [m, 0]}}
"""
ZERO_MASS = """\
parameters: {m: mass, k: stiffness, mu: {description: second mass, positive: false}}
values: {m: 1, k: 1, mu: 0}
coordinates: {x: length, y: length}
points:
  O: [0, 0]
  P: [x, 0]
  Q: [y, 0]
bodies:
  a: {shape: particle, mass: m, at: P}
  b: {shape: particle, mass: mu, at: Q}
springs:
  s1: {stiffness: k, between: [O, P]}
  s2: {stiffness: k, between: [P, Q]}
questions:
  - modes: {about: {x: 0, y: 0}}
"""
CAUSES = {"junction": (JUNCTION, "the coordinate x moves no mass"),
          "redundant": (REDUNDANT, "q̇ ∝ (1, −1) of (x, y) moves no mass: x, y are redundant")}


def _solve(text: str, route: RouteChoice):
    return solve_file(load_text(text, "scene.yaml"), Options(route=route, budget=30)).solutions


@pytest.mark.parametrize("scene", CAUSES)
@pytest.mark.parametrize("route", [RouteChoice.EXACT, RouteChoice.NUMERIC, RouteChoice.AUTO])
def test_modes_and_impact_refuse_naming_the_cause(scene: str, route: RouteChoice) -> None:
    text, cause = CAUSES[scene]
    eom, modes, impact = _solve(text, route)
    for solution, where in ((modes, "at this configuration"), (impact, "at the instant")):
        assert not solution.solved and solution.answers is None
        assert cause in solution.error and where in solution.error
        assert "singular" in solution.error
    if route is RouteChoice.NUMERIC:
        assert "in floating point" in modes.error and "in floating point" in impact.error


@pytest.mark.parametrize("scene", CAUSES)
def test_eom_answers_with_a_warning_that_the_accelerations_are_not_determined(scene: str) -> None:
    text, cause = CAUSES[scene]
    eom = _solve(text, RouteChoice.EXACT)[0]
    assert eom.solved  # the equations themselves are right: Lagrange's equations hold
    assert any(cause in w and "at every configuration" in w and "cannot be solved for the accelerations" in w
               for w in eom.warnings)


def test_a_regular_scene_gets_no_singular_warning() -> None:
    text = JUNCTION.replace("J: [x, 0]", "J: [x, 0]\n  R: [x, 1]").replace(
        "bodies:\n", "bodies:\n  junction: {shape: particle, mass: m, at: R}\n")
    eom, modes, impact = _solve(text, RouteChoice.EXACT)
    assert eom.solved and not eom.warnings
    assert modes.solved and impact.solved


@pytest.mark.parametrize("route", [RouteChoice.EXACT, RouteChoice.NUMERIC])
def test_an_impact_redundant_at_the_instant_is_refused(route: RouteChoice) -> None:
    (impact,) = _solve(INSTANT, route)
    assert not impact.solved
    assert "q̇ ∝ (1, −1) of (x, y) moves no mass" in impact.error and "at the instant" in impact.error


@pytest.mark.parametrize("route", [RouteChoice.EXACT, RouteChoice.NUMERIC])
def test_a_mass_zero_at_the_values_is_refused_on_every_route(route: RouteChoice) -> None:
    # Before this check the exact route answered with mu symbolic and called both modes
    # 'growth' at mu = 0: a silently wrong answer (by hand: y is then massless, y = x, and
    # m x'' + k x = 0 is one oscillation).
    with pytest.raises(InputError) as caught:
        _solve(ZERO_MASS, route)
    assert str(caught.value).startswith("scene.yaml:10:30: bodies.b.mass: a mass must not be zero or negative")
    assert "at the values given (m = 1, k = 1, mu = 0)" in str(caught.value)


def test_the_cli_exits_1_with_strict_json_and_the_reason(tmp_path) -> None:
    path = tmp_path / "redundant.yaml"
    path.write_text(REDUNDANT)
    run = subprocess.run([sys.executable, "-m", "rbdsolve", "solve", str(path), "--format", "json",
                          "--route", "numeric"], capture_output=True, text=True, timeout=60)
    assert run.returncode == 1
    line = json.loads(run.stdout, parse_constant=lambda c: pytest.fail(f"non-strict JSON: {c}"))
    eom, *others = line["results"]
    assert eom["ok"] and any("redundant" in w and "cannot be solved for the accelerations" in w
                             for w in eom["warnings"])
    assert all(not r["ok"] and "redundant" in r["error"] for r in others) and len(others) == 2
