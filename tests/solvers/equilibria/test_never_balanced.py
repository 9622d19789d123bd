"""Where ∂V/∂q holds no coordinate and is a nonzero number at the values, the loads never
balance: the answer is that there is no equilibrium (exit 0), not a failure to find one."""

from rbdsolve.api import loads
from rbdsolve.model.build import build_model
from rbdsolve.solvers import solve_question

SCENE = """
title: A block pulled across a table, tied over a pulley to a hanging block
parameters: {m1: mass, m2: mass, M: mass, R: length, J: inertia, F: force, l: length, g: gravity}
values: {m1: 2 kg, m2: 1.5 kg, M: 3 kg, R: 12 cm, J: 0.018 kg*m^2, l: 50 cm, g: 9.81 m/s^2, F: FORCE}
coordinates: [theta]
gravity: [0, -g]
points:
  O: [0, 0]
bodies:
  pulley: {mass: M, inertia: J, at: O, angle: theta}
  block1: {shape: particle, mass: m1}
  block2: {shape: particle, mass: m2}
contacts:
  S1: {body: block1, hangs_from: {drum: pulley, radius: R, side: above, direction: [-1, 0], length: l}}
  S2: {body: block2, hangs_from: {drum: pulley, radius: R, side: right, length: l}}
forces:
  pull: {on: block1, force: [-F, 0]}
questions:
  - equilibria
"""


def _equilibria(force: str):
    model = build_model(loads(SCENE.replace("FORCE", force)))
    return solve_question(model.problem.questions[0], model)


def test_pulled_harder_than_the_hanging_weight_there_is_no_equilibrium():
    # ∂V/∂θ = R (g m₂ − F), by hand: the pull F against the weight m₂ g, both at the rim R
    solution = _equilibria("20 N")
    assert solution.solved and solution.answers.equilibria == ()
    note = solution.steps[-1].text
    assert "∂V/∂θ" in note and "−0.6342" in note and "no equilibrium" in note  # 0.12 (14.715 − 20)


def test_pulled_with_the_hanging_weight_every_place_is_one():
    solution = _equilibria("14.715 N")  # F = m₂ g
    assert solution.solved and len(solution.answers.equilibria) == 1


def test_with_the_pull_symbolic_the_balancing_pull_is_a_critical_value_with_its_number():
    model = build_model(loads(SCENE.replace(", F: FORCE", "")))
    solution = solve_question(model.problem.questions[0], model)
    (critical,) = solution.answers.critical
    assert critical.parameter == "F"  # F = m₂ g by hand: 1.5 · 9.81 = 14.715 N
    assert abs(float(critical.value.xreplace(dict(model.values))) - 14.715) < 1e-12
    lines = [n for n in solution.numbers if str(n.relation.lhs) == "F_c"]
    assert lines and abs(float(lines[0].relation.rhs) - 14.715) < 1e-9 and lines[0].unit == "N"
