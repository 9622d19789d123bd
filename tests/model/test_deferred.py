"""model/deferred.py: points, positions and periodic angles made on first read."""

from __future__ import annotations

from dataclasses import dataclass

import pytest
import sympy as sp

from rbdsolve.model.build import build_model
from rbdsolve.errors import Location
from rbdsolve.model.deferred import Deferred, Later, Points
from rbdsolve.model.symbols import plainly_real
from rbdsolve.problem import load_text
from rbdsolve.problem.expr import Scope, parse
from rbdsolve.solvers import Options, RouteChoice, solve_problem

CHAIN = """\
title: three rods
parameters: {m: mass, l: length, g: acceleration}
values: {m: 1, l: 1, g: 981/100}
coordinates: [a, b, c]
gravity: [0, -g]
points:
  P0: [0, 0]
  P1: P0 + l * [sin(a), -cos(a)]
  G1: P0 + l/2 * [sin(a), -cos(a)]
  P2: P1 + l * [sin(b), -cos(b)]
  G2: P1 + l/2 * [sin(b), -cos(b)]
  G3: P2 + l/2 * [sin(c), -cos(c)]
bodies:
  rod1: {shape: rod, mass: m, length: l, at: G1, angle: a, axis: y}
  rod2: {shape: rod, mass: m, length: l, at: G2, angle: b, axis: y}
  rod3: {shape: rod, mass: m, length: l, at: G3, angle: c, axis: y}
questions:
  - modes: {about: {a: 0, b: 0, c: 0}}
"""


@dataclass(frozen=True)
class Box:
    value: int = Deferred()


def test_a_deferred_field_is_made_once_on_first_read() -> None:
    calls = []
    box = Box(Later(lambda: calls.append(1) or 7))
    assert not Deferred.made(box, "value") and calls == []
    assert box.value == 7 and box.value == 7
    assert calls == [1] and Deferred.made(box, "value")
    assert Box(3).value == 3 and Deferred.made(Box(3), "value")


def test_a_deferred_field_is_required() -> None:
    with pytest.raises(TypeError):
        Box()  # type: ignore[call-arg]


def test_points_fold_on_read_with_the_points_before_them() -> None:
    folded = []
    points = Points(("A", "B", "C"), lambda name: folded.append(name) or name.lower())
    assert "B" in points and "D" not in points and list(points) == ["A", "B", "C"] and len(points) == 3
    assert folded == []  # neither ``in`` nor iteration folds
    assert points["B"] == "b" and folded == ["A", "B"]
    assert points["C"] == "c" and folded == ["A", "B", "C"]
    with pytest.raises(KeyError):
        points["D"]


def test_a_chain_read_gives_the_sums_written_out() -> None:
    # By hand: G3 = l (sin a + sin b + ½ sin c, −cos a − cos b − ½ cos c).
    model = build_model(load_text(CHAIN, "chain.yaml"))
    a, b, c = model.q
    l = model.symbols.parameters["l"]
    expected = sp.Matrix([l * (sp.sin(a) + sp.sin(b) + sp.sin(c) / 2), -l * (sp.cos(a) + sp.cos(b) + sp.cos(c) / 2), 0])
    assert sp.expand(model.bodies[2].position - expected) == sp.zeros(3, 1)
    assert model.angles == frozenset(model.q)  # each enters only through sin and cos


def test_the_numeric_route_makes_no_position() -> None:
    model = build_model(load_text(CHAIN, "chain.yaml"))
    solution = solve_problem(model, Options(route=RouteChoice("numeric"))).solutions[0]
    assert solution.error is None
    assert not any(Deferred.made(b, "position") for b in model.bodies)
    assert not Deferred.made(model, "angles")


@pytest.mark.parametrize("text, plain", [
    ("P + l/2 * [sin(a), -cos(a)]", True), ("[l**2, a*l - 3, pi]", True), ("inner(P, P) * [1, 0]", True),
    ("[1/l, 0]", False),  # l may be zero for all this test knows: the fold is asked
    ("[sqrt(l), 0]", False), ("[l**(1/2), 0]", False), ("[l**-1, 0]", False), ("[log(l), 0]", False),
])
def test_plainly_real_trees_need_no_fold(text: str, plain: bool) -> None:
    # By hand: sums, products, sin and cos of real names are real; division by a name,
    # roots, negative powers and logarithms may leave the reals.
    scope = Scope(scalars=frozenset({"l", "a"}), vectors=frozenset({"P"}))
    expr = parse(text, Location("t.yaml", 1, 1), scope)
    assert plainly_real(expr.tree) is plain
