"""Conditions in the parameter the question is about (issue 38): the one `for:` names,
else the only parameter without a value, else a rate, a stiffness, a length, a mass, in
that order. Each critical value is compared with a hand derivation, and each printed
case is checked by sampling the parameters on both sides of it.

By hand:
- an inverted rod (m, L) on a pivot with a mass M at its top, held by two horizontal
  springs k at the height a: K = 2 a² k − (M + m/2) g L, M = L² (M + m/3), so λ > 0 iff
  k > k_c = (2M + m) g L/(4 a²), i.e. a > a_c = √((2M + m) g L/(4k));
- a half-disk (m, r) rocking on a drum R: λ ∝ 4R + 4r − 3π r, an oscillation iff
  R > R_c = (3π − 4) r/4, i.e. r < r_c = 4R/(3π − 4);
- an inverted rod (m, l) with a torsional spring c: λ ∝ 2c − m g l, an oscillation iff
  c > m g l/2, i.e. l < 2c/(m g), m < 2c/(g l).
"""

from __future__ import annotations

import math
import random

import sympy as sp

from conftest import PROBLEMS, ROD_ON_INCLINE
from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.solvers import solve_problem

SPRINGS = (PROBLEMS / "conditions" / "inverted-rod-springs.yaml").read_text()
DRUM = (PROBLEMS / "conditions" / "half-disk-on-drum.yaml").read_text()
TORSION = "\n".join(line for line in (PROBLEMS / "edges" / "inverted-rod-torsion-spring.yaml").read_text().splitlines()
                    if not line.startswith("values:"))


def _answers(text: str, question: str = "modes"):
    report = solve_problem(build_model(load_text(text, "scene.yaml")))
    (solution,) = [s for s in report.solutions if s.question == question]
    assert solution.solved, solution.error
    return solution.answers


def _symbols(names: str) -> dict[str, sp.Symbol]:
    return {n: sp.Symbol(n, positive=True) for n in names.split()}


def _read(text, symbols: dict) -> sp.Basic:
    return sp.parse_expr(str(text), local_dict=symbols)


def _critical(answers, parameter: str, expected: sp.Expr, symbols: dict) -> None:
    (c,) = answers.critical
    assert c.parameter == parameter
    assert sp.simplify(_read(c.value, symbols) - expected) == 0


def _sampled(answers, symbols: dict, draw, kind_at) -> None:
    """At 40 points drawn on both sides of the critical value, exactly one case holds,
    and it is the kind the hand derivation gives there."""
    (cases,) = answers.cases
    rng = random.Random(38)
    for _ in range(40):
        at = draw(rng)
        (case,) = [x for x in cases if bool(_read(x.when, symbols).subs({symbols[n]: v for n, v in at.items()}))]
        assert case.kind.value == kind_at(at)


def _springs_kind(v: dict) -> str:
    return "oscillation" if 2 * v["a"] ** 2 * v["k"] - (v["M"] + v["m"] / 2) * v["g"] * v["L"] > 0 else "growth"


def _springs_point(rng: random.Random, free: str) -> dict:
    """The file's values, and the free parameter on either side of its critical value."""
    v = {"m": 2.0, "M": 1.0, "L": 1.0, "a": 0.5, "g": 9.81, "k": 39.24}
    critical = {"k": (2 * v["M"] + v["m"]) * v["g"] * v["L"] / (4 * v["a"] ** 2),
                "a": math.sqrt((2 * v["M"] + v["m"]) * v["g"] * v["L"] / (4 * v["k"] * 1.5))}[free]
    if free == "a":
        v["k"] *= 1.5
    v[free] = critical * rng.choice([rng.uniform(0.2, 0.98), rng.uniform(1.02, 5)])
    return v


def test_every_value_given_but_k_puts_the_condition_in_k() -> None:
    """'How stiff must the springs be': every value given but k, so k_c, not a_c (a comes
    first in the file)."""
    s = _symbols("m M L a g k d")
    answers = _answers(SPRINGS)
    _critical(answers, "k", (2 * s["M"] + s["m"]) * s["g"] * s["L"] / (4 * s["a"] ** 2), s)
    _sampled(answers, s, lambda rng: _springs_point(rng, "k"), _springs_kind)


def test_every_value_given_but_a_puts_the_condition_in_a() -> None:
    text = SPRINGS.replace("values: {", "values: {k: 58.86 N/m, ").replace("a: 50 cm, ", "")
    s = _symbols("m M L a g k d")
    answers = _answers(text)
    _critical(answers, "a", sp.sqrt((2 * s["M"] + s["m"]) * s["g"] * s["L"] / (4 * s["k"])), s)
    _sampled(answers, s, lambda rng: _springs_point(rng, "a"), _springs_kind)


def _drum_point(rng: random.Random) -> dict:
    r, g, m = rng.uniform(0.1, 3), rng.uniform(1, 20), rng.uniform(0.1, 5)
    R = (3 * math.pi - 4) * r / 4 * rng.choice([rng.uniform(0.2, 0.98), rng.uniform(1.02, 5)])
    return {"r": r, "R": R, "g": g, "m": m}


def _drum_kind(v: dict) -> str:
    return "oscillation" if 4 * v["R"] + 4 * v["r"] - 3 * math.pi * v["r"] > 0 else "growth"


def test_for_names_the_parameter_a_half_disk_on_a_drum_is_asked_in() -> None:
    s = _symbols("m r R g")
    answers = _answers(DRUM)  # the file asks 'for: R'
    _critical(answers, "R", (3 * sp.pi - 4) * s["r"] / 4, s)
    _sampled(answers, s, _drum_point, _drum_kind)


def test_without_for_the_half_disk_is_asked_in_the_first_length() -> None:
    s = _symbols("m r R g")
    answers = _answers(DRUM.replace(", for: R}", "}"))
    _critical(answers, "r", 4 * s["R"] / (3 * sp.pi - 4), s)
    _sampled(answers, s, _drum_point, _drum_kind)


def test_for_wins_over_the_only_parameter_without_a_value() -> None:
    """k alone has no value, but the question names a: the condition is in a."""
    text = SPRINGS.replace("modes: {about: {theta: 0}}", "modes: {about: {theta: 0}, for: a}")
    s = _symbols("m M L a g k d")
    _critical(_answers(text), "a", sp.sqrt((2 * s["M"] + s["m"]) * s["g"] * s["L"] / (4 * s["k"])), s)


def _torsion_point(rng: random.Random) -> dict:
    v = {n: rng.uniform(0.1, 5) for n in ("m", "l", "g", "c")}
    v["c"] = v["m"] * v["g"] * v["l"] / 2 * rng.choice([rng.uniform(0.2, 0.98), rng.uniform(1.02, 5)])
    return v


def _torsion_kind(v: dict) -> str:
    return "oscillation" if 2 * v["c"] - v["m"] * v["g"] * v["l"] > 0 else "growth"


def test_a_stiffness_comes_before_lengths_and_masses() -> None:
    s = _symbols("m l g c")
    answers = _answers(TORSION)
    _critical(answers, "c", s["g"] * s["l"] * s["m"] / 2, s)
    _sampled(answers, s, _torsion_point, _torsion_kind)


# A rod (m, l) hung from a pivot at its end, with a mass M on a light arm at the height a
# above the pivot: V = g cos θ (M a − m l/2), K = g (m l/2 − M a), M = m l²/3 + M a²:
# an oscillation iff a < a_c = m l/(2M) (or M < m l/(2a), in the first parameter).
BALANCE = """\
parameters: {M: top mass, m: mass of the rod, a: height of the top mass, l: length of the rod, g: gravity}
coordinates: [theta]
gravity: [0, -g]
points:
  G: l/2*[sin(theta), -cos(theta)]
  T: a*[-sin(theta), cos(theta)]
bodies:
  rod: {shape: rod, mass: m, length: l, at: G, angle: theta, axis: y}
  top: {shape: particle, mass: M, at: T}
questions:
  - modes: {about: {theta: 0}}
"""


def _balance_point(rng: random.Random) -> dict:
    v = {n: rng.uniform(0.1, 5) for n in ("M", "m", "l", "g")}
    v["a"] = v["m"] * v["l"] / (2 * v["M"]) * rng.choice([rng.uniform(0.2, 0.98), rng.uniform(1.02, 5)])
    return v


def test_a_length_comes_before_a_mass() -> None:
    """M comes first in the file, but a length is asked before a mass: a_c, the first
    length; the masses and g say nothing of the kind."""
    s = _symbols("M m a l g")
    answers = _answers(BALANCE)
    _critical(answers, "a", s["m"] * s["l"] / (2 * s["M"]), s)
    _sampled(answers, s, _balance_point,
             lambda v: "oscillation" if v["m"] * v["l"] / 2 - v["M"] * v["a"] > 0 else "growth")


def test_for_a_mass() -> None:
    s = _symbols("M m a l g")
    answers = _answers(BALANCE.replace("{about: {theta: 0}}", "{about: {theta: 0}, for: M}"))
    _critical(answers, "M", s["m"] * s["l"] / (2 * s["a"]), s)
    _sampled(answers, s, _balance_point,
             lambda v: "oscillation" if v["m"] * v["l"] / 2 - v["M"] * v["a"] > 0 else "growth")


# A heavy top at the tilt θ (problems/conditions): the two precession rates are real where
# D = J3² s² − 4 (J1 + m h² − J3) m g h cos θ ≥ 0 (by hand, its golden file), in the spin s
# by kind (a rate), and, asked 'for: g', where g ≤ g_c = J3² s²/(4 (J1 + m h² − J3) m h cos θ).
TOP = (PROBLEMS / "conditions" / "heavy-top-precession-rates.yaml").read_text()


def test_for_names_the_parameter_a_steady_motion_exists_in() -> None:
    s = _symbols("m h J1 J3 g theta spin")
    answers = _answers(TOP.replace("solve_for: Omega}", "solve_for: Omega, for: g}"), "steady_motion")
    want = s["J3"] ** 2 * s["spin"] ** 2 / (4 * (s["J1"] + s["m"] * s["h"] ** 2 - s["J3"]) * s["m"] * s["h"]
                                            * sp.cos(s["theta"]))
    _critical(answers, "g", want, s)
    rng = random.Random(38)
    for _ in range(20):
        v = {"m": rng.uniform(0.1, 3), "h": rng.uniform(0.1, 2), "J3": rng.uniform(0.1, 1), "theta": rng.uniform(0.1, 1.5),
             "spin": rng.uniform(1, 30)}
        v["J1"] = v["J3"] * rng.uniform(1.1, 3)
        v["g"] = float(want.subs({s[n]: x for n, x in v.items()})) * rng.choice([rng.uniform(0.2, 0.98), rng.uniform(1.02, 5)])
        D = v["J3"] ** 2 * v["spin"] ** 2 - 4 * (v["J1"] + v["m"] * v["h"] ** 2 - v["J3"]) * v["m"] * v["g"] * v["h"] \
            * math.cos(v["theta"])
        for branch in answers.branches:
            assert bool(_read(branch.exists_when, s).subs({s[n]: x for n, x in v.items()})) == (D >= 0)


def test_a_parameter_left_open_comes_before_one_given_a_value() -> None:
    """a, l and g given values, the masses M and m left open (two of them, so neither is
    'the only one without a value'): the condition is in the first open one, M < M_c =
    m l/(2 a), not in the length a that has a value (which a length's kind put first)."""
    s = _symbols("M m a l g")
    answers = _answers(BALANCE.replace("coordinates:", "values: {a: 0.2, l: 1, g: 9.81}\ncoordinates:"))
    _critical(answers, "M", s["m"] * s["l"] / (2 * s["a"]), s)
    _sampled(answers, s, _balance_point,
             lambda v: "oscillation" if v["m"] * v["l"] / 2 - v["M"] * v["a"] > 0 else "growth")


LOADED_ROD = (ROD_ON_INCLINE.replace("parameters: {", "parameters: {M: mass of the load, ")
              .replace("springs:", "  load: {shape: particle, mass: M, at: A}\nsprings:")
              + "questions:\n  - modes: {about: {theta: 0}, for: M}\n")


def test_for_a_parameter_that_splits_nothing_is_said() -> None:
    """By hand, V = (M + m/2) g L sin α cos θ + ½ k L² sin²θ: at θ = 0, K = k L² − (M +
    m/2) g L sin α, so k_c = (M + m/2) g sin α/L, while in M the critical value
    k L/(g sin α) − m/2 is positive only where 2 k L > m g sin α. For: M then writes the
    case in k, and a warning says so (a new user's `for: M` was dropped silently); under
    [2*k*L > g*m] (so 2 k L > g m sin α) it is written in M."""
    s = _symbols("m M L k g alpha")
    report = solve_problem(build_model(load_text(LOADED_ROD, "scene.yaml")))
    (solution,) = report.solutions
    assert solution.solved, solution.error
    _critical(solution.answers, "k", (s["M"] + s["m"] / 2) * s["g"] * sp.sin(s["alpha"]) / s["L"], s)
    assert any(w.startswith("for: M: no condition here is written in M") for w in solution.warnings)
    held = LOADED_ROD.replace("coordinates:", "assumptions: [2*k*L > g*m]\ncoordinates:")
    report = solve_problem(build_model(load_text(held, "scene.yaml")))
    (solution,) = report.solutions
    _critical(solution.answers, "M", s["k"] * s["L"] / (s["g"] * sp.sin(s["alpha"])) - s["m"] / 2, s)
    assert not any(w.startswith("for: M") for w in solution.warnings)
