"""The kinematics family against sympy directly, and its bad input (exit 2, located)."""

from __future__ import annotations

import pytest
import sympy as sp
from click.testing import CliRunner

from rbdsolve.cli import main
from rbdsolve.errors import InputError
from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.solvers import solve_problem

from conftest import CART_PENDULUM


def test_cart_pendulum_bob_against_sympy() -> None:
    """The bob of a pendulum on a moving cart, by differentiating P(t) = (x + l sin θ,
    −l cos θ) with sympy's own diff on functions of time, then putting the state in."""
    text = CART_PENDULUM + ("questions:\n  - kinematics: {points: [P], at: {theta: pi/3, dot(x): u, dot(theta): w, "
                            "ddot(x): 0, ddot(theta): 0}}\n")
    text = text.replace("{m: mass, M: cart mass, l: length, g: gravity}",
                        "{m: mass, M: cart mass, l: length, g: gravity, u: speed, w: rate}")
    (solution,) = solve_problem(build_model(load_text(text))).solutions
    t, l, u, w = sp.symbols("t"), *sp.symbols("l u w", positive=True)
    x, th = sp.Function("x")(t), sp.Function("theta")(t)
    P = sp.Matrix([x + l * sp.sin(th), -l * sp.cos(th), 0])
    state = {sp.Derivative(x, (t, 2)): 0, sp.Derivative(th, (t, 2)): 0, sp.Derivative(x, t): u,
             sp.Derivative(th, t): w}
    v, a = P.diff(t), P.diff(t, 2)
    (point,) = solution.answers.points
    for got, want in zip((point.velocity, point.acceleration), (v, a)):
        want = want.subs(state).subs(th, sp.pi / 3)
        names = {str(s): s for s in want.free_symbols}
        for g, e in zip(got, want):
            g = sp.sympify(str(g), locals={"x": sp.Function("x"), "t": t, **names})
            assert sp.simplify(g - e) == 0


@pytest.mark.parametrize("option, message", [
    ("{points: [Q]}", "no point 'Q' (points: C, P, cart, bob)"),  # a body's name is its origin's
    ("{points: [P], at: {psi: 0}}", "'psi' is not a coordinate, nor dot() or ddot() of one"),
    ("{points: [P], at: {theta: x}}", "'x' cannot appear here"),
    ("{distance: [P, P]}", "a distance needs two different points, found 'P' twice"),
    ("{at: {theta: 0}}", "'kinematics' needs 'points: [NAME, …]'"),
    ("{points: [P], speed: 1}", "unknown key 'speed'"),
])
def test_bad_options_are_located(option, message, tmp_path) -> None:
    path = tmp_path / "k.yaml"
    path.write_text(CART_PENDULUM + f"questions:\n  - kinematics: {option}\n")
    result = CliRunner().invoke(main, ["check", str(path)])
    assert result.exit_code == 2 and message in result.output and f"{path}:11:" in result.output, result.output
    with pytest.raises(InputError):
        load_text(path.read_text())


def test_a_state_given_as_bare_numbers_still_gives_si_units(tmp_path) -> None:
    """A state's rates are SI numbers (dot(theta): 2 is 2 rad/s), so a point's velocity
    is in m/s and its acceleration in m/s² (by hand: v = l θ̇ = 0.6 m/s here)."""
    import json

    from click.testing import CliRunner

    from rbdsolve.cli import main

    path = tmp_path / "pendulum.yaml"
    path.write_text(
        "parameters: {m: mass, l: length, g: gravity}\nvalues: {m: 200 g, l: 30 cm, g: 9.81 m/s^2}\n"
        "coordinates: [theta]\ngravity: [0, -g]\npoints:\n  P: l*[sin(theta), -cos(theta)]\n"
        "bodies:\n  bob: {shape: particle, mass: m, at: P}\nquestions:\n"
        "  - kinematics: {points: [P], at: {theta: pi/6, dot(theta): 2, ddot(theta): 0}}\n", encoding="utf-8")
    result = CliRunner().invoke(main, ["solve", str(path), "-f", "json"])
    assert result.exit_code == 0, result.output
    solution = json.loads(result.stdout)["results"][0]
    point = solution["units"]["points"][0]
    assert point["velocity"] == ["m/s"] * 3 and point["acceleration"] == ["m/s²"] * 3 and point["speed"] == "m/s"
    assert abs(solution["values"]["points"][0]["speed"] - 0.6) < 1e-12
