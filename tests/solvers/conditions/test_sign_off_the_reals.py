"""solvers/conditions/conditions.py, ``sign_on``: a piece of a parameter's range where the
value is not real has no sign, said at once from the samples.

A uniform rod of length l with both ends on a smooth bowl of radius R swings about the
bowl's centre: its centre is at d = √(R² − l²/4) below O, J_O = m (l²/12 + d²) and
V = −m g d cos θ, so by hand

    λ = g d/(l²/12 + d²) = 3 g √(4 R² − l²)/(6 R² − l²),

positive for 0 < l < 2R, not real for l > 2R (√ of a negative number), and
6 R² − l² < 0 past l = √6 R. Expected signs from this derivation."""

from __future__ import annotations

import sympy as sp

from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.solvers.conditions import conditions
from rbdsolve.solvers.conditions.conditions import Piece, sign_on

SCENE = """\
title: a rod with both ends in a smooth bowl
parameters: {m: mass, R: length, l: length, g: acceleration}
values: {R: 50 cm, l: 60 cm, g: 9.81}
coordinates: [theta]
gravity: [0, -g]
points:
  G: sqrt(R**2 - l**2/4) * [sin(theta), -cos(theta)]
bodies:
  rod: {shape: rod, mass: m, length: l, at: G, angle: theta}
questions: [modes]
"""


def _setting():
    model = build_model(load_text(SCENE))
    R, l, g = (model.symbols.parameters[n] for n in ("R", "l", "g"))
    lam = 3 * g * sp.sqrt(4 * R**2 - l**2) / (6 * R**2 - l**2)
    return model, R, l, lam


def test_no_sign_where_the_value_is_not_real_and_the_assumptions_are_not_asked(monkeypatch) -> None:
    model, R, l, lam = _setting()

    def asked(value):
        raise AssertionError(f"sympy's assumptions asked for the sign of {value}, which is not real on the piece")

    monkeypatch.setattr(conditions, "symbolic_sign", asked)
    span = (sp.Integer(0), sp.oo)
    assert sign_on(lam, Piece(l, 2 * R, sp.sqrt(6) * R, 0, span), model, {}) is None
    assert sign_on(lam, Piece(l, sp.sqrt(6) * R, None, 0, span), model, {}) is None


def test_real_pieces_keep_their_signs() -> None:
    model, R, l, lam = _setting()
    span = (sp.Integer(0), sp.oo)
    assert sign_on(lam, Piece(l, None, 2 * R, 0, span), model, {}) == 1
    assert sign_on(6 * R**2 - l**2, Piece(l, sp.sqrt(6) * R, None, 0, span), model, {}) == -1
    assert sign_on(6 * R**2 - l**2, Piece(l, None, sp.sqrt(6) * R, 0, span), model, {}) == 1
