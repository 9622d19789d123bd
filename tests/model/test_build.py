"""The model stage: signs of physical constants, explicit inertia, time dependence."""

from __future__ import annotations

import pytest
import sympy as sp

from rbdsolve.errors import InputError
from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.solvers import solve_problem

BASE = """
parameters: {m: mass, l: length, k: stiffness, g: gravity}
coordinates: [theta]
gravity: [0, -g]
points:
  P: l * [sin(theta), -cos(theta)]
bodies:
  bob: {shape: particle, mass: m, at: P}
questions: [eom, equilibria, modes]
"""


def model_error(extra: str) -> InputError:
    with pytest.raises(InputError) as info:
        build_model(load_text(BASE + extra, "scene.yaml"))
    return info.value


@pytest.mark.parametrize(
    "extra, path, words",
    [
        ("springs:\n  s: {stiffness: -k, angle: theta}\n", "springs.s.stiffness", "a stiffness must not be negative"),
        ("springs:\n  s: {stiffness: k, between: [P, [0, 0]], natural_length: -l}\n",
         "springs.s.natural_length", "a natural length must not be negative"),
    ],
)
def test_signs_of_physical_constants(extra: str, path: str, words: str) -> None:
    err = model_error(extra)
    assert words in err.message
    assert err.location.key_path() == path


def test_a_symbolic_negative_dimension_is_refused() -> None:
    scene = BASE.replace("bob: {shape: particle, mass: m, at: P}",
                         "bob: {shape: disk, mass: m, radius: -l, at: P, angle: theta}")
    with pytest.raises(InputError) as info:
        build_model(load_text(scene, "s.yaml"))
    assert "a radius must not be zero or negative, found -l" in info.value.message
    assert info.value.location.key_path() == "bodies.bob.radius"


def test_explicit_inertia_must_be_symmetric_and_not_negative() -> None:
    scene = BASE.replace("bob: {shape: particle, mass: m, at: P}",
                         "bob: {inertia: [[1, 5, 0], [0, 1, 0], [0, 0, 1]], mass: m, at: P, angle: theta}")
    with pytest.raises(InputError, match="symmetric"):
        build_model(load_text(scene, "s.yaml"))
    scene = BASE.replace("bob: {shape: particle, mass: m, at: P}",
                         "bob: {inertia: -2*m*l**2, mass: m, at: P, angle: theta}")
    with pytest.raises(InputError, match="moment of inertia must not be negative"):
        build_model(load_text(scene, "s.yaml"))


def test_a_scene_that_moves_by_itself_has_no_equilibria() -> None:
    # A pendulum whose pivot oscillates: eom is fine, ∂V/∂q = 0 would be wrong.
    scene = BASE.replace("  P: l * [sin(theta), -cos(theta)]",
                         "  O: [l*cos(3*t), 0]\n  P: O + l * [sin(theta), -cos(theta)]")
    report = solve_problem(build_model(load_text(scene, "s.yaml")))
    eom, equilibria, modes = report.solutions
    assert eom.solved
    for result in (equilibria, modes):
        assert not result.solved and "depends explicitly on time" in result.error


def test_an_angle_the_scene_does_not_repeat_after_one_turn_is_refused() -> None:
    # θ enters as θ/2: V = −m g l cos(θ/2) does not repeat after a turn, so declaring θ
    # an angle (whose equilibria are folded into (−π, π]) is refused, naming the term.
    scene = BASE.replace("coordinates: [theta]", "coordinates: {theta: angle}").replace(
        "l * [sin(theta), -cos(theta)]", "l * [sin(theta/2), -cos(theta/2)]")
    with pytest.raises(InputError, match=r"s.yaml:\d+:\d+: coordinates.theta: 'theta' is declared an angle, which "
                                         r"repeats after a turn, but the height of body 'bob' holds it outside sin"):
        build_model(load_text(scene, "s.yaml"))


def test_an_angle_declared_not_periodic_is_not_folded() -> None:
    # By hand: V = −m g l cos(θ/2), V' = (m g l/2) sin(θ/2) = 0 at θ = 2πk; the bob hangs
    # at θ = 0 (V'' > 0) and stands on top at θ = 2π (V'' < 0), which folding would put on 0.
    scene = BASE.replace("coordinates: [theta]", "coordinates: {theta: {kind: angle, periodic: false}}").replace(
        "l * [sin(theta), -cos(theta)]", "l * [sin(theta/2), -cos(theta/2)]")
    solution = solve_problem(build_model(load_text(scene, "s.yaml"))).solutions[1]
    found = {(eq.at["theta"], eq.stability.value) for eq in solution.answers.equilibria}
    assert (0, "stable") in found  # θ = ±2π are one configuration: either may be listed, the other its equivalent
    assert (2 * sp.pi, "unstable") in found or (-2 * sp.pi, "unstable") in found


@pytest.mark.parametrize("position, words", [("[1/0, 0]", "division by zero"),
                                             ("[sqrt(-1)*l, 0]", "is not a real number"),
                                             ("[log(0)*l, 0]", "is not a real number")])
def test_values_that_are_not_real_numbers(position: str, words: str) -> None:
    scene = BASE.replace("l * [sin(theta), -cos(theta)]", f"'{position}'")
    with pytest.raises(InputError, match=words.replace("(", r"\(")):
        build_model(load_text(scene, "s.yaml"))


def test_a_body_that_should_turn_gets_a_note() -> None:
    scene = BASE.replace("bob: {shape: particle, mass: m, at: P}", "rod: {shape: rod, mass: m, length: l, at: P}")
    report = solve_problem(build_model(load_text(scene, "s.yaml")))
    # its centre circles the origin, an unnamed pivot: a warning, not the plain note (issue 38)
    assert any("warning: body 'rod' has no angle" in s.text and "the point (0, 0)" in s.text
               for s in report.model.steps)
