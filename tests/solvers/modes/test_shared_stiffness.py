"""The modes about each equilibrium take K = ∂²V/∂q∂q there from the equilibria question
(one per model and root), not a second derivation of it.

A pendulum (a rod of mass m and length l pivoted at one end) held by a torsion spring of
stiffness c at its pivot, upright at θ = 0: by hand V = ½ m g l cos θ + ½ c θ², whose
equilibria include θ = 0 with K = c − ½ m g l, and M = m l²/3 there, so
λ = 3 (2c − m g l)/(2 m l²)."""

from __future__ import annotations

import sympy as sp

import rbdsolve
from rbdsolve.solvers.equilibria import cases

from conftest import counted_calls

SCENE = """\
title: an inverted pendulum on a torsion spring
parameters: {m: mass, l: length, g: acceleration, c: torsional stiffness}
coordinates: [theta]
gravity: [0, -g]
points:
  G: l/2 * [-sin(theta), cos(theta)]
bodies:
  rod: {shape: rod, mass: m, length: l, at: G, angle: theta, axis: y}
springs:
  hinge: {stiffness: c, angle: theta}
questions:
  - equilibria
  - modes: {about: {theta: 0}}
"""


def test_k_is_made_once_for_both_questions(tmp_path, monkeypatch) -> None:
    path = tmp_path / "inverted.yaml"
    path.write_text(SCENE, encoding="utf-8")
    tidied = counted_calls(monkeypatch, cases, "_compact")  # once per entry of each K made
    equilibria, modes = (solution.answers for solution in rbdsolve.solve(path, budget=600.0))
    assert len(tidied) == len(equilibria.equilibria)  # 1 × 1 each, none again for the modes
    (lam,) = modes.eigenvalues
    names = {s.name: s for s in lam.free_symbols}
    m, l, g, c = (names[n] for n in ("m", "l", "g", "c"))
    assert sp.simplify(lam - 3 * (2 * c - m * g * l) / (2 * m * l**2)) == 0
