"""Lagrange's equations with applied loads, against Newton–Euler written here: a spool of
any round shape pulled at an angle by a string from its axle, a motor between two disks,
and a force that varies in time (both routes agree)."""

from __future__ import annotations

import json

import pytest
import sympy as sp

from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.render.json import report_object
from rbdsolve.solvers import solve_problem

from conftest import PROBLEMS, positive_names

SPOOL = (PROBLEMS / "forces" / "spool-pulled-at-angle.yaml").read_text(encoding="utf-8")


def _results(text: str, route: str | None = None) -> list[dict]:
    from rbdsolve.solvers.routes.options import Options, RouteChoice

    options = Options(route=RouteChoice(route)) if route else Options()
    report = solve_problem(build_model(load_text(text, "p.yaml")), options)
    return json.loads(json.dumps(report_object(report)))["results"]


def _read(text: str):
    return sp.sympify(text, locals=positive_names(text))


def _newton_euler(c: sp.Expr):
    """A round body (J = c m R² about G) rolling on the floor, pulled by F along
    (cos α, sin α) at the point r below the axle's line (the string leaving it from below):
    m ẍ = F cos α − f, J φ̈ = r F − R f (the pull's moment r F, the friction f backwards at
    C = G − R e_y), φ̈ = −ẍ/R. Returns (ẍ, f)."""
    m, R, r, F, alpha = sp.symbols("m R r F alpha", positive=True)
    a, f = sp.symbols("a f")
    J = c * m * R**2
    found = sp.solve([m * a - (F * sp.cos(alpha) - f), J * (-a / R) - (r * F - R * f)], [a, f], dict=True)[0]
    return found[a], found[f]


@pytest.mark.parametrize("shape, c", [("disk", sp.Rational(1, 2)), ("ring", 1), ("sphere", sp.Rational(2, 5)),
                                      ("spherical_shell", sp.Rational(2, 3))])
def test_a_spool_of_any_round_shape(shape: str, c) -> None:
    results = _results(SPOOL.replace("shape: disk", f"shape: {shape}"))
    a, f = _newton_euler(c)
    assert sp.simplify(_read(results[0]["answers"]["accelerations"]["x"]) - a) == 0
    friction = results[1]["answers"]["reactions"]["C"]["components"]["F_C"]  # F_C is counted backwards, along −x
    assert sp.simplify(_read(friction) - f) == 0


def test_the_spool_at_an_angle_in_degrees() -> None:
    """α = 30°, R = 2r: ẍ = 2F (R cos α − r)/(3 m R) = F (√3 − 1)/(3 m) for a disk."""
    text = SPOOL.replace("questions:", "values: {alpha: 30 deg, R: 2, r: 1, F: 3, m: 1}\nquestions:")
    results = _results(text)
    assert results[0]["values"]["accelerations"]["x"] == pytest.approx(float(sp.sqrt(3) - 1), rel=1e-12)


TWO_DISKS = """\
parameters: {m1: mass, m2: mass, r1: radius, r2: radius, Q0: couple}
coordinates: [a, b]
points: {O: [0, 0]}
bodies:
  one: {shape: disk, mass: m1, radius: r1, at: O, angle: a}
  two: {shape: disk, mass: m2, radius: r2, at: O, angle: b}
couples:
  motor: {on: two, by: one, moment: Q0}
questions: [eom]
"""


def test_a_motor_between_two_disks_on_one_axle() -> None:
    """Each disk about the axle: (m1 r1²/2) ä = −Q0, (m2 r2²/2) b̈ = Q0."""
    (result,) = _results(TWO_DISKS)
    found = result["answers"]["accelerations"]
    assert sp.simplify(_read(found["a"]) + 2 * _read("Q0") / (_read("m1") * _read("r1") ** 2)) == 0
    assert sp.simplify(_read(found["b"]) - 2 * _read("Q0") / (_read("m2") * _read("r2") ** 2)) == 0


SHAKEN = """\
parameters: {m: mass, l: length, F0: force, w: rate, g: gravity}
values: {m: 2, l: 3/2, F0: 5, w: 3, g: 9.81}
coordinates: [theta]
gravity: [0, -g]
points: {O: [0, 0]}
bodies:
  rod: {shape: rod, mass: m, length: l, at: "l/2*[sin(theta), -cos(theta)]", angle: theta, axis: y,
        points: {B: [0, -l/2]}}
forces:
  shake: {at: B, force: "[F0*cos(w*t), 0]"}
questions: [eom]
"""


def test_a_force_that_varies_in_time_on_both_routes() -> None:
    """By hand: (m l²/3) θ̈ + (m g l/2) sin θ = F0 cos(w t) l cos θ (the force's moment
    about O, at B = l (sin θ, −cos θ)). The numeric route's equation, divided by its θ̈
    coefficient, has the same coefficients at the values."""
    (exact,) = _results(SHAKEN)
    theta, t = sp.Function("theta")(sp.Symbol("t", real=True)), sp.Symbol("t", real=True)
    m, l, F0, w, g = (sp.Symbol(n, positive=True) for n in ("m", "l", "F0", "w", "g"))
    hand = 3 * (F0 * sp.cos(w * t) * l * sp.cos(theta) - m * g * l * sp.sin(theta) / 2) / (m * l**2)
    names = {**positive_names(exact["answers"]["accelerations"]["theta"]), "theta": sp.Function("theta")}
    got = sp.sympify(exact["answers"]["accelerations"]["theta"], locals=names)
    assert sp.simplify(got.subs(dict(zip(sp.symbols("m l F0 w g", positive=True), (m, l, F0, w, g)))) - hand) == 0
    (numeric,) = _results(SHAKEN, "numeric")
    equation = sp.sympify(numeric["answers"]["equations"][0], locals=names)
    qdd = sp.Derivative(sp.Function("theta")(t), (t, 2))
    scaled = sp.expand(equation / equation.coeff(qdd))
    values = {m: 2, l: sp.Rational(3, 2), F0: 5, w: 3, g: sp.Rational(981, 100)}
    expected = sp.expand(qdd - hand.subs(values))
    for term in sp.Add.make_args(expected):
        coefficient, rest = term.as_coeff_Mul()
        assert float(scaled.coeff(rest)) == pytest.approx(float(coefficient), rel=1e-12)
