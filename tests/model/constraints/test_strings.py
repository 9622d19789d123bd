"""A body hanging on a string from a drum over a pulley, checked by the string's
definition rather than by model/constraints/strings.py's formulas: the block goes down exactly as
fast as the drum's material point at C moves along the string towards the pulley
(v_block·h = v_C·d, the straight part inextensible, the pulley light), at random
configurations and rates; and by hand, for a cylinder rolling on a table with the
string off its top, the block goes down at twice the centre's speed."""

from __future__ import annotations

import random

import sympy as sp

from rbdsolve.model.build import build_model
from rbdsolve.problem import load_file, load_text

from conftest import PROBLEMS


def test_the_block_moves_with_the_string_off_the_drum() -> None:
    model = build_model(load_file(PROBLEMS / "contacts" / "cylinder-pulley-block.yaml"))
    state = model.state
    string = next(c for c in model.contacts if c.source.pulley is not None)
    drum = next(b for b in model.bodies if b.name == "cylinder")
    block = next(b for b in model.bodies if b.name == "block")
    centre = model.symbols.vector(next(b for b in model.problem.bodies if b.name == "cylinder").at)
    v_C = state.d_dt(centre) + drum.angular_velocity(state).cross(string.point - centre)  # rigid body
    v_block = state.d_dt(block.position)
    d, h = sp.Matrix([1, 0, 0]), sp.Matrix([0, -1, 0])
    rng = random.Random(7)
    for _ in range(4):
        at = {q: sp.Rational(rng.randint(-900, 900), 1000) for q in state.q}
        at |= {qd: sp.Rational(rng.randint(-900, 900), 1000) for qd in state.qd}
        at |= {p: sp.Rational(rng.randint(1100, 2900), 1000) for p in model.symbols.parameters.values()}
        assert sp.simplify((v_block.dot(h) - v_C.dot(d)).xreplace(at)) == 0
        assert sp.simplify((v_block.dot(h) - 2 * state.qd[0]).xreplace(at)) == 0  # by hand: twice the centre's
        assert sp.simplify(v_block.dot(sp.Matrix([1, 0, 0])).xreplace(at)) == 0  # it hangs straight down


def test_a_block_on_a_fixed_drum_turning_on_its_axle() -> None:
    """A drum of radius R turning on a fixed axle (angle φ, counterclockwise), the string
    off its right side straight down (no pulley in the way: 'over' a point on that line):
    by hand the block goes down at −R φ̇ (counterclockwise winds it up), T = ½ (M R²/2 +
    m R²) φ̇², so (M/2 + m) R² φ̈ = −m g R."""
    text = """
parameters: {M: mass, m: mass, R: radius, g: gravity}
coordinates: [phi]
gravity: [0, -g]
points: {P: [R, -2*R]}
bodies:
  drum: {shape: disk, mass: M, radius: R, at: [0, 0], angle: phi}
  block: {shape: particle, mass: m}
contacts:
  S: {body: block, hangs_from: {drum: drum, direction: [0, -1], over: P, length: R}}
questions: [eom]
"""
    model = build_model(load_text(text))
    block = next(b for b in model.bodies if b.name == "block")
    (phi,) = model.q
    R = model.symbols.parameters["R"]
    # R below P at the reference (a length of 0 is refused: issue 39), then up by R φ
    assert sp.simplify(block.position - sp.Matrix([R, -3 * R + R * phi, 0])) == sp.zeros(3, 1)
