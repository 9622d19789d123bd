"""A string from a rolling drum over a pulley with mass (``hangs_from: {…, over: P,
pulley: W}``): a new user's cylinder on a table, its string off the top over a disk
pulley to a hanging block, could be written only by turning the pulley by hand
(``angle: -2*x/R``, a workaround nobody would find), and its reactions were refused with
advice about a table the block does not touch; now the forces have a tension on each
side of the pulley.

By hand (the string off a drum's top moves at twice its centre's speed, and turns the
pulley of radius R at that speed over R; T = ½ m v² + ½ J ω² per body):

- on a table, a solid cylinder (M₂), a disk pulley (M), a block (m):
  T = ¾ M₂ ẋ² + ½ (½ M R²)(2ẋ/R)² + ½ m (2ẋ)² = (¾ M₂ + M + 2m) ẋ², V = −2 m g x,
  so ẍ = 2 m g/(3/2 M₂ + 2M + 4m) = 4 g m/(3 M₂ + 4 M + 8 m);
- up a 30° incline, the string off the cylinder's top parallel to the slope, over a
  ring pulley (J = M R²): T = (¾ M₂ + 2M + 2m) ṡ², V = M₂ g s sin β − 2 m g s, so
  s̈ = (2 m g − M₂ g sin β)/(3/2 M₂ + 4M + 4m).
"""

from __future__ import annotations

import pytest
import sympy as sp

import rbdsolve
from rbdsolve.errors import InputError

TABLE = """\
parameters: {M2: mass, r: radius, M: mass, R: radius, m: mass, d: distance, g: gravity}
coordinates: [x]
gravity: [0, -g]
points:
  P: [d, 2*r]
bodies:
  cylinder: {shape: cylinder, mass: M2, radius: r, height: 1}
  wheel: {shape: disk, mass: M, radius: R, at: "[d, 2*r - R]"}
  block: {shape: particle, mass: m}
contacts:
  C: {body: cylinder, rolls_on: floor, along: x}
  S: {body: block, hangs_from: {drum: cylinder, direction: [1, 0], over: P, pulley: wheel}}
questions: [eom]
"""

INCLINE = """\
parameters: {M2: mass, r: radius, M: mass, R: radius, m: mass, L: distance, beta: incline, g: gravity}
values: {beta: 30 deg}
coordinates: [s]
gravity: [0, -g]
points:
  P: "2*r*[-sin(beta), cos(beta)] + L*[cos(beta), sin(beta)]"
bodies:
  cylinder: {shape: cylinder, mass: M2, radius: r, height: 1}
  wheel: {shape: ring, mass: M, radius: R, at: "P - R*[-sin(beta), cos(beta)]"}
  block: {shape: particle, mass: m}
contacts:
  C: {body: cylinder, rolls_on: {line: {through: [0, 0], angle: beta}}, along: s}
  S: {body: block, hangs_from: {drum: cylinder, direction: "[cos(beta), sin(beta)]", over: P, pulley: wheel}}
questions: [eom]
"""


def _acceleration(tmp_path, text: str) -> sp.Expr:
    path = tmp_path / "scene.yaml"
    path.write_text(text)
    (solution,) = rbdsolve.solve(path, budget=1200.0)  # a budget far from the work
    (found,) = solution.answers.accelerations.values()
    return found


def test_a_cylinder_on_a_table_pulls_a_block_over_a_disk_pulley(tmp_path) -> None:
    M2, M, m, g = sp.symbols("M2 M m g", positive=True)
    assert sp.simplify(_acceleration(tmp_path, TABLE) - 4 * g * m / (3 * M2 + 4 * M + 8 * m)) == 0


def test_a_cylinder_up_an_incline_in_degrees_over_a_ring_pulley(tmp_path) -> None:
    """β stays a symbol in the answer (its 30° only in the numbers, and in which way the
    pulley turns: the string bends over it clockwise, cos β > 0)."""
    M2, M, m, g, beta = sp.symbols("M2 M m g beta", positive=True)
    by_hand = (2 * m * g - M2 * g * sp.sin(beta)) / (sp.Rational(3, 2) * M2 + 4 * M + 4 * m)
    assert sp.simplify(_acceleration(tmp_path, INCLINE) - by_hand) == 0


def test_the_tensions_on_the_two_sides_differ_by_what_turns_the_pulley(tmp_path) -> None:
    """On the table, by hand with a = ẍ = 4 g m/(3 M₂ + 4 M + 8 m): the block, m (2a) =
    m g − T₂; the pulley, J ψ̈ = R (T₁ − T₂) with ψ = −2x/R, so T₁ = T₂ − M a; the
    cylinder, M₂ a = T₁ − F_C (F_C counted along e_z × n = −e_x). Its axle, not asked, is
    found with them."""
    path = tmp_path / "scene.yaml"
    path.write_text(TABLE.replace("questions: [eom]", "questions: [{reactions: {forces: [C, S]}}]"))
    (solution,) = rbdsolve.solve(path, budget=1200.0)
    M2, M, m, g = sp.symbols("M2 M m g", positive=True)
    a = 4 * g * m / (3 * M2 + 4 * M + 8 * m)
    T2 = m * (g - 2 * a)
    T1 = T2 - M * a
    found = solution.answers.reactions
    tensions = found["S"].components
    assert sp.simplify(tensions["T_S2"] - T2) == 0 and sp.simplify(tensions["T_S1"] - T1) == 0
    assert sp.simplify(found["C"].components["F_C"] - (T1 - M2 * a)) == 0
    assert sp.simplify(found["wheel"].components["R_wheely"] - (M * g + T2)) == 0  # its axle: weight and T₂ down


SECOND = """\
  cyl2: {shape: cylinder, mass: M2, radius: r, height: 1}
  block2: {shape: particle, mass: m}
"""

WRONG = {  # what is wrong -> (the scene, the words of the refusal)
    "no over": (TABLE.replace("over: P, pulley: wheel", "pulley: wheel, side: right"), "give 'over: P'"),
    "an angle": (TABLE.replace('at: "[d, 2*r - R]"}', 'at: "[d, 2*r - R]", angle: x}'), "remove its 'angle'"),
    "the drum": (TABLE.replace("pulley: wheel}", "pulley: cylinder}"), "is the drum"),
    "no rim": (TABLE.replace("shape: disk, mass: M, radius: R,", "shape: rod, mass: M, length: R,"),
               "not a round body"),
    "a moving axle": (TABLE.replace('at: "[d, 2*r - R]"}', 'at: "[d + x, 2*r - R]"}'), "but its centre 'at' moves"),
    "no bend": (TABLE.replace("over: P, pulley: wheel", "over: P, down: [1, 0], pulley: wheel"),
                "does not bend over pulley"),
    "two strings": (TABLE.replace("  block: {", SECOND + "  block: {").replace("coordinates: [x]", "coordinates: [x, y]")
                    .replace("questions", "  C2: {body: cyl2, rolls_on: floor, along: y}\n  S2: {body: block2, hangs_from: "
                             "{drum: cyl2, direction: [1, 0], over: P, pulley: wheel}}\nquestions"),
                    "is turned by the string of contact 'S' already"),
    "turned later": (TABLE.replace("contacts:\n", "contacts:\n  H: {body: block2, hangs_from: {drum: wheel, side: left}}\n")
                     .replace("  block: {", "  block2: {shape: particle, mass: m}\n  block: {"),
                     "which the string of contact 'S' turns later: list 'S' first"),
}


@pytest.mark.parametrize("what", list(WRONG))
def test_a_pulley_that_cannot_be_turned_by_the_string_is_refused(tmp_path, what) -> None:
    text, said = WRONG[what]
    assert text != TABLE
    path = tmp_path / "scene.yaml"
    path.write_text(text)
    with pytest.raises(InputError, match=said):
        rbdsolve.solve(path, budget=1200.0)


def test_a_refusal_names_the_file_line_column_and_key_with_exit_code_2(tmp_path) -> None:
    from click.testing import CliRunner

    from rbdsolve.cli import main

    path = tmp_path / "scene.yaml"
    text = WRONG["the drum"][0]
    path.write_text(text)
    done = CliRunner().invoke(main, ["solve", str(path)])
    (line,) = [k for k, row in enumerate(text.splitlines(), 1) if "pulley: cylinder" in row]
    column = text.splitlines()[line - 1].index("pulley: cylinder") + len("pulley: ") + 1
    assert done.exit_code == 2
    assert done.output.startswith(f"{path}:{line}:{column}: contacts.S.hangs_from.pulley: body 'cylinder' is the drum")


def test_the_axle_asked_alone_brings_the_strings_that_turn_the_pulley(tmp_path) -> None:
    """The axle at the pulley's centre A: by hand (as above) R_Ax = T₁ and R_Ay = M g + T₂."""
    path = tmp_path / "scene.yaml"
    path.write_text(TABLE.replace("  P: [d, 2*r]", "  P: [d, 2*r]\n  A: [d, 2*r - R]")
                    .replace("questions: [eom]", "questions: [{reactions: {forces: [{at: A, on: wheel}]}}]"))
    (solution,) = rbdsolve.solve(path, budget=1200.0)
    M2, M, m, g = sp.symbols("M2 M m g", positive=True)
    a = 4 * g * m / (3 * M2 + 4 * M + 8 * m)
    T2 = m * (g - 2 * a)
    axle = solution.answers.reactions["A"].components
    assert sp.simplify(axle["R_Ax"] - (T2 - M * a)) == 0 and sp.simplify(axle["R_Ay"] - (M * g + T2)) == 0
