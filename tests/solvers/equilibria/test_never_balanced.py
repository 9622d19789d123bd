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
    assert note.endswith("they would balance where m₂ = F/g (= 2.03874 here).")  # 20/9.81, by hand
    model = build_model(loads(SCENE.replace("FORCE", "20 N").replace("  - equilibria", "  - equilibria: {for: F}")))
    note = solve_question(model.problem.questions[0], model).steps[-1].text
    assert note.endswith("they would balance where F = g m₂ (= 14.715 here).")  # asked for F: m₂ g


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


CART = """
title: A cart pulled by a constant force F, a rod hanging from it on a pin
parameters: {M: mass, m: mass, l: length, F: {unit: N, positive: false}, g: gravity}
values: {M: 8 kg, m: 2 kg, l: 1.2 m, g: 9.81 m/s^2, F: FORCE}
coordinates: [x, theta]
gravity: [0, -g]
points:
  P: [x, 0]
  G: P + l/2*[sin(theta), -cos(theta)]
bodies:
  cart: {shape: particle, mass: M, at: P}
  rod: {shape: rod, mass: m, length: l, at: G, angle: theta, axis: y}
forces:
  pull: {on: cart, force: [F, 0]}
questions:
  - equilibria
"""


def test_a_pulled_cart_under_a_pendulum_has_no_equilibrium_though_the_pendulum_alone_would():
    # by hand: V = −F x − m g (l/2) cos θ, so ∂V/∂x = −F at every x, θ (a new user's trial)
    model = build_model(loads(CART.replace("FORCE", "20 N")))
    solution = solve_question(model.problem.questions[0], model)
    assert solution.solved and solution.answers.equilibria == ()
    assert "∂V/∂x = −F = −20, not 0" in solution.steps[-1].text
    model = build_model(loads(CART.replace("FORCE", "-5 N")))  # pulled the other way: no more equilibrium
    solution = solve_question(model.problem.questions[0], model)
    assert solution.solved and solution.answers.equilibria == ()


COUPLE = """
title: A disk on a fixed axle, a particle on its rim, turned by a constant couple C
parameters: {M: mass, m: mass, R: length, C: moment, g: gravity}
values: {M: 2 kg, m: 0.5 kg, R: 20 cm, g: 9.81 m/s^2, C: COUPLE}
coordinates: [theta]
gravity: [0, -g]
points:
  O: [0, 0]
  P: R*[sin(theta), -cos(theta)]
bodies:
  wheel: {shape: disk, mass: M, radius: R, at: O, angle: theta}
  bob: {shape: particle, mass: m, at: P}
couples:
  drive: {on: wheel, moment: C}
questions:
  - equilibria
"""


def test_a_couple_past_m_g_R_leaves_no_equilibrium_and_below_it_two():
    # by hand: V = −m g R cos θ − C θ, ∂V/∂θ = m g R sin θ − C: roots sin θ = C/(m g R),
    # real only for C ≤ m g R = 0.981 N·m
    for couple, count in (("1.2 N*m", 0), ("0.9 N*m", 2), ("0.5 N*m", 2)):
        model = build_model(loads(COUPLE.replace("COUPLE", couple)))
        solution = solve_question(model.problem.questions[0], model)
        assert solution.solved and len(solution.answers.equilibria) == count, couple
    model = build_model(loads(COUPLE.replace("COUPLE", "1.2 N*m")))
    assert "has no real root" in solve_question(model.problem.questions[0], model).steps[-1].text
