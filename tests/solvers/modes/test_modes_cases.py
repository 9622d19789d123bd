"""Modes whose kind depends on the parameters (issue 19): oscillation on one side of a
critical value, growth on the other, each case checked by sampling.

By hand: the bead on the hoop turning at Ω, about θ = 0 in the hoop's frame:
M = m R², K = m R (g − Ω² R), λ = g/R − Ω²: an oscillation iff Ω < √(g/R).
An inverted rod (m, l) on a pivot with a torsional spring c, about θ = 0:
M = m l²/3, K = c − m g l/2, λ = 3 (2c − m g l)/(2 m l²): an oscillation iff c > m g l/2.
"""

from __future__ import annotations

import math
import random

import pytest
import sympy as sp

from conftest import PROBLEMS, TURNING_ROD
from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.solvers import solve_problem


def _without_values(path) -> str:
    return "\n".join(line for line in path.read_text().splitlines() if not line.startswith("values:"))


def _modes(text: str):
    report = solve_problem(build_model(load_text(text, "scene.yaml")))
    (solution,) = [s for s in report.solutions if s.question == "modes"]
    assert solution.solved, solution.error
    return solution.answers


def _holds(condition, at: dict) -> bool:
    names = {str(s): s for s in at}
    return bool(sp.parse_expr(str(condition), local_dict=names).subs(at))


def _check(answers, names: tuple[str, ...], critical, kind_at) -> None:
    (c,) = answers.critical
    assert c.parameter == critical[0]
    symbols = {n: sp.Symbol(n, positive=True) for n in names}
    assert sp.simplify(sp.parse_expr(str(c.value), local_dict=symbols) - critical[1](symbols)) == 0
    (cases,) = answers.cases
    rng = random.Random(19)
    for _ in range(40):
        at = {symbols[n]: rng.uniform(0.1, 5) for n in names}
        (case,) = [x for x in cases if _holds(x.when, at)]
        assert case.kind.value == kind_at({n: float(at[symbols[n]]) for n in names})


def test_the_hoop_oscillates_below_the_critical_rate_and_grows_above() -> None:
    answers = _modes(_without_values(PROBLEMS / "frames" / "rotating-hoop-slow.yaml"))
    _check(answers, ("m", "R", "g", "Omega"), ("Omega", lambda s: sp.sqrt(s["g"] / s["R"])),
           lambda v: "oscillation" if v["g"] / v["R"] - v["Omega"] ** 2 > 0 else "growth")


def test_the_inverted_rod_oscillates_when_the_spring_is_stiff_enough() -> None:
    text = _without_values(PROBLEMS / "edges" / "inverted-rod-torsion-spring.yaml")
    text = text[:text.index("questions:")] + "questions:\n  - modes: {about: {theta: 0}}\n"
    answers = _modes(text)
    _check(answers, ("m", "l", "g", "c"), ("c", lambda s: s["m"] * s["g"] * s["l"] / 2),
           lambda v: "oscillation" if v["c"] - v["m"] * v["g"] * v["l"] / 2 > 0 else "growth")
    (lam,) = answers.eigenvalues
    m, l, g, c = (sp.Symbol(n, positive=True) for n in "mlgc")
    assert sp.simplify(sp.parse_expr(str(lam), local_dict={"m": m, "l": l, "g": g, "c": c})
                       - 3 * (2 * c - m * g * l) / (2 * m * l**2)) == 0


def test_modes_at_every_equilibrium_with_their_cases() -> None:
    """about: each on the hoop (no values): θ = 0 oscillates below Ω_c and grows above;
    ±acos(g/(R Ω²)) exist only above Ω_c, where they oscillate with
    λ = Ω² − g²/(Ω² R²) (K/M by hand); θ = π grows at γ = √(g/R + Ω²)."""
    text = _without_values(PROBLEMS / "frames" / "rotating-hoop-slow.yaml")
    text = text[:text.index("questions:")] + "questions:\n  - modes: {frame: hoop, about: each}\n"
    report = solve_problem(build_model(load_text(text, "hoop.yaml")))
    (solution,) = report.solutions
    assert solution.solved, solution.error
    bottom, left, right, top = solution.answers.modes
    assert [m.value for m in bottom.motions] == ["depends"]
    R, g, Om = (sp.Symbol(n, positive=True) for n in ("R", "g", "Omega"))
    local = {"R": R, "g": g, "Omega": Om}
    for side in (left, right):
        assert [m.value for m in side.motions] == ["oscillation"]
        (lam,) = side.eigenvalues
        assert sp.simplify(sp.parse_expr(str(lam), local_dict=local) - (Om**2 - g**2 / (Om**2 * R**2))) == 0
    assert [m.value for m in top.motions] == ["growth"]
    (gamma,) = top.growth_rates
    assert sp.simplify(sp.parse_expr(str(gamma), local_dict=local) ** 2 - (g / R + Om**2)) == 0


def test_about_each_on_the_numeric_route() -> None:
    """The inverted rod with c = 3/10 (m = 1, l = 2, g = 1): equilibria −θ*, 0, θ* with
    λ = c (1 − k cos θ)/M, k = 10/3, M = 4/3 (by hand; θ* by mpmath)."""
    import mpmath as mp

    text = (PROBLEMS / "edges" / "inverted-rod-torsion-spring.yaml").read_text()
    text = text[:text.index("values:")] + "values: {m: 1, l: 2, g: 1, c: 3/10}\n" + text[text.index("coordinates:"):]
    text = text[:text.index("questions:")] + "questions:\n  - modes: {about: each}\n"
    (solution,) = solve_problem(build_model(load_text(text, "rod.yaml"))).solutions
    assert solution.solved and solution.route.value == "numeric", solution.error
    k = mp.mpf(10) / 3
    root = float(mp.findroot(lambda x: x - k * mp.sin(x), 2.5))
    for modes, theta in zip(solution.answers.modes, (-root, 0.0, root)):
        assert modes.about["theta"] == pytest.approx(theta, abs=1e-9)
        (lam,) = modes.eigenvalues
        assert lam == pytest.approx(0.3 * (1 - float(k) * math.cos(theta)) / (4 / 3), rel=1e-9)


# --- cases only where the answer exists (issue 38) ---------------------------------------


def test_modes_about_an_equilibrium_that_exists_only_above_the_critical_rate() -> None:
    """θ = acos(g/(R Ω²)) exists only where Ω ≥ Ω_c = √(g/R); there λ = Ω² − g²/(R² Ω²) > 0
    (by hand: K = m (Ω² R² − g²/Ω²), M = m R²), so one kind, an oscillation: no "growth
    when Ω < Ω_c", no critical value; the solution says where it exists."""
    report = solve_problem(build_model(load_text(
        (PROBLEMS / "conditions" / "bead-on-hoop-off-axis.yaml").read_text(), "hoop.yaml")))
    (solution,) = report.solutions
    assert solution.solved, solution.error
    answers = solution.answers
    assert [m.value for m in answers.motions] == ["oscillation"] and answers.cases == () and answers.critical == ()
    R, g, Om = (sp.Symbol(n, positive=True) for n in ("R", "g", "Omega"))
    (lam,) = answers.eigenvalues
    lam = sp.parse_expr(str(lam), local_dict={"R": R, "g": g, "Omega": Om})
    assert sp.simplify(lam - (Om**2 - g**2 / (R**2 * Om**2))) == 0
    rng = random.Random(38)
    for _ in range(40):  # wherever it exists (above Ω_c) λ > 0; below Ω_c acos is not real
        at = {R: rng.uniform(0.1, 5), g: rng.uniform(1, 20)}
        rate = math.sqrt(at[g] / at[R])
        above, below = rate * rng.uniform(1.02, 5), rate * rng.uniform(0.2, 0.98)
        assert float(lam.subs({**at, Om: above})) > 0
        assert abs(at[g] / (at[R] * below**2)) > 1  # no equilibrium: acos(g/(R Ω²)) is not real
    (note,) = [step for step in solution.steps if "exists only where" in step.text]
    (bound,) = note.math
    assert sp.simplify(sp.parse_expr(str(bound.rhs), local_dict={"R": R, "g": g}) - sp.sqrt(g / R)) == 0


def test_a_case_outside_the_assumptions_is_no_case() -> None:
    """A disk (m, r) rolling inside a ring (M, R) on an axle, R given, r not: the contact
    implies R > r, so λ = g (2M + m)/((3M + m)(R − r)) (by hand, docs in the golden file)
    is positive: an oscillation, with no case "growth when r > R" and no critical value.
    Sampled with r < R: the hand λ is positive at each."""
    text = (PROBLEMS / "conditions" / "disk-in-turning-ring.yaml").read_text()
    answers = _modes(text)
    assert [m.value for m in answers.motions] == ["neutral", "oscillation"]
    assert answers.cases == () and answers.critical == ()
    M, R, m, g, r = (sp.Symbol(n, positive=True) for n in ("M", "R", "m", "g", "r"))
    lam = sp.parse_expr(str(answers.eigenvalues[1]), local_dict={"M": M, "R": R, "m": m, "g": g, "r": r})
    assert sp.simplify(lam - g * (2 * M + m) / ((3 * M + m) * (R - r))) == 0
    rng = random.Random(38)
    for _ in range(20):  # inside the assumption (r < R = 2, the file's values) λ > 0
        at = {M: 2, R: 2, m: 1, g: sp.Rational(981, 100), r: sp.Rational(rng.randint(1, 1999), 1000)}
        assert lam.subs(at) > 0


def test_the_equilibrium_is_stable_under_the_assumption_when_a_value_is_given() -> None:
    """A cylinder (m, r) rolling inside a hollow cylinder R with R given and r not: the
    contact implies R > r, which decides K = g m (R − r) > 0 at θ = 0 (stable) and < 0 at
    θ = π (unstable) though the value of R drops the substitution R = r + δ."""
    text = (PROBLEMS / "conditions" / "cylinder-in-cylinder.yaml").read_text().replace(
        "assumptions: [R > r]", "values: {R: 1}")
    report = solve_problem(build_model(load_text(text, "cylinder.yaml")))
    equilibria, modes = report.solutions
    stabilities = {str(e.at["theta"]): e.stability.value for e in equilibria.answers.equilibria}
    assert stabilities == {"0": "stable", "pi": "unstable"}
    assert [k.value for k in modes.answers.motions] == ["oscillation"] and modes.answers.cases == ()


def test_kinds_and_cases_agree() -> None:
    """Wherever a λ has cases they are two or more, and its kind is `depends`, or, where
    the values decide it, the kind of the case the values fall in."""
    texts = [_without_values(PROBLEMS / "frames" / "rotating-hoop-slow.yaml")]
    texts += [(PROBLEMS / "frames" / name).read_text() for name in ("rotating-hoop-slow.yaml", "rotating-hoop-fast.yaml")]
    for text in texts:
        report = solve_problem(build_model(load_text(text, "hoop.yaml")))
        for solution in report.solutions:
            if solution.question != "modes":
                continue
            a = solution.answers
            values = {sp.Symbol(n, positive=True): v for n, v in report.values.items()}
            for motion, cases in zip(a.motions, a.cases or [()] * len(a.motions)):
                if not cases:
                    assert motion.value != "depends"
                    continue
                assert len(cases) >= 2
                if motion.value != "depends":
                    (held,) = [c for c in cases if bool(sp.parse_expr(str(c.when), local_dict={
                        str(s): s for s in values}).subs(values))]
                    assert held.kind is motion


# Two particles m1 (x) and m2 (y) on a line, a spring k from the wall to the first and one
# k between them: M = diag(m1, m2), K = [[2k, −k], [−k, k]]. By hand,
# det(K − λM) = m1 m2 λ² − k (m1 + 2 m2) λ + k² = 0, λ = k (m1 + 2 m2 ∓ √(m1² + 4 m2²))/(2 m1 m2):
# both positive (their sum and product are), though the smaller one's sign is not read
# off its form by sympy: K positive definite decides it (Sylvester's law of inertia).
TWO_MASSES = """
parameters: {m1: mass, m2: mass, k: stiffness}
coordinates: [x, y]
points:
  O: [0, 0]
  A: [x, 0]
  B: [y, 0]
bodies:
  a: {shape: particle, mass: m1, at: A}
  b: {shape: particle, mass: m2, at: B}
springs:
  s1: {stiffness: k, between: [O, A]}
  s2: {stiffness: k, between: [A, B]}
questions:
  - modes: {about: {x: 0, y: 0}}
"""


def test_two_masses_oscillate_in_both_modes_by_hand() -> None:
    (solution,) = solve_problem(build_model(load_text(TWO_MASSES, "two.yaml"))).solutions
    assert solution.solved, solution.error
    a = solution.answers
    assert [m.value for m in a.motions] == ["oscillation", "oscillation"]
    m1, m2, k = sp.symbols("m1 m2 k", positive=True)
    want = [k * (m1 + 2 * m2 - sp.sqrt(m1**2 + 4 * m2**2)) / (2 * m1 * m2),
            k * (m1 + 2 * m2 + sp.sqrt(m1**2 + 4 * m2**2)) / (2 * m1 * m2)]
    rng = random.Random(43)
    for _ in range(5):
        at = {m1: rng.uniform(0.1, 5), m2: rng.uniform(0.1, 5), k: rng.uniform(0.1, 50)}
        got = sorted(float(sp.sympify(str(w), locals={"m1": m1, "m2": m2, "k": k}).subs(at)) ** 2
                     for w in a.frequencies)
        assert got == pytest.approx(sorted(float(x.subs(at)) for x in want), rel=1e-10)


BEAD_ON_TURNING_ROD = TURNING_ROD.replace("  - equilibria: {frame: rod}\n", "")  # its modes alone


def test_modes_about_an_equilibrium_that_exists_somewhere_say_where():
    """A bead on a rod turning at Ω, held by a spring of natural length a from the axis
    (neighbours seed 5150, scene 45). By hand: V' = ½ k x² − ½ m Ω² (a + x)², so
    x₀ = m Ω² a/(k − m Ω²), and the bead is on the spring's drawn side, a + x₀ =
    a k/(k − m Ω²) > 0, only where Ω² < k/m. The modes' answers say so (a script reading
    JSON has no other way to know): the condition holds at samples below √(k/m), not above."""
    (entry,) = _modes(BEAD_ON_TURNING_ROD).modes
    x0, exists_when = entry.about["x"], entry.exists_when
    names = {str(x): x for x in x0.free_symbols | exists_when.free_symbols}
    m, k, a, W = (names[n] for n in ("m", "k", "a", "Omega"))
    assert sp.simplify(x0 - m * W**2 * a / (k - m * W**2)) == 0
    rng = random.Random(5150)
    for _ in range(8):
        values = {m: sp.Rational(rng.randint(1, 9), 2), k: sp.Rational(rng.randint(10, 90), 3), a: sp.Rational(1, 2)}
        critical = sp.sqrt(values[k] / values[m])
        for rate, exists in ((critical * sp.Rational(9, 10), True), (critical * sp.Rational(11, 10), False)):
            at = {**values, W: rate}
            assert bool(exists_when.subs(at)) is exists
            side = (a + x0).subs(at)  # the bead's distance from the axis, on the spring's side
            assert bool(side > 0) is exists


CARTS = """
title: Three carts on a smooth track joined by two springs, no walls
parameters: {m1: mass, m2: mass, m3: mass, k1: stiffness, k2: stiffness, L: length}
coordinates: [x1, x2, x3]
points:
  P1: [x1, 0]
  P2: [x2 + L, 0]
  P3: [x3 + 2*L, 0]
bodies:
  c1: {shape: particle, mass: m1, at: P1}
  c2: {shape: particle, mass: m2, at: P2}
  c3: {shape: particle, mass: m3, at: P3}
springs:
  s1: {stiffness: k1, between: [P1, P2], natural_length: L}
  s2: {stiffness: k2, between: [P2, P3], natural_length: L}
questions:
  - modes: {about: {x1: 0, x2: 0, x3: 0}}
"""


def test_a_semidefinite_k_makes_every_nonzero_eigenvalue_positive() -> None:
    """K = [[k1, −k1, 0], [−k1, k1 + k2, −k2], [0, −k2, k2]] ≥ 0 with one zero eigenvalue
    (the carts move together), M > 0: by Sylvester's law the other two λ are positive,
    though λ = (A − √(A² − 4B))/2 has no sign by itself (a trial's two carts and a
    pendulum were refused). By hand, the nonzero λ solve m1 m2 m3 λ² − (k1 m3 (m1 + m2) +
    k2 m1 (m2 + m3)) λ + k1 k2 (m1 + m2 + m3) = 0."""
    from rbdsolve.api import loads
    from rbdsolve.model.build import build_model
    from rbdsolve.solvers import solve_question

    model = build_model(loads(CARTS))
    solution = solve_question(model.problem.questions[0], model)
    assert [m.value for m in solution.answers.motions] == ["neutral", "oscillation", "oscillation"]
    m1, m2, m3, k1, k2 = (model.symbols.parameters[n] for n in ("m1", "m2", "m3", "k1", "k2"))
    _, a, b = solution.answers.eigenvalues
    assert sp.simplify(a + b - (k1 * m3 * (m1 + m2) + k2 * m1 * (m2 + m3)) / (m1 * m2 * m3)) == 0
    assert sp.simplify(sp.expand(a * b) - k1 * k2 * (m1 + m2 + m3) / (m1 * m2 * m3)) == 0
