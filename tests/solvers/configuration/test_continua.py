"""The numeric equilibria route on a continuum of equilibria: one representative per
family, its free direction named, and modes without ``about`` taken about it.

Hand derivations. Cart (mass M, coordinate x) with a pendulum (mass m, length l,
angle θ from the downward vertical): V = −m g l cos θ does not contain x, so
∂V/∂x ≡ 0 and ∂V/∂θ = m g l sin θ = 0 at θ = 0 and θ = π, for every x: two lines of
equilibria. The Hessian is diag(0, m g l cos θ): at θ = 0 its eigenvalues are 0 and
m g l = 9.81 (neutral along x, stable across); at θ = π, −9.81 and 0 (unstable).
About θ = 0: M = [[M + m, m l], [m l, m l²]] = [[3, 1], [1, 1]], K = diag(0, 9.81);
det(K − λM) = (−3λ)(9.81 − λ) − λ² = 2λ² − 29.43λ, so λ = 0 and λ = 14.715.

Skew: V = ½ k (x − y)², zero on the line x = y: the free direction is (1, 1)/√2, and
the point of the line nearest q = 0 is the origin.
"""

from __future__ import annotations

import math

import pytest

from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.solvers import Options, RouteChoice, solve_problem

from conftest import CART_PENDULUM

CART = "title: cart with pendulum\n" + CART_PENDULUM + """\
questions:
  - equilibria
  - modes
values: {m: 1, M: 2, l: 1, g: 9.81}
"""

SKEW = """\
title: two particles joined by a spring
parameters: {m: mass, k: stiffness}
coordinates: [x, y]
points:
  A: [x, 0]
  B: [y, 1]
  B0: [y, 0]
bodies:
  a: {shape: particle, mass: m, at: A}
  b: {shape: particle, mass: m, at: B}
springs:
  s: {stiffness: k, between: [A, B0]}
questions:
  - equilibria
values: {m: 1, k: 2}
"""


def _numeric(text: str):
    return solve_problem(build_model(load_text(text, "scene.yaml")), Options(route=RouteChoice.NUMERIC))


@pytest.fixture(scope="module")
def cart():
    return _numeric(CART)


def test_a_line_of_equilibria_is_one_representative_with_its_direction(cart) -> None:
    equilibria, _ = cart.solutions
    assert equilibria.error is None
    found = equilibria.answers.equilibria
    assert [(eq.at["x"], round(eq.at["theta"], 12)) for eq in found] == [(0.0, 0.0), (0.0, round(math.pi, 12))]
    assert [eq.stability.value for eq in found] == ["neutral", "unstable"]
    assert all(eq.free == ((1.0, 0.0),) for eq in found)
    assert found[0].curvatures == pytest.approx((0.0, 9.81), abs=1e-12)
    assert found[1].curvatures == pytest.approx((-9.81, 0.0), abs=1e-12)
    assert "every x is an equilibrium (a continuum); shown at x = 0" in equilibria.warnings
    assert equilibria.error_estimate < 1e-12  # across the line, not the singular H along it


def test_modes_without_about_take_the_representative_and_say_so(cart) -> None:
    _, modes = cart.solutions
    assert modes.error is None
    assert modes.answers.about == {"x": 0.0, "theta": 0.0}
    assert modes.answers.eigenvalues == pytest.approx((0.0, 14.715), abs=1e-12)
    (note,) = modes.warnings
    assert note.startswith("every x is an equilibrium (a continuum); shown at x = 0; the modes are taken about it")


def test_a_continuum_along_a_combination_of_coordinates() -> None:
    (equilibria,) = _numeric(SKEW).solutions
    (eq,) = equilibria.answers.equilibria
    assert eq.at["x"] == pytest.approx(0.0, abs=1e-12) and eq.at["y"] == pytest.approx(0.0, abs=1e-12)
    (v,) = eq.free
    assert abs(v[0]) == pytest.approx(1 / math.sqrt(2)) and v[0] == pytest.approx(v[1])
    assert eq.curvatures == pytest.approx((0.0, 4.0), abs=1e-9)  # eigenvalues of k [[1, −1], [−1, 1]]
    assert any("continuum along (x, y)" in w for w in equilibria.warnings)


def test_values_repeat_the_answers_on_the_numeric_route(cart) -> None:
    """Stability and counts are not lost in ``values`` (docs/json.md)."""
    from rbdsolve.render.json import exact

    equilibria, modes = cart.solutions
    assert equilibria.values == exact(equilibria.answers)
    assert equilibria.values["equilibria"][0]["stability"] == "neutral"
    assert equilibria.values["starts"] == 576  # a 24 × 24 grid over x and θ
    assert modes.values["motions"][1] == "oscillation"


def test_the_search_says_how_the_starts_were_placed(cart) -> None:
    equilibria, _ = cart.solutions
    assert "from 576 starts on a 24 × 24 grid" in equilibria.warnings[0]


@pytest.mark.parametrize("n, starts, text", [
    (2, 24 * 24, "starts on a 24 × 24 grid"),
    (12, 2 ** 12, "starts on a " + " × ".join(["2"] * 12) + " grid"),  # 2¹² = 4096: still a grid
    (13, 4096, "starts at fixed pseudo-random points"),  # 2¹³ > 4096
])
def test_the_starts_are_described_as_they_were_placed(n, starts, text) -> None:
    from types import SimpleNamespace

    import sympy as sp

    from rbdsolve.solvers.numeric.numeric_model import _starts

    from rbdsolve.problem.schema import Coordinate, CoordinateKind

    q = sp.symbols(f"q0:{n}")
    coordinates = [Coordinate(str(x), CoordinateKind.LENGTH, None) for x in q]
    class Fake(SimpleNamespace):  # weak references and hashing by identity, as a Model's (memoized)
        __hash__ = object.__hash__

    model = Fake(q=q, angles=set(), values={}, springs=(), contacts=(),
                            problem=SimpleNamespace(coordinates=coordinates, dimensions=(), contacts=()))
    points, how = _starts(model, 24)
    assert len(points) == starts and how.startswith(text)
