"""Plain 'modes' takes the first stable equilibrium, or says why there is none. An
inverted pendulum, a bob of mass m on a light rod l above its hinge, held up by a
torsion spring c: by hand V = ½ c θ² + m g l cos θ, so at θ = 0, K = c − m g l and
M = m l²: stable only where c > m g l, and then λ = (c − m g l)/(m l²)."""

from __future__ import annotations

import math

import pytest

import rbdsolve

SCENE = """\
title: an inverted pendulum held up by a torsion spring
parameters: {{m: mass, l: length, g: acceleration, c: torsional stiffness}}
values: {{m: 1 kg, l: 50 cm, g: 9.81 m/s^2{more}}}
coordinates: [theta]
gravity: [0, -g]
points:
  P: l * [sin(theta), cos(theta)]
bodies:
  bob: {{shape: particle, mass: m, at: P}}
springs:
  hinge: {{stiffness: c, angle: theta}}
questions:
  - modes
"""


def _solved(tmp_path, more: str = ""):
    path = tmp_path / "inverted.yaml"
    path.write_text(SCENE.format(more=more))
    return rbdsolve.solve(path, budget=600.0)[0]  # a budget far from the work


def test_a_stability_that_depends_on_an_open_parameter_is_named(tmp_path):
    answer = _solved(tmp_path)
    assert answer.answers is None
    assert "the stability of equilibrium 1 depends on c" in answer.error
    assert "give a value for c" in answer.error and "{equilibrium: 1}" in answer.error


@pytest.mark.parametrize("c", [6.0, 10.0])
def test_with_the_stiffness_given_past_m_g_l_the_upright_position_is_taken(tmp_path, c):
    answer = _solved(tmp_path, f", c: {c} N*m/rad")
    modes = answer.answers
    assert modes.about == {"theta": 0}
    (lam,) = modes.eigenvalues  # in the symbols, the values put in here
    table = {"m": 1.0, "l": 0.5, "g": 9.81, "c": c}
    got = float(lam.xreplace({s: table[s.name] for s in lam.free_symbols}))
    assert math.isclose(got, (c - 1.0 * 9.81 * 0.5) / (1.0 * 0.5 ** 2), rel_tol=1e-12)
