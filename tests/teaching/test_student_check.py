"""A student's check on the seed exam (teaching/check.py, ``rbdsolve grade FILE --answer``).

The right answers come from the exam's worked solutions (shared/seeds/000_…txt), not
from rbdsolve: problem 1 λ₁ = 24g/(25r), λ₂ = 2g/r, ω = √λ, M = m r² [[7/4, 1/4],
[1/4, 1/3]], K = m g r [[2, 0], [0, 1/2]], four equilibria θ₀, φ₀ ∈ {0, π}, only
θ₀ = φ₀ = 0 stable; problem 2 ẋ = 7v₀/5, l φ̇ = 6v₀/5; problem 3 ω₀² cos θ (4R +
r sin θ) = 2 g sin θ; problem 4 principal moments (23 ± √145)/12 m r² and 17/6 m r²
(ascending, as docs/json.md says they are listed); problem 5 m l² φ̈ + m (g + ÿ_A) l
sin φ = 0. Each is given in forms a student writes (expanded, factored, rationalized,
√ as a power ½) and with the slips a grader meets. One CLI run per problem (its
answers as JSON), so each problem is solved once.
"""

from __future__ import annotations

import json
import math

import pytest
from click.testing import CliRunner

from rbdsolve.cli import main

from conftest import PROBLEMS, SEED

P1 = [
    # equivalent forms of the exam's answers
    ("modes.frequencies[1] = sqrt(24*g/(25*r))", "right"),
    ("omega1 = 2*sqrt(6*g*r)/(5*r)", "right"),  # rationalized
    ("ω₁ = (24*g/(25*r))**(1/2)", "right"),  # √ as a power ½
    ("omega2 = (2*g/r)**0.5", "right"),
    ("lambda1 = 24/25*g/r", "right"),
    ("modes.M[1][1] = 7*m*r**2/4", "right"),
    ("modes.M[2][1] = m*r*r/4", "right"),
    ("modes.K[1][1] = g*m*r + m*g*r", "right"),  # expanded
    ("omega2 = sqrt(2*G/r)", None),  # G is not a symbol of the problem: malformed
    ("eom.equations[1] = m*r**2*(7*ddot(theta)/4 + cos(phi - theta)*ddot(phi)/4 - sin(phi - theta)*dot(phi)**2/4)"
     " + 2*m*g*r*sin(theta)", "right"),
    ("eom.equations[2] = m*r**2*cos(phi - theta)*ddot(theta)/4 + m*r**2*ddot(phi)/3"
     " + m*r**2*sin(phi - theta)*dot(theta)**2/4 + m*g*r*sin(phi)/2", "right"),  # expanded
    ("modes.shapes[1][2] = 4/3", "right"),
    ("modes.shapes[2][2] = -3", "right"),
    # the slips, recognised as such
    ("omega2 = 2*sqrt(2*g/r)", "factor_2"),
    ("omega1 = sqrt(6*g/(25*r))", "factor_2"),  # ω/2
    ("omega1 = -sqrt(24*g/(25*r))", "sign"),
    ("omega1 = sqrt(24*g/(25*r))/(2*pi)", "two_pi"),  # f for ω
    ("omega2 = 2*g/r", "missing_root"),  # λ for ω
    ("lambda2 = sqrt(2*g/r)", "extra_root"),  # ω for λ
    ("modes.K[2][2] = -m*g*r/2", "sign"),
    # wrong answers
    ("omega1 = sqrt(g/r)", "factor"),  # a constant factor that is no slip
    ("omega1 = m*sqrt(24*g/(25*r))", "equal_for"),
    ("modes.M[1][1] = 7*m*r**2/4 + m*r", "different"),
    ("eom.equations[1] = m*r**2*(7*ddot(theta)/4 + cos(phi - theta)*ddot(phi)/4 - sin(phi - theta)*dot(phi)**2/4)"
     " + 2*m*g*r*cos(theta)", "different"),
    ("modes.shapes[1][2] = 3/4", "different"),
]


# Equilibria named by where they are (any order of listing): the exam's four.
PLACES = [("theta=0, phi=0", "stable"), ("theta=pi, phi=0", "unstable"), ("theta=0, phi=pi", "unstable"),
          ("theta=-pi, phi=3*pi", "unstable"), ("theta=pi, phi=pi", "stable")]


def run_check(problem: str, lines: list[str], *options: str):
    args = ["grade", str(SEED / problem), "--format", "json", *options]
    for line in lines:
        args += ["--answer", line]
    return CliRunner().invoke(main, args)


def outcome(answer: dict) -> str:
    if answer["right"]:
        return "right"
    return "+".join(answer["slips"]) or answer["verdict"]


@pytest.fixture(scope="module")
def p1():
    result = run_check("p1-two-rods.yaml", [line for line, _ in P1]
                       + [f"equilibria.equilibria[{k}].at.{q} = {v}"
                          for k in range(1, 5) for q in ("theta", "phi") for v in ("0", "pi", "180", "-pi")]
                       + [f"equilibrium{k}.stability = stable" for k in range(1, 5)]
                       + [f"equilibrium({place}).stability = {word}" for place, word in PLACES])
    return result, json.loads(result.stdout)


def test_p1_equivalent_forms_and_slips(p1) -> None:
    result, body = p1
    expected = [want for _, want in P1 if want is not None]
    assert [outcome(a) for a in body["answers"][: len(expected)]] == expected


def test_p1_a_malformed_answer_is_one_message_and_the_rest_is_checked(p1) -> None:
    result, body = p1
    assert result.exit_code == 2
    assert body["errors"] == ["--answer:9:17: unknown symbol 'G' (did you mean 'g'?)"]  # the 9th --answer
    assert "Traceback" not in result.output


def test_p1_equilibria_are_the_exams_up_to_whole_turns_and_degrees_are_recognised(p1) -> None:
    """Every equilibrium's coordinate is 0 or π (the exam); −π is π, whole turns apart;
    180 for π is degrees; exactly one equilibrium is stable, and it is at (0, 0)."""
    _, body = p1
    answers = {(a["answer"], a["given"]): a for a in body["answers"]}
    places = []
    for k in range(1, 5):
        at = {}
        for q in ("theta", "phi"):
            name = f"equilibria.equilibria[{k}].at.{q}"
            zero, pi = answers[(name, "0")], answers[(name, "pi")]
            assert zero["right"] != pi["right"]  # one of 0 and π, as the exam says
            at[q] = 0.0 if zero["right"] else math.pi
            assert answers[(name, "-pi")]["right"] == pi["right"]
            assert outcome(answers[(name, "180")]) == ("degrees" if pi["right"] else "different")
        places.append((at["theta"], at["phi"]))
    assert sorted(places) == sorted((a, b) for a in (0.0, math.pi) for b in (0.0, math.pi))
    stable = [places[k - 1] for k in range(1, 5) if answers[(f"equilibria.equilibria[{k}].stability", "stable")]["right"]]
    assert stable == [(0.0, 0.0)]


def test_p1_a_wrong_answer_is_shown_at_a_point_where_it_differs(p1) -> None:
    """The point is checked by hand: yours 7/4 m r² + m r there, the answer's 7/4 m r²."""
    _, body = p1
    wrong = next(a for a in body["answers"] if a["given"] == "7*m*r**2/4 + m*r")
    point = {k: float(v) for k, v in wrong["point"].items()}
    m, r = point["m"], point["r"]
    assert float(wrong["yours"]) == pytest.approx(7 * m * r**2 / 4 + m * r, rel=1e-5)
    assert m * r != 0  # where the two differ
    assert "expected" not in wrong and "expected_there" not in wrong  # not shown unless asked


def test_p1_equal_only_for_names_the_parameter_value(p1) -> None:
    _, body = p1
    answer = next(a for a in body["answers"] if a["given"] == "m*sqrt(24*g/(25*r))")
    assert answer["condition"] == "m = 1"


def test_p2_impact_velocities_by_their_alias() -> None:
    result = run_check("p2-rod-impact.yaml", [
        "dot(x) = 7*v0/5", "dot(phi) = 6*v0/(5*l)", "impact.velocities.phi = 1.2*v0/l",
        "dot(x) = -7*v0/5", "impact.energy_lost = m*v0**2/10", "dot(phi) = 6*v0/5"])
    body = json.loads(result.stdout)
    assert [outcome(a) for a in body["answers"]] == ["right", "right", "right", "sign", "right", "equal_for"]
    assert body["answers"][-1]["condition"] == "l = 1"
    assert result.exit_code == 1


def test_p3_a_trigonometric_rewrite_is_the_same_relation() -> None:
    result = run_check("p3-rolling-ring.yaml", [
        "steady_motion.solved.omega0**2 = 2*g*tan(theta)/(4*R + r*sin(theta))",
        "steady_motion.solved.omega0**2 = 2*g*sin(theta)/(cos(theta)*(4*R + r*cos(theta)))",
        "steady_motion.rates.spin = -omega0*R/r - omega0*sin(theta)"])
    body = json.loads(result.stdout)
    assert [outcome(a) for a in body["answers"]] == ["right", "different", "right"]


def test_p4_principal_moments_expanded_and_factored() -> None:
    result = run_check("p4-cylindrical-shell-inertia.yaml", [
        "J1 = 23*m*r**2/12 - sqrt(145)*m*r**2/12", "J2 = 17/6*m*r**2", "J3 = m*r**2*(23 + 145**(1/2))/12",
        "inertia.principal_moments[3] = (23 + sqrt(145))*m*r/12", "J1 = (23 - sqrt(145))*m*r**2/6"])
    body = json.loads(result.stdout)
    assert [outcome(a) for a in body["answers"]] == ["right", "right", "right", "equal_for", "factor_2"]


def test_p5_an_equation_of_motion_with_a_given_function_of_time() -> None:
    result = run_check("p5-accelerated-pendulum.yaml", [
        "eom.equations[1] = m*l**2*ddot(phi) + m*g*l*sin(phi) + m*l*sin(phi)*ddot(y_A)",
        "eom.equations[1] = -m*l**2*ddot(phi) - m*(g + ddot(y_A))*l*sin(phi)",
        "eom.equations[1] = m*l**2*ddot(phi) + m*g*l*sin(phi)"])
    body = json.loads(result.stdout)
    assert [outcome(a) for a in body["answers"]] == ["right", "sign", "different"]


def test_the_answer_is_printed_only_when_asked() -> None:
    """Nor anything that gives it away: a constant factor that is no slip (yours over
    it is the answer), the answer's value where a wrong one differs."""
    lines = ["omega1 = sqrt(g/r)", "omega2 = sqrt(g/r) + 1"]
    hidden = run_check("p1-two-rods.yaml", lines, "--format", "text")
    shown = run_check("p1-two-rods.yaml", lines, "--format", "text", "--show")
    assert hidden.exit_code == shown.exit_code == 1
    assert "√6" not in hidden.stdout and "√2" not in hidden.stdout and "the answer" not in hidden.stdout
    assert "off by a constant factor\n" in hidden.stdout
    assert "the answer: modes.frequencies[1] = 2 √6" in shown.stdout
    assert "off by a constant factor 5 √6/12" in shown.stdout


def test_p1_equilibria_named_by_where_they_are(p1) -> None:
    _, body = p1
    found = [a for a in body["answers"] if a["given"] in ("stable", "unstable")][-len(PLACES):]
    assert [outcome(a) for a in found] == ["right", "right", "right", "right", "different"]


def test_p3_compared_only_where_the_steady_motion_exists() -> None:
    """ω₀² = 2 g sin θ/((4R + r sin θ) cos θ) exists for θ < π/2 (cos θ > 0 there): an
    answer with |cos θ| is the same answer where the motion exists, and was 'different
    at θ = 2', a tilt past the horizontal; one with cos² θ differs inside it too."""
    result = run_check("p3-rolling-ring.yaml", [
        "steady_motion.solved.omega0**2 = 2*g*sin(theta)/((4*R + r*sin(theta))*abs(cos(theta)))",
        "steady_motion.branches[1].solved.omega0**2 = 2*g*sin(theta)/((4*R + r*sin(theta))*abs(cos(theta)))",
        "steady_motion.solved.omega0**2 = 2*g*sin(theta)/((4*R + r*sin(theta))*cos(theta)**2)"])
    body = json.loads(result.stdout)
    assert [outcome(a) for a in body["answers"]] == ["right", "right", "different"]
    assert 0 < float(body["answers"][2]["point"]["θ"]) < math.pi / 2


RANGED = """\
title: A pendulum of a length drawn per student
parameters: {m: mass, l: length, g: acceleration}
values: {l: {range: [2, 5], step: 1}}
coordinates: [theta]
gravity: [0, -g]
points:
  P: l*[sin(theta), -cos(theta)]
bodies:
  bob: {shape: particle, mass: m, at: P}
questions:
  - modes: {about: {theta: 0}}
"""


def test_test_points_lie_inside_a_parameters_range(tmp_path) -> None:
    """l is drawn in [2, 5]: there |l − 6| − 6 + 2l = l, so g/(|l − 6| − 6 + 2l) is λ = g/l
    for every l the exam draws (it was 'different' at an l past 6); a wrong g/l² is shown
    at an l inside the range, or named by where it agrees."""
    path = tmp_path / "ranged.yaml"
    path.write_text(RANGED, encoding="utf-8")
    args = ["grade", str(path), "--format", "json", "--answer", "lambda1 = g/l**2",
            "--answer", "lambda1 = g/(abs(l - 6) - 6 + 2*l)"]
    body = json.loads(CliRunner().invoke(main, args).stdout)
    wrong, inside = body["answers"]
    assert outcome(inside) == "right"  # |l − 6| = 6 − l for every l the exam draws
    if "point" in wrong:
        assert 2 <= float(wrong["point"]["l"]) <= 5
    else:
        assert outcome(wrong) == "equal_for"


def test_abs_and_its_argument_agree_where_the_assumptions_fix_the_sign() -> None:
    """A cylinder rolling inside a cylinder of radius R > r (its assumption): λ = 2g/(3(R − r))
    by hand (T = ¾ m (R − r)² θ̇², V = −m g (R − r) cos θ); |R − r| and |r − R| are R − r
    there, and r − R is the sign slip."""
    args = ["grade", str(PROBLEMS / "contacts" / "cylinder-in-cylinder.yaml"), "--format", "json"]
    for line in ["lambda1 = 2*g/(3*abs(R - r))", "lambda1 = 2*g/(3*abs(r - R))", "lambda1 = 2*g/(3*(r - R))"]:
        args += ["--answer", line]
    body = json.loads(CliRunner().invoke(main, args).stdout)
    assert [outcome(a) for a in body["answers"]] == ["right", "right", "sign"]


def test_an_angle_given_in_degrees_is_drawn_in_its_quarter_turn() -> None:
    """The ladder released at φ₀ = 30° from the floor: N_B = ¾ m g sin φ₀ cos φ₀ just after
    release (by hand: problems/forces/ladder-angle-from-floor.expected.yaml). Written with
    |cos φ₀| it is the same answer for every release an exam means (0 < φ₀ < 90°); it was
    'wrong' at φ₀ = 4 rad. A wrong sin² φ₀ is still wrong."""
    problem = str(PROBLEMS / "forces" / "ladder-angle-from-floor.yaml")
    args = ["grade", problem, "--format", "json"]
    for line in ["reactions.at.B.components.N_B = 3*m*g*sin(phi0)*abs(cos(phi0))/4",
                 "reactions.at.B.components.N_B = 3*m*g*sin(phi0)**2/4"]:
        args += ["--answer", line]
    body = json.loads(CliRunner().invoke(main, args).stdout)
    assert [a["right"] for a in body["answers"]] == [True, False]


def test_a_name_two_answers_hold_with_one_value_is_graded() -> None:
    """Ω_c = √(g/R) is the critical rate of the bead on a turning hoop's equilibria and of
    its modes (by hand: g/R − Ω² changes sign there): one answer, not an ambiguous name."""
    args = ["grade", str(PROBLEMS / "conditions" / "bead-on-turning-hoop.yaml"), "--format", "json",
            "--answer", "Omega_c = sqrt(g/R)", "--answer", "Omega_c = sqrt(2*g/R)"]
    result = CliRunner().invoke(main, args)
    assert result.exit_code == 1, result.output
    assert [a["right"] for a in json.loads(result.stdout)["answers"]] == [True, False]
