"""Grading accepts an answer as an exam writes it (issue 41, item 2): a number with its
unit, and an answer named as the printed solution names it (Ω_c, ω₁, Omega_c).

By hand, for the bead on a hoop turning at Ω (problems/frames/rotating-hoop-fast.yaml,
Ω = 5 rad/s, g = 9.81 m/s², R = 1 m): V' = −m g R cos θ − ½ m Ω² R² sin² θ, so the
off-axis equilibria have cos θ₀ = g/(Ω² R) = 0.3924, θ₀ = ±66.896°, they exist for
Ω > Ω_c = √(g/R) = 3.13209 rad/s, and the small oscillations about them have
ω² = Ω² sin² θ₀ = 21.1506 s⁻², ω = 4.59897 rad/s = 43.917 rpm.
"""

from __future__ import annotations

import json
import math

import pytest
from click.testing import CliRunner

from rbdsolve.cli import main

from conftest import PROBLEMS

LINES = [
    ("omega1 = 4.599 rad/s", "modes.frequencies[1]", True),
    ("ω₁ = 4.599 1/s", "modes.frequencies[1]", True),
    ("omega_1 = 43.92 rpm", "modes.frequencies[1]", True),
    ("ω₁ = 4.7 rad/s", "modes.frequencies[1]", False),
    ("Omega_c = sqrt(g/R)", "equilibria.critical[1].value", True),
    ("Ω_c = sqrt(g/R)", "equilibria.critical[1].value", True),
    ("Ωc = 3.132 rad/s", "equilibria.critical[1].value", True),
    ("Omega_c = sqrt(2*g/R)", "equilibria.critical[1].value", False),
    ("equilibrium2.theta = 66.9°", "equilibria.equilibria[2].at.theta", None),
    ("equilibrium2.theta = -66.9 deg", "equilibria.equilibria[2].at.theta", None),
]


@pytest.fixture(scope="module")
def graded():
    args = ["grade", str(PROBLEMS / "frames" / "rotating-hoop-fast.yaml"), "--format", "json"]
    for line, _, _ in LINES:
        args += ["--answer", line]
    args += ["--answer", "omega1 = 4.599 Hz", "--answer", "K = 1"]
    result = CliRunner().invoke(main, args)
    return result, json.loads(result.stdout)


def test_units_and_printed_names_are_read(graded) -> None:
    _, body = graded
    got = [(a["answer"], a["right"]) for a in body["answers"]]
    assert [a for a, _ in got] == [address for _, address, _ in LINES]
    assert [r for (_, r), (_, _, want) in zip(got, LINES) if want is not None] == [w for _, _, w in LINES
                                                                                    if w is not None]
    assert got[-2][1] != got[-1][1]  # θ₀ is +66.9° or −66.9°, the same equilibrium: one is right


def test_a_unit_that_is_not_the_answers_and_a_name_printed_twice_are_one_message_each(graded) -> None:
    result, body = graded
    assert result.exit_code == 2
    assert body["errors"][0] == "--answer:11:9: 'Hz' is not the unit of this answer: give it in rad/s"
    assert "give the whole path" in body["errors"][1] and "modes.K" in body["errors"][1]


# A particle released from rest on top of a smooth sphere leaves it where
# m g cos θ − m v²/R = 0 with v² = 2 g R (1 − cos θ): cos θ = 2/3 (by hand).
EQUATIONS = [
    ("contact_lost.N_P = cos(theta) = 2/3", True),
    ("contact_lost.N_P = 3*cos(theta) = 2", True),  # a constant factor: the same equation
    ("contact_lost.N_P = theta = acos(2/3)", True),  # solved for θ
    ("contact_lost.N_P = cos(theta) = 1/3", False),
    ("contact_lost.N_P = cos(theta) > 2/3", False),  # a condition for an equation
]

# The bead on a hoop turning at Ω: the off-axis equilibria cos θ₀ = g/(Ω² R) exist
# where g/(Ω² R) ≤ 1, Ω ≥ √(g/R) (by hand).
CONDITIONS = [
    ("equilibria.equilibria[2].exists_when = Omega > sqrt(g/R)", True),  # > for ≥: the boundary only
    ("equilibria.equilibria[2].exists_when = Omega**2*R >= g", True),
    ("equilibria.equilibria[2].exists_when = g <= R*Omega**2", True),
    ("equilibria.equilibria[2].exists_when = Omega > sqrt(2*g/R)", False),
    ("equilibria.equilibria[2].exists_when = Omega < sqrt(g/R)", False),
]


def _grade(problem: str, lines: list[str]):
    args = ["grade", str(PROBLEMS / problem), "--format", "json"]
    for line in lines:
        args += ["--answer", line]
    result = CliRunner().invoke(main, args)
    return result, json.loads(result.stdout)


def test_an_equation_as_the_answer_is_compared_as_a_set_of_points() -> None:
    result, body = _grade("forces/particle-on-sphere.yaml", [line for line, _ in EQUATIONS] + ["contact_lost.N_P = 2/3"])
    assert [a["right"] for a in body["answers"]] == [want for _, want in EQUATIONS]
    assert {a["answer"] for a in body["answers"]} == {"reactions.contact_lost.N_P[1]"}
    assert body["errors"] == ["--answer:6:19: this answer is an equation or a condition: give one, "
                              "e.g. 'cos(theta) = 2/3' or 'Omega > sqrt(g/R)'"]


def test_a_condition_as_the_answer_is_compared_as_a_region() -> None:
    _, body = _grade("conditions/bead-on-turning-hoop.yaml", [line for line, _ in CONDITIONS])
    assert [a["right"] for a in body["answers"]] == [want for _, want in CONDITIONS]


def test_a_wrong_answer_is_shown_at_angles_inside_their_range() -> None:
    """Lagrange's first equation of seed problem 1 with cos θ for sin θ: the point it is
    shown different at has θ and φ in (−π, π], where the solution lists them."""
    wrong = ("eom.equations[1] = m*r**2*(7*ddot(theta)/4 + cos(phi - theta)*ddot(phi)/4"
             " - sin(phi - theta)*dot(phi)**2/4) + 2*m*g*r*cos(theta)")
    _, body = _grade("sg2150-2015-10-29/p1-two-rods.yaml", [wrong])
    (answer,) = body["answers"]
    point = {k: float(v) for k, v in answer["point"].items()}
    assert not answer["right"] and {"θ", "φ"} <= set(point)
    assert all(-math.pi < point[q] <= math.pi for q in ("θ", "φ"))
