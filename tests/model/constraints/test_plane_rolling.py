"""Contacts on a plane in 3D (model/constraints/plane_rolling.py), checked by what C must be rather
than by the module's formula: on the rim (|C − G| = r, across the axis), on the plane,
and the rim's lowest point (no sampled rim point lies lower); the coin's C is the hand
C = G − r e3 of the seed's problem 3; and the questions that need independent
coordinates refuse the contact, located."""

from __future__ import annotations

import math
import random

import pytest
import sympy as sp

from rbdsolve.errors import InputError
from rbdsolve.model.build import build_model
from rbdsolve.model.state import t
from rbdsolve.problem import load_file, load_text

from conftest import PROBLEMS

# a disk on a table with five coordinates: heading a, lean b, spin c, place (x, y)
DISK = """
parameters: {m: mass, r: radius, g: gravity}
coordinates: [x, y, a, b, c]
gravity: [0, 0, -g]
bodies:
  disk: {shape: disk, mass: m, radius: r, at: [x, y, r*cos(b)], axis: x, orientation: [[z, a], [y, -b], [x, c]]}
contacts:
  C: {body: disk, rolls_on: {plane: {normal: z, through: [0, 0, 0]}}}
questions: [inertia]
"""


def test_the_coin_touches_the_table_where_the_hand_work_says() -> None:
    """The seed's hand work: e3 = (−sin θ cos ψ, −sin θ sin ψ, cos θ), ψ = ω₀ t, from C
    towards G, so C = G − r e3; and the tilt must keep cos θ > 0 (assumed, named)."""
    model = build_model(load_file(PROBLEMS / "steady" / "rolling-coin.yaml"))
    (contact,) = model.plane_contacts
    p = model.symbols.parameters
    theta, r, psi = p["theta"], p["r"], p["omega0"] * t
    e3 = sp.Matrix([-sp.sin(theta) * sp.cos(psi), -sp.sin(theta) * sp.sin(psi), sp.cos(theta)])
    G = model.bodies[0].position
    assert sp.simplify(contact.point - (G - r * e3)) == sp.zeros(3, 1)
    (lowest,) = model.assumptions
    assert sp.simplify(lowest.difference - sp.cos(theta)) == 0 and "contact 'C'" in lowest.implied_by


def test_a_leaning_disk_touches_the_table_at_its_rim_s_lowest_point() -> None:
    model = build_model(load_text(DISK, "disk.yaml"))
    (contact,) = model.plane_contacts
    body = model.bodies[0]
    names = model.symbols
    rng = random.Random(20)
    for _ in range(4):
        at = {q: sp.Float(rng.uniform(-1.2, 1.2)) for q in model.q} | {names.parameters["r"]: sp.Float(0.7)}
        C, G = contact.point.xreplace(at).evalf(), body.position.xreplace(at).evalf()
        axis = (body.rotation * sp.Matrix([1, 0, 0])).xreplace(at).evalf()
        d = C - G
        assert abs(d.norm() - 0.7) < 1e-12 and abs(d.dot(axis)) < 1e-12 and abs(C[2]) < 1e-12
        # any point of the rim, G + r (cos s u + sin s w) with u, w across the axis, is as high or higher
        u = axis.cross(sp.Matrix([0, 0, 1])).normalized()
        w = axis.cross(u)
        heights = [(G + 0.7 * (math.cos(s) * u + math.sin(s) * w))[2] for s in (k * math.pi / 180 for k in range(360))]
        assert min(heights) >= C[2] - 1e-4


def test_a_ball_touches_a_tilted_plane_along_its_normal() -> None:
    """C = G − r n, n the plane's unit normal ([0, 1, 1]/√2 as given: not normalized)."""
    text = """
parameters: {m: mass, r: radius}
coordinates: [x, a]
bodies:
  ball: {shape: sphere, mass: m, radius: r, at: [x, r/sqrt(2), r/sqrt(2)], orientation: [[x, a]]}
contacts:
  C: {body: ball, rolls_on: {plane: {normal: [0, 1, 1], through: [0, 0, 0]}}}
questions: [inertia]
"""
    model = build_model(load_text(text, "ball.yaml"))
    (contact,) = model.plane_contacts
    x = model.symbols.coordinates["x"]
    assert sp.simplify(contact.point - sp.Matrix([x, 0, 0])) == sp.zeros(3, 1)
    assert not model.assumptions


@pytest.mark.parametrize("question", ["eom", "equilibria", "modes", "reactions"])
def test_questions_that_need_independent_coordinates_refuse_a_plane_contact(question: str) -> None:
    with pytest.raises(InputError, match=f"'{question}' cannot take contact 'C' .*not integrable") as caught:
        load_text(DISK.replace("questions: [inertia]", f"questions: [{question}]"), "disk.yaml")
    assert caught.value.location.line == 9 and "(line 8)" in caught.value.message  # at the question, naming C's line


def test_values_that_tip_the_coin_past_the_vertical_are_refused() -> None:
    text = (PROBLEMS / "steady" / "rolling-coin.yaml").read_text(encoding="utf-8")
    with pytest.raises(InputError, match="leans past the plane's normal"):
        build_model(load_text(text.replace("unknowns: [spin]", "values: {theta: 2}\nunknowns: [spin]"), "c.yaml"))
