"""A flat body with its sizes symbolic: its principal moments about a point of its plane
are J_zz and the two roots of its in-plane block's quadratic, though the cubic has no
compact roots (a new user's T of two rods was refused, "no compact closed form here",
and the tensor J_A with it).

By hand, the crossbar (M, from −a to a on x) and the stem (m, from O down to (0, −b))
about the crossbar's end A = (−a, 0, 0), J_ij = ∫ (|r|² δ_ij − r_i r_j) dm:
J_xx = m b²/3, J_yy = 4 M a²/3 + m a², J_zz = J_xx + J_yy, J_xy = −∫ x y dm = a b m/2
(x = a along the stem, ∫ y dm = −m b/2)."""

from __future__ import annotations

import random

import numpy as np
import sympy as sp

import rbdsolve

SCENE = """\
title: a T of two rods about the end of its crossbar
parameters: {M: mass of the crossbar, m: mass of the stem, a: half length of the crossbar, b: length of the stem}
points:
  A: [-a, 0, 0]
bodies:
  tee:
    at: [0, 0, 0]
    parts:
      crossbar: {shape: rod, mass: M, length: 2*a}
      stem: {shape: rod, mass: m, length: b, at: [0, -b/2], axis: y}
questions:
  - inertia: {body: tee, about: A}
"""
M, m, a, b = sp.symbols("M m a b", positive=True)
J_XX, J_YY, J_XY = m * b**2 / 3, 4 * M * a**2 / 3 + m * a**2, a * b * m / 2


def test_a_flat_body_s_principal_moments_come_from_its_plane_s_quadratic(tmp_path) -> None:
    path = tmp_path / "tee.yaml"
    path.write_text(SCENE, encoding="utf-8")
    (solution,) = rbdsolve.solve(path, budget=600.0)
    assert solution.error is None, solution.error
    J = sp.Matrix(solution.answers.J)
    hand = sp.Matrix([[J_XX, J_XY, 0], [J_XY, J_YY, 0], [0, 0, J_XX + J_YY]])
    assert (J - hand).applyfunc(sp.simplify) == sp.zeros(3, 3)
    moments = list(solution.answers.principal_moments)
    # the in-plane pair: their sum and product are the block's trace and determinant, exactly
    plane = [x for x in moments if sp.simplify(x - (J_XX + J_YY)) != 0]
    assert len(plane) == 2
    assert sp.simplify(plane[0] + plane[1] - (J_XX + J_YY)) == 0
    assert sp.simplify(sp.expand(plane[0] * plane[1]) - (J_XX * J_YY - J_XY**2)) == 0
    rng = random.Random(5)
    for _ in range(3):  # ascending, as numpy's eigenvalues of the hand tensor
        point = {s: rng.uniform(0.5, 3.0) for s in (M, m, a, b)}
        expected = np.linalg.eigvalsh(np.array(hand.xreplace(point).tolist(), dtype=float))
        found = sorted(float(x.xreplace(point)) for x in moments)
        assert np.allclose(found, expected, rtol=1e-12)
