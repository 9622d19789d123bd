"""A steady motion with the rolling written as a contact on a plane (the coin of
problems/steady/rolling-coin.yaml): the same answer as a hand derivation by another
route (Newton's law for the contact force and Euler's law about G, the contact point
worked out by hand), and the same as the point written by hand under 'rolling_at'."""

from __future__ import annotations

import pytest
import sympy as sp
from click.testing import CliRunner

from rbdsolve.cli import main

from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.solvers import solve_problem

from conftest import PROBLEMS

COIN = (PROBLEMS / "steady" / "rolling-coin.yaml").read_text(encoding="utf-8")
m, r, R, g, theta, w0, t = sp.symbols("m r R g theta omega0 t", positive=True)


def _solve(text: str):
    solution = solve_problem(build_model(load_text(text, "coin.yaml"))).solutions[0]
    assert solution.error is None, solution.error
    return solution


@pytest.fixture(scope="module")
def by_contact():
    return _solve(COIN)


def by_hand() -> tuple[sp.Expr, sp.Expr]:
    """(spin, ω₀²) for the coin: C = G − r e3, e3 across the axis e1 towards G; rolling
    v_G + ω × (C − G) = 0 gives the spin; the contact force F = m a_G + m g e_z (Newton)
    and Euler's law about G, dH_G/dt = (C − G) × F, give ω₀² (its e2 component at t = 0)."""
    psi = w0 * t
    e1 = sp.Matrix([sp.cos(theta) * sp.cos(psi), sp.cos(theta) * sp.sin(psi), sp.sin(theta)])
    e2 = sp.Matrix([-sp.sin(psi), sp.cos(psi), 0])
    e3 = e1.cross(e2)
    G = R * sp.Matrix([sp.cos(psi), sp.sin(psi), 0])
    d = -r * e3
    s = sp.Symbol("s")
    omega = w0 * sp.Matrix([0, 0, 1]) + s * e1
    rolling = G.diff(t) + omega.cross(d)
    (found,) = sp.solve([sp.simplify(x) for x in rolling if sp.simplify(x) != 0], [s], dict=True)
    omega = omega.subs(s, found[s])
    H = m * r**2 / 2 * omega.dot(e1) * e1 + m * r**2 / 4 * (omega.dot(e2) * e2 + omega.dot(e3) * e3)
    F = m * G.diff(t, 2) + m * g * sp.Matrix([0, 0, 1])
    balance = (H.diff(t) - d.cross(F)).dot(e2).subs(t, 0)
    square = sp.Symbol("W")
    (value,) = sp.solve(sp.simplify(balance).subs(w0**2, square), square)
    return found[s], value


def test_the_contact_gives_the_hand_spin_and_rate(by_contact) -> None:
    spin_rate, omega_squared = by_hand()
    (value,) = by_contact.answers.solved.values()
    names = {str(x): x for x in value.free_symbols}
    mine = value.xreplace({names[k]: v for k, v in {"g": g, "R": R, "r": r, "theta": theta}.items() if k in names})
    assert sp.simplify(mine - omega_squared) == 0



def test_the_solution_shows_where_c_is_before_the_rolling_condition() -> None:
    """r_C − r_G = −r e₃ in the triad (the seed's e₃ from C towards G), then v_C = 0."""
    result = CliRunner().invoke(main, ["solve", str(PROBLEMS / "steady" / "rolling-coin.yaml")])
    assert result.exit_code == 0, result.output
    where = result.output.index("The contact point C is where the body touches the plane")
    rolling = result.output.index("Rolling without slipping at C")
    assert where < result.output.index("r_C − r_G = −r e₃") < rolling

def test_the_contact_is_the_constraint_rolling_at_states(by_contact) -> None:
    """The scene with C written by hand (C = G − r e3) and named in 'rolling_at'."""
    text = COIN.replace("  G: R * [cos(omega0*t), sin(omega0*t), 0]\n",
                        "  G: R * [cos(omega0*t), sin(omega0*t), 0]\n  C: G - r*e3\n")
    text = text.replace("  C: {body: coin, rolls_on: {plane: {normal: z}}}\n", "").replace(
        "{about: C, solve_for", "{about: C, rolling_at: C, solve_for")
    by_point = _solve(text)
    assert by_point.answers.rates == by_contact.answers.rates
    assert by_point.answers.solved == by_contact.answers.solved
    assert by_point.answers.relations == by_contact.answers.relations


def test_the_seed_ring_written_with_a_contact_gives_the_exam_s_answer() -> None:
    """Seed problem 3 with its hand-worked C = G − r e3 replaced by a contact on the
    table: ω₀² = 2 g sin θ/(cos θ (4R + r sin θ)), the exam's worked solution."""
    ring = (PROBLEMS / "sg2150-2015-10-29" / "p3-rolling-ring.yaml").read_text(encoding="utf-8")
    text = ring.replace("  C: G - r*e3\n", "").replace(
        "questions:\n", "contacts:\n  C: {body: ring, rolls_on: {plane: {normal: z}}}\nquestions:\n").replace(
        "{about: C, rolling_at: C,", "{about: C,")
    assert "rolling_at" not in text and "G - r*e3" not in text
    (value,) = _solve(text).answers.solved.values()
    names = {str(x): x for x in value.free_symbols}
    mine = value.xreplace({names[k]: v for k, v in {"g": g, "R": R, "r": r, "theta": theta}.items()})
    assert sp.simplify(mine - 2 * g * sp.sin(theta) / (sp.cos(theta) * (4 * R + r * sp.sin(theta)))) == 0
