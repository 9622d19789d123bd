"""Contact limits as conditions on the parameters (solvers/reactions/limits.py): when a
support holds at a state (N ≥ 0, T ≥ 0, μ ≥ |F|/N), and when the point where a contact
is lost along the motion is reached at all. Expected values derived by hand below."""

from __future__ import annotations

import json
import random

import sympy as sp

from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.render import latex, markdown
from rbdsolve.render.json import report_object
from rbdsolve.solvers import solve_problem
from rbdsolve.solvers.conditions.conditions import nonnegative_where

from conftest import PROBLEMS

m, R, g, k, omega, alpha, r = sp.symbols("m R g k omega alpha r", positive=True)
mu_C = sp.Symbol("mu_C")
NAMES = {"m": m, "R": R, "g": g, "k": k, "omega": omega, "alpha": alpha, "r": r, "mu_C": mu_C}

SPHERE = """title: a particle on a smooth sphere
parameters: {m: mass, R: radius, g: acceleration, omega: angular speed at the top, k: stiffness}
coordinates: [theta]
gravity: [0, -g]
points:
  O: [0, 0]
  P: R * [sin(theta), cos(theta)]
bodies:
  particle: {shape: particle, mass: m, at: P}
"""


def _answers(text: str) -> dict:
    report = solve_problem(build_model(load_text(text, "p.yaml")))
    result = json.loads(json.dumps(report_object(report)))["results"][0]
    assert result["ok"], result["error"]
    return result["answers"]


def _read(text: str):
    return sp.sympify(text, locals=NAMES)


def test_holds_at_the_top_only_below_a_speed() -> None:
    """At the top with θ̇ = ω: m g − N = m R ω² (the centripetal balance), so
    N = m (g − R ω²) ≥ 0 when ω ≤ √(g/R), the critical rate."""
    answers = _answers(SPHERE.replace("  k: stiffness}", "}").replace(", k: stiffness", "") +
                       "questions:\n  - reactions: {forces: [P], at: {theta: 0, dot(theta): omega}}\n")
    assert _read(answers["holds_when"]["P"]) == sp.Le(omega, sp.sqrt(g / R))
    assert [c["parameter"] for c in answers["critical"]] == ["omega"]
    assert sp.simplify(_read(answers["critical"][0]["value"]) - sp.sqrt(g / R)) == 0


def test_where_the_contact_is_lost_exists_only_for_a_soft_spring() -> None:
    """A spring of zero natural length from the centre O pulls the particle inward with
    k R (the sphere's radius is its length). Radially m R θ̇² = m g cos θ + k R − N, and
    from rest at the top θ̇² = 2 g (1 − cos θ)/R (the spring's energy is constant), so
    N = m g (3 cos θ − 2) + k R, zero at cos θ = (2 m g − k R)/(3 m g): below 2/3, and
    ≥ −1 only when k ≤ 5 m g/R (else the particle stays on the sphere)."""
    answers = _answers(SPHERE + "springs:\n  s: {stiffness: k, between: [P, O]}\n"
                       "questions:\n  - reactions: {forces: [P], from_rest: {theta: 0}}\n")
    th = sp.Function("theta")(sp.Symbol("t"))
    (lost,) = answers["contact_lost"]["N_P"]
    assert sp.simplify(_read(lost).rhs - (2 * m * g - k * R) / (3 * m * g)) == 0 and _read(lost).lhs == sp.cos(th)
    assert _read(answers["lost_exists_when"]["N_P"][0]) == sp.Le(k, 5 * g * m / R)
    assert answers["holds_when"]["P"] == "True"  # N = m g + k R at release


def test_rolling_holds_with_enough_friction() -> None:
    """The cylinder on the incline (hand, problems/forces/wheel-on-incline.expected.yaml):
    N = m g cos α ≥ 0 needs α ≤ π/2, and F = m g sin α/3 needs μ ≥ tan α/3."""
    text = (PROBLEMS / "forces" / "wheel-on-incline.yaml").read_text(encoding="utf-8")
    condition = _read(_answers(text)["holds_when"]["C"])
    for a, mu, held in [(sp.pi / 6, 0.2, True), (sp.pi / 6, 0.19, False), (sp.pi / 3, 0.58, True),
                        (2 * sp.pi / 3, 5, False)]:
        assert bool(condition.xreplace({alpha: a, mu_C: mu})) is held, (a, mu)


def test_a_string_that_stays_taut_holds_always() -> None:
    """The yo-yo's tension is m g/3 > 0 whatever the parameters."""
    text = (PROBLEMS / "forces" / "yo-yo.yaml").read_text(encoding="utf-8")
    answers = _answers(text)
    assert answers["holds_when"]["S"] == "True" and answers["critical"] == []


def test_a_zero_reached_only_after_a_let_go_is_no_loss() -> None:
    """A solid cylinder (radius r) released from rest at θ = α inside a hollow one (R):
    its centre moves on a circle of radius R − r, so radially
    m (R − r) θ̇² = N − m g cos θ, and T + V constant gives
    (3/4) m (R − r)² θ̇² = m g (R − r)(cos θ − cos α). So N = m g (7 cos θ − 4 cos α)/3,
    zero at cos θ = 4 cos α/7, where cos θ − cos α = −3 cos α/7: reached (θ̇² ≥ 0) only
    when cos α ≤ 0, α ≥ π/2; released lower, the cylinder turns back first. But there
    N = m g cos α ≤ 0 at the release: the cylinder leaves at once, and the zero is where N
    rises back through zero, no loss (failure-edges §75)."""
    text = (PROBLEMS / "contacts" / "cylinder-in-cylinder.yaml").read_text(encoding="utf-8").split("questions:")[0]
    text = text.replace("parameters:\n", "parameters:\n  alpha: angle of release\n")
    text = "\n".join(line for line in text.splitlines() if not line.startswith("values:"))
    answers = _answers(text + "\nquestions:\n  - reactions: {from_rest: {theta: alpha}}\n")
    th = sp.Function("theta")(sp.Symbol("t"))
    (name,) = answers["along"]
    N = _read(answers["along"][name]["N_" + name])
    assert sp.simplify(N - m * g * (7 * sp.cos(th) - 4 * sp.cos(alpha)) / 3) == 0
    assert answers["contact_lost"]["N_" + name] == [] and answers["lost_exists_when"]["N_" + name] == []


def test_a_union_of_pieces_is_printed_and_right() -> None:
    """A particle on top of a smooth circle of radius l (a guide at P, θ from the upward
    vertical), a spring of zero natural length to A = (0, h) above the centre, released
    from rest at θ₀ (issue 38: exit 3, 'Or' object has no attribute 'lhs', where the
    condition is k > … or k ≤ …; the hanging pendulum it was found on loses its push
    nowhere, failure-edges §75). By hand: V = (m g − k h) l cos θ + const, so
    m l θ̇² = 2 (m g − k h)(cos θ₀ − cos θ); radially, outward,
    N = (m g − k h) cos θ + k l − m l θ̇² = (m g − k h)(3 cos θ − 2 cos θ₀) + k l, zero at
    cos θ = c = (2 (m g − k h) cos θ₀ − k l)/(3 (m g − k h)). θ̇² is monotone in cos θ from
    0 at θ₀, so c is reached iff |c| ≤ 1 and θ̇² ≥ 0 there, 2 N(θ₀)/(3 m l) ≥ 0: a loss
    where N ≥ 0 at the release and |c| ≤ 1. The printed condition, sampled on both sides
    (θ₀ in (0, π), the range of a positive angle), says the same."""
    text = """title: a particle on a circle held by a spring from above the centre
parameters: {m: mass, l: length, g: gravity, k: stiffness, h: height of the anchor, theta0: angle of release}
coordinates: [theta]
gravity: [0, -g]
points:
  P: l * [sin(theta), cos(theta)]
  A: "[0, h]"
bodies:
  bob: {shape: particle, mass: m, at: P}
springs:
  s: {stiffness: k, between: [P, A]}
questions:
  - reactions: {forces: [P], from_rest: {theta: theta0}}
"""
    report = solve_problem(build_model(load_text(text, "p.yaml")))
    assert "either" in markdown.render(report) and "either" in latex.render_document([report])  # printed, no crash
    got = json.loads(json.dumps(report_object(report)))["results"][0]["answers"]
    (condition,) = got["lost_exists_when"]["N_P"]
    l, h, theta0 = sp.symbols("l h theta0", positive=True)
    names = {**NAMES, "l": l, "h": h, "theta0": theta0}
    printed = sp.sympify(condition, locals=names)
    rng = random.Random(38)
    sides = set()
    for _ in range(60):
        values = {m: rng.uniform(0.1, 2), g: rng.uniform(1, 10), k: rng.uniform(0.1, 30), l: rng.uniform(0.1, 2),
                  h: rng.uniform(0.1, 2), theta0: rng.uniform(0.05, 3.1)}
        w = float((m * g - k * h).subs(values))
        c = float(((2 * (m * g - k * h) * sp.cos(theta0) - k * l) / (3 * (m * g - k * h))).subs(values))
        reached_by_rate = float(((m * g - k * h) * sp.cos(theta0) + k * l).subs(values))
        if abs(w) < 1e-6 or min(abs(abs(c) - 1), abs(reached_by_rate)) < 1e-6:
            continue  # too near a boundary to say
        hand = abs(c) <= 1 and reached_by_rate >= 0
        sides.add(hand)
        assert bool(printed.subs(values)) is hand, values
    assert sides == {True, False}


SHELL_IN_PIPE = """title: a spherical shell released inside a pipe
parameters: {m: mass, r: radius, R: pipe radius, theta0: angle of release, g: acceleration}
values: {m: 400 g, r: 5 cm, R: 60 cm, theta0: 50 deg, g: 9.81 m/s^2}
coordinates: [theta]
gravity: [0, -g]
bodies:
  ball: {shape: spherical_shell, mass: m, radius: r}
contacts:
  C: {body: ball, rolls_on: {circle: {centre: [0, 0], radius: R, side: inside}}, along: theta}
questions:
  - reactions: {forces: [C], from_rest: {theta: theta0}}
"""


def test_a_condition_the_assumptions_rule_out_is_written_in_the_next_parameter() -> None:
    """A shell (J = ⅔ m r²) inside a pipe, R > r by its contact (newuser20): T = (5/6) m
    (R − r)² θ̇², so θ̇² = 6 g (cos θ − cos θ₀)/(5 (R − r)), and N = m g (11 cos θ −
    6 cos θ₀)/5 vanishes at cos θ = 6 cos θ₀/11, where θ̇² = −6 g cos θ₀/(11 (R − r)):
    ≥ 0 only when θ₀ ≥ π/2. It was written "only when r > R", which the contact's R > r
    rules out. (That zero is no loss: N = m g cos θ₀ ≤ 0 at the release there, failure-edges
    §75, so the sign is asked of the condition itself.)"""
    theta0 = sp.Symbol("theta0", positive=True)
    model = build_model(load_text(SHELL_IN_PIPE, "p.yaml"))
    names = model.symbols.parameters
    found = nonnegative_where(-6 * names["g"] * sp.cos(names["theta0"]) / (11 * (names["R"] - names["r"])), model)
    assert found.condition.xreplace({names["theta0"]: theta0}) == sp.Ge(theta0, sp.pi / 2)
    report = solve_problem(model)
    result = json.loads(json.dumps(report_object(report)))["results"][0]
    assert result["answers"]["lost_exists_when"]["N_C"] == []
