"""The warnings the scene itself calls for (issue 38), in each question's `warnings`:
a body that swings without an angle, whether or not its pivot is a named point, on every
question that uses T; a declared parameter used nowhere, on every question, with the
missing line named where it is gravity's.
"""

from __future__ import annotations

import sympy as sp

from conftest import PROBLEMS
from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.solvers import solve_problem

# A rod (m, l) hung from an unnamed pivot at the origin by its end, G = l/2 (sin θ, −cos θ),
# written without `angle`: it translates, T = ½ m (l/2)² θ̇² = m l² θ̇²/8 (not m l² θ̇²/6).
HUNG = """\
parameters: {m: mass of the rod, l: length of the rod, g: acceleration of gravity}
coordinates: [theta]
gravity: [0, -g]
points:
  G: l/2*[sin(theta), -cos(theta)]
bodies:
  rod: {shape: rod, mass: m, length: l, at: G}
questions:
  - eom
  - equilibria
  - modes: {about: {theta: 0}}
  - energy: {from_rest: {theta: pi/2}, to: {theta: 0}}
"""

# The pendulum of problems/examples with its `gravity:` line left out: V = 0.
PENDULUM = "\n".join(line for line in (PROBLEMS / "examples" / "pendulum.yaml").read_text().splitlines()
                     if not line.startswith("gravity:"))


def _report(text: str):
    return solve_problem(build_model(load_text(text, "scene.yaml")))


def test_a_rod_hung_by_its_end_from_an_unnamed_pivot_is_warned_about_on_every_question_using_T() -> None:
    eom, equilibria, modes, energy = _report(HUNG).solutions
    for solution in (eom, modes, energy):
        (warning,) = solution.warnings
        assert "'rod' has no angle" in warning and "the point (0, 0)" in warning and "add `angle: theta`" in warning
    assert equilibria.warnings == ()  # V alone
    l, m = sp.symbols("l m", positive=True)
    (equation,) = eom.answers.equations
    (thdd,) = [d for d in equation.atoms(sp.Derivative) if d.derivative_count == 2]
    assert sp.simplify(equation.coeff(thdd) - m * l**2 / 4) == 0  # 2 × m l²/8: the answer is unchanged


def test_a_centre_on_a_circle_about_a_moving_point_names_that_point() -> None:
    """A second rod hung by its end from the end of a first, written without angle:
    G₂ = l (sin θ, −cos θ) + l/2 (sin φ, −cos φ) circles about the first rod's end."""
    text = HUNG.replace("coordinates: [theta]", "coordinates: [theta, phi]").replace(
        "  G: l/2*[sin(theta), -cos(theta)]\n",
        "  G: l/2*[sin(theta), -cos(theta)]\n  H: l*[sin(theta), -cos(theta)] + l/2*[sin(phi), -cos(phi)]\n").replace(
        "  rod: {shape: rod, mass: m, length: l, at: G}\n",
        "  rod: {shape: rod, mass: m, length: l, at: G, angle: theta}\n  rod2: {shape: rod, mass: m, length: l, at: H}\n")
    text = text[:text.index("questions:")] + "questions: [eom]\n"
    (eom,) = _report(text).solutions
    (warning,) = eom.warnings
    assert "'rod2' has no angle" in warning and "the point (l sin(θ), −l cos(θ))" in warning and "`angle: phi`" in warning


def test_a_slider_on_a_line_gets_no_warning() -> None:
    """A body whose centre moves along a line, [a cos θ + 2a, 0]: not a circle."""
    text = HUNG.replace("G: l/2*[sin(theta), -cos(theta)]", "G: [l*cos(theta) + 2*l, 0]")
    text = text[:text.index("questions:")] + "questions: [eom]\n"
    (eom,) = _report(text).solutions
    assert eom.warnings == ()


def test_gravity_left_out_names_the_line_to_add() -> None:
    """Without gravity V = 0: every θ is an equilibrium and λ = 0; the warning says why."""
    report = _report(PENDULUM)
    for solution in report.solutions:
        assert any("parameter 'g' is declared but used nowhere" in w and "`gravity: [0, -g]`" in w
                   for w in solution.warnings), solution.question


def test_a_parameter_used_nowhere_is_warned_about() -> None:
    text = HUNG.replace("g: acceleration of gravity}", "g: acceleration of gravity, c: damping}")
    for solution in _report(text).solutions:
        assert any(w.startswith("parameter 'c' is declared but used nowhere") and "gravity:" not in w
                   for w in solution.warnings)


SPINNING = """
title: A box spinning freely about a principal axis, its spin named Omega
parameters: {m: mass, a: length, Omega: spin rate}
values: {m: 1 kg, a: 10 cm, Omega: 10 rad/s}
bodies:
  box: {shape: box, mass: m, width: a, depth: 2*a, height: 3*a, at: [0, 0, 0]}
questions:
  - steady_spin
"""


def test_omega_is_a_steady_spins_size_so_it_is_not_unused() -> None:
    # docs/format.md: a parameter named Omega is the spin's size in the answers (a trial was told otherwise)
    (solution,) = _report(SPINNING).solutions
    assert not any("used nowhere" in w for w in solution.warnings)
    (solution,) = _report(SPINNING.replace("Omega", "W")).solutions  # any other name is unused here
    assert any(w.startswith("parameter 'W' is declared but used nowhere") for w in solution.warnings)


COUPLED = """
title: A disk on a fixed axle turned by a couple C against a rim weight
parameters: {M: mass, m: mass, R: length, C: the applied couple, g: gravity}
values: {M: 2 kg, m: 0.5 kg, R: 20 cm, g: 9.81 m/s^2}
coordinates: [theta]
gravity: [0, -g]
points:
  P: R*[sin(theta), -cos(theta)]
bodies:
  wheel: {shape: disk, mass: M, radius: R, at: [0, 0], angle: theta}
  bob: {shape: particle, mass: m, at: P}
couples:
  drive: {on: wheel, moment: C}
questions:
  - modes: {about: {theta: asin(C/(m*g*R))}}
"""


def test_a_couple_is_in_newton_metres_and_the_modes_json_says_where_the_equilibrium_exists() -> None:
    from rbdsolve.model.values.units import parameter_units

    model = build_model(load_text(COUPLED, "c.yaml"))
    assert parameter_units(model)["C"] == "N·m"  # a torque, not an energy (J)
    (solution,) = solve_problem(model).solutions
    # sin θ₀ = C/(m g R) needs C ≤ m g R, by hand; the text says so, and the answers too
    assert solution.answers.exists_when == sp.Le(sp.Symbol("C", positive=True),
                                                 sp.Symbol("R", positive=True) * sp.Symbol("g", positive=True)
                                                 * sp.Symbol("m", positive=True))
