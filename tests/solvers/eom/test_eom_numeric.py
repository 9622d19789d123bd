"""The numeric eom route's Lagrange step from L's parts by degree in q̇ equals
d/dt(∂L/∂q̇) − ∂L/∂q taken by sympy on L whole (an independent derivation: the chain
rule written out by hand below), for a Lagrangian with every kind of part: M(q, t),
b(q, t) and L₀(q, t); and one that is not quadratic in q̇ takes the direct way."""

from __future__ import annotations

import sympy as sp

from rbdsolve.model.build import build_model
from rbdsolve.model.state import t
from rbdsolve.problem import load_text
from rbdsolve.solvers.eom.numeric import _lagrange

TWO = """\
coordinates: [x, y]
points:
  P: [x, y]
bodies:
  b: {shape: particle, mass: 1, at: P}
questions: [eom]
"""


def _direct(model, L):
    out = []
    for q, qd in zip(model.q, model.qd):
        p = sp.diff(L, qd)
        dp = sp.diff(p, t) + sum(sp.diff(p, a) * b for a, b in zip(model.q, model.qd)) \
            + sum(sp.diff(p, a) * b for a, b in zip(model.qd, model.qdd))
        out.append(dp - sp.diff(L, q))
    return out


def test_parts_by_degree_match_the_direct_derivative() -> None:
    model = build_model(load_text(TWO))
    (x, y), (xd, yd) = model.q, model.qd
    L = sp.expand(sp.Rational(3, 2) * xd**2 + sp.cos(x - y) * xd * yd + (2 + sp.sin(x) * t) * yd**2 / 2
                  + x * t * xd + sp.cos(y) * yd + 5 * sp.sin(x) * sp.cos(t) + x * y**2)
    for got, want in zip(_lagrange(model, L), _direct(model, L)):
        assert sp.simplify(got - want) == 0


def test_a_lagrangian_not_quadratic_in_the_rates_takes_the_direct_way() -> None:
    model = build_model(load_text(TWO))
    (x, y), (xd, yd) = model.q, model.qd
    L = sp.expand(xd**2 + yd**2 + xd**3 * y / 10 + sp.sin(xd) * x)
    for got, want in zip(_lagrange(model, L), _direct(model, L)):
        assert sp.simplify(got - want) == 0


def test_a_value_with_pi_in_it_goes_in_as_a_float() -> None:
    """A wheel rolling down an incline at α = π/6 (problems/contacts/wheel-on-incline.yaml,
    m = 1, g = 9.81): by hand (3/2) m ẍ − m g sin α = 0, so 1.5 ẍ − 4.905 = 0. The value
    π/6 once stopped the numeric route ('cannot create mpf from pi/6')."""
    import json

    from conftest import PROBLEMS
    from rbdsolve.render.json import report_object
    from rbdsolve.solvers import solve_problem
    from rbdsolve.solvers.routes.options import Options, RouteChoice

    text = (PROBLEMS / "contacts" / "wheel-on-incline.yaml").read_text(encoding="utf-8")
    model = build_model(load_text(text.replace("values: {alpha: 1/2}", "values: {alpha: pi/6, m: 1, g: 9.81, r: 1}"),
                                  "w.yaml"))
    (result,) = json.loads(json.dumps(report_object(solve_problem(model, Options(route=RouteChoice.NUMERIC)))))[
        "results"]
    assert result["ok"], result["error"]
    equation = sp.sympify(result["answers"]["equations"][0], locals={"x": sp.Function("x")})
    terms = {str(k): float(v) for k, v in sp.expand(equation).as_coefficients_dict().items()}
    assert abs(terms["1"] / terms["Derivative(x(t), (t, 2))"] + 4.905 / 1.5) < 1e-12
