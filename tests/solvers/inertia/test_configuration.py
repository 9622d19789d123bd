"""Inertia at a configuration (``at``) and about one axis (``axis``: J = eᵀ J_P e),
each checked against a derivation made here directly (an integral along a rod)."""

from __future__ import annotations

import pytest
import sympy as sp

from rbdsolve.errors import InputError
from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.solvers import solve_problem
from rbdsolve.solvers.routes.options import Options, RouteChoice

PENDULUM = """
parameters: {{m: mass, l: length}}
values: {{m: 2, l: 3}}
coordinates: [theta]
points:
  O: [0, 0]
  A: l * [sin(theta), -cos(theta)]
bodies:
  rod: {{shape: rod, mass: m, length: l, at: A/2, angle: theta - pi/2}}
questions:
  - inertia: {{about: O, {options}}}
"""
m, l, s = sp.symbols("m l s")  # as sympify reads the answers back


def _rod_about_end(theta: sp.Expr, e: sp.Matrix) -> sp.Expr:
    """∫₀^l (m/l) |r − (r·e) e|² ds along r = s u: the definition of J_e, not Steiner."""
    u = sp.Matrix([sp.sin(theta), -sp.cos(theta), 0])
    e = e / e.norm()
    r = s * u
    return sp.simplify(sp.integrate(m / l * (r - r.dot(e) * e).dot(r - r.dot(e) * e), (s, 0, l)))


def _solve(options: str, route: RouteChoice = RouteChoice.EXACT):
    model = build_model(load_text(PENDULUM.format(options=options), "p.yaml"))
    result = solve_problem(model, Options(route=route)).solutions[0]
    assert result.solved, result.error
    return result.answers


@pytest.mark.parametrize("theta, axis", [("pi/3", [1, 1, 0]), ("0", [0, 0, 1]), ("pi/4", [1, 2, 2])])
def test_moment_about_an_axis_through_the_hinge(theta: str, axis: list[int]) -> None:
    answers = _solve(f"at: {{theta: {theta}}}, axis: {axis}")
    want = _rod_about_end(sp.sympify(theta), sp.Matrix(axis))
    assert sp.simplify(sp.sympify(str(answers.J_axis)) - want) == 0
    assert answers.at == {"theta": sp.sympify(theta)}


def test_numeric_route_at_a_configuration() -> None:
    answers = _solve("at: {theta: pi/3}, axis: [1, 1, 0]", RouteChoice.NUMERIC)
    want = float(_rod_about_end(sp.pi / 3, sp.Matrix([1, 1, 0])).subs({m: 2, l: 3}))
    assert answers.J_axis == pytest.approx(want, rel=1e-12)


def test_no_coordinates_left_and_axes_defined() -> None:
    """At θ = 0 the tensor is free of θ and its axes defined: no warning about them."""
    model = build_model(load_text(PENDULUM.format(options="at: {theta: 0}"), "p.yaml"))
    result = solve_problem(model, Options(route=RouteChoice.EXACT)).solutions[0]
    assert not any("undefined" in w for w in result.warnings)
    J = sp.Matrix(result.answers.J)
    J = sp.sympify(str(J))
    assert J.free_symbols == {m, l}
    # rod along −y from O: J_O = m l²/3 diag(1, 0, 1)
    assert sp.simplify(J - sp.diag(1, 0, 1) * m * l**2 / 3) == sp.zeros(3, 3)


@pytest.mark.parametrize("options, words", [
    ("at: {thta: 0}", "p.yaml:11:30: questions[0].inertia.at.thta: 'thta' is not a coordinate (did you mean"),
    ("axis: [0, 0, 0]", "questions[0].inertia.axis: an axis direction must not be the zero vector"),
    ("axis: [theta, 0, 0]", "'theta' cannot appear here: an axis must be constant"),
    ("at: [0]", "questions[0].inertia.at: expected 'at': coordinate -> value"),
])
def test_bad_options(options: str, words: str) -> None:
    with pytest.raises(InputError) as caught:
        load_text(PENDULUM.format(options=options), "p.yaml")
    assert words in str(caught.value)


def test_at_needs_coordinates() -> None:
    text = "parameters: {m: mass}\nbodies:\n  b: {shape: sphere, mass: m, radius: 1, at: [0, 0, 0]}\n" \
           "questions:\n  - inertia: {at: {x: 0}}\n"
    with pytest.raises(InputError, match="this scene has none"):
        load_text(text, "s.yaml")


def test_numbers_of_a_moving_tensor_need_a_configuration() -> None:
    """Without 'at' the rod's tensor holds θ: the numeric route says what to give."""
    model = build_model(load_text(PENDULUM.format(options="axis: [1, 0, 0]"), "p.yaml"))
    result = solve_problem(model, Options(route=RouteChoice.NUMERIC)).solutions[0]
    assert not result.solved and "give 'at: {theta: …}' for its numbers" in result.error
