"""Steady motion and steady spin at their edges: what is refused, and what another
body in the scene does not change. Expected values are the seed's (problem 3)."""

from __future__ import annotations

import pytest
import sympy as sp

from rbdsolve.errors import InputError
from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.solvers import solve_problem

from conftest import PROBLEMS

RING = (PROBLEMS / "sg2150-2015-10-29" / "p3-rolling-ring.yaml").read_text(encoding="utf-8")
g, R, r, theta = sp.symbols("g R r theta", positive=True)
SEED = 2 * g * sp.sin(theta) / (sp.cos(theta) * (4 * R + r * sp.sin(theta)))


def solve(text: str):
    return solve_problem(build_model(load_text(text, "scene.yaml"))).solutions[0]


def test_another_body_does_not_change_the_ring_s_balance() -> None:
    text = RING.replace("bodies:\n", "bodies:\n  bob: {shape: particle, mass: m, at: G + r*e2}\n").replace(
        "{about: C, rolling_at: C,", "{about: C, rolling_at: C, body: ring,")
    solution = solve(text)
    assert solution.error is None, solution.error
    (value,) = solution.answers.solved.values()
    assert sp.simplify(value - SEED) == 0


@pytest.mark.parametrize(
    "old, new, words",
    [
        ("{about: C, rolling_at: C,", "{about: G, rolling_at: C,", "take moments about that point"),
        ("gravity: [0, 0, -g]", "gravity: [0, -g, 0]", "not a steady motion"),
        ("{about: C, rolling_at: C,", "{about: C, rolling_at: [C, G],", "rolls at more than one point"),
        ("solve_for: omega0**2}", "solve_for: [omega0, R]}", "do not give omega0, R uniquely"),
    ],
)
def test_what_steady_motion_refuses(old, new, words) -> None:
    solution = solve(RING.replace(old, new))
    assert solution.error is not None and words in solution.error


def test_a_body_given_by_its_velocity_has_no_steady_motion() -> None:
    text = RING.replace("ring: {shape: ring, mass: m, radius: r, at: G, axis: x, orientation: [T, [x, spin*t]]}",
                        "ring: {shape: ring, mass: m, radius: r, velocity: [R*omega0, 0, 0], "
                        "angular_velocity: [0, 0, omega0]}")
    with pytest.raises(InputError, match="needs the position of body 'ring'"):
        load_text(text, "scene.yaml")


def test_steady_spin_needs_three_positive_moments() -> None:
    text = """
parameters: {m: mass, l: length}
bodies:
  rod: {shape: rod, mass: m, length: l, at: [0, 0, 0]}
questions: [steady_spin]
"""
    solution = solve(text)
    assert solution.error is not None and "zero principal moment" in solution.error


CONE = (PROBLEMS / "steady" / "rolling-cone.yaml").read_text(encoding="utf-8")


def test_reactions_let_moments_be_taken_about_any_point() -> None:
    """About G instead of the tip, the same forces (hand derivation in the golden
    file): N = m g wherever the moments are taken."""
    solution = solve(CONE.replace("about: O", "about: K"))
    assert solution.error is None, solution.error
    m, g = sp.symbols("m g", positive=True)
    assert sp.simplify(solution.answers.solved["N"] - m * g) == 0


def test_a_missing_friction_leaves_no_steady_motion() -> None:
    """Without friction nothing turns G on its circle: Newton's law along e1 becomes
    3/4 m Omega² h cos(alpha) = 0, which does not hold (the reactions are then
    complete, N at Q on the line of contact, but frictionless)."""
    text = CONE.replace("        - {at: O, force: F1*e1 + F2*e2}     # friction\n", "")
    solution = solve(text.replace("solve_for: [N, x_N, F1, F2]", "solve_for: [N, x_N]"))
    assert solution.error is not None and "no such steady motion" in solution.error
    assert "missing from 'reactions'" in solution.error


# By hand (the golden file's derivation): N = m g from Newton's law along e3, then the
# moment about O along e2, N x_N = 3/4 m g h cos(alpha) + Omega L_O·e1 (inertia about the tip).
h, alpha, Omega = sp.symbols("h alpha Omega", positive=True)
X_N = (sp.Rational(3, 4) * h * sp.cos(alpha) + Omega**2 * h**2 * (
    sp.Rational(9, 10) * sp.sin(alpha) * sp.cos(alpha) + sp.Rational(3, 20) * sp.tan(alpha) * sp.sin(alpha)**2) / g)


def test_x_N_alone_is_solved_with_the_other_reaction_unknowns() -> None:
    """solve_for [x_N] alone: N (and F1, F2) are solved with it, so x_N holds no N."""
    solution = solve(CONE.replace("solve_for: [N, x_N, F1, F2]", "solve_for: [x_N]"))
    assert solution.error is None, solution.error
    assert list(solution.answers.solved) == ["x_N"]
    value = solution.answers.solved["x_N"]
    assert not {s.name for s in value.free_symbols} & {"N", "F1", "F2", "spin"}
    assert sp.simplify(value - X_N) == 0
    m = sp.Symbol("m", positive=True)
    assert sp.simplify(solution.answers.found_along["N"] - m * g) == 0
    assert sp.simplify(solution.answers.found_along["F1"] + sp.Rational(3, 4) * m * Omega**2 * h * sp.cos(alpha)) == 0


def test_an_answer_that_keeps_an_unknown_is_refused() -> None:
    """A second push at the rim, N2 at B: N + N2 = m g fixes neither, so x_N depends on
    N2 (statically indeterminate) and is not printed."""
    text = CONE.replace("unknowns: [spin, N, x_N, F1, F2]", "unknowns: [spin, N, x_N, F1, F2, N2]").replace(
        "        - {at: O, force: F1*e1 + F2*e2}     # friction\n",
        "        - {at: O, force: F1*e1 + F2*e2}     # friction\n        - {at: B, force: N2*e3}\n")
    solution = solve(text.replace("solve_for: [N, x_N, F1, F2]", "solve_for: [x_N]"))
    assert solution.error is not None and "leave N2 unknown" in solution.error
    assert "x_N is not fixed" in solution.error


def test_an_answer_that_keeps_an_unsolved_rate_is_refused() -> None:
    """Rolling at the tip alone (at rest anyway) leaves the spin open; x_N depends on it."""
    text = CONE.replace("rolling_at: [O, B]", "rolling_at: O")
    solution = solve(text.replace("solve_for: [N, x_N, F1, F2]", "solve_for: [x_N]"))
    assert solution.error is not None and "leave spin unknown" in solution.error


def test_a_rolling_contact_without_a_reaction_is_bad_input() -> None:
    """Friction and push stated at the tip only: the rim's contact B has none (and the
    tip's reaction sits at a known point, so it is no line contact's resultant)."""
    text = CONE.replace("        - {at: Q, force: N*e3}              # the table's push, spread along OB\n", "")
    text = text.replace("{at: O, force: F1*e1 + F2*e2}", "{at: O, force: F1*e1 + F2*e2 + N*e3}")
    with pytest.raises(InputError, match="no reaction at the rolling contact 'B'") as caught:
        solve(text)
    assert caught.value.location.key_path() == "questions[0].steady_motion.reactions"


def test_moments_about_the_contact_do_not_excuse_its_reaction() -> None:
    """About C a force at C has no moment, but Newton's law for G still counts it."""
    text = RING.replace("unknowns: [spin]", "unknowns: [spin, P]").replace(
        "{about: C, rolling_at: C,", "{about: C, rolling_at: C, reactions: [{at: G, force: P*e3}],")
    with pytest.raises(InputError, match="no reaction at the rolling contact 'C'"):
        solve(text)


# --- the numeric route ------------------------------------------------------------------
#
# The ring with values: ω₀² cos θ (4R + r sin θ) = 2 g sin θ (the seed's relation).

VALUES = "values: {m: 1, r: 1/5, R: 1, g: 981/100, theta: 1/2}\n"


def numeric(text: str):
    from rbdsolve.solvers import Options, RouteChoice

    model = build_model(load_text(text, "scene.yaml"))
    return solve_problem(model, Options(route=RouteChoice.NUMERIC)).solutions[0]


def seed_value(**values) -> float:
    names = {"g": g, "R": R, "r": r, "theta": theta}
    return float(SEED.subs({names[k]: sp.Rational(v) for k, v in values.items()}))


def test_numeric_route_solves_for_omega0_without_its_value() -> None:
    solution = numeric(RING + VALUES)
    assert solution.error is None and solution.route.value == "numeric"
    want = seed_value(g="981/100", R=1, r="1/5", theta="1/2")
    assert abs(solution.answers.solved["omega0**2"] - want) <= solution.error_estimate * want
    (one,) = solution.answers.solutions  # omega0 is positive: one root
    assert abs(one.unknowns["omega0"] ** 2 - want) <= 1e-13 * want


def test_numeric_route_reports_both_roots_of_a_real_omega0() -> None:
    text = RING.replace("omega0: angular speed of G about the vertical axis",
                        "omega0: {description: angular speed, positive: false}")
    solution = numeric(text.replace("solve_for: omega0**2", "solve_for: omega0") + VALUES)
    assert solution.error is None, solution.error
    low, high = sorted(solution.answers.solved["omega0"])
    assert low < 0 < high and abs(low + high) <= 1e-12 * high
    first, second = solution.answers.angular_velocity  # ω changes sign with ω₀
    assert all(abs(a + b) <= 1e-12 * max(1.0, abs(a)) for a, b in zip(first, second))


@pytest.mark.parametrize(
    "old, new, words",
    [
        (VALUES, "values: {m: 1, r: 1/5, theta: 1/2}\n",
         "the numeric route needs a value for every parameter the answer depends on except omega0 (solved for); give R, g "),
        ("solve_for: omega0**2", "solve_for: [omega0, R]", "is singular at the solution"),
        ("solve_for: omega0**2", "solve_for: spin", "found no solution of the relations"),
    ],
)
def test_what_the_numeric_route_refuses(old, new, words) -> None:
    text = (RING + VALUES).replace(old, new)
    if "solve_for: spin" in text:
        text = text.replace("theta: 1/2}", "theta: 1/2, omega0: 2}")
    solution = numeric(text)
    assert solution.answers is None and words in solution.error, solution.error
