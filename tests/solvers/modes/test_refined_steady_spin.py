"""Gyroscopic modes about a steady spin whose tilt has no closed form, the tilt typed
with six digits: refined by Newton's method on the steady motion's equations (as
docs/format.md promises), not refused as "not a steady state".

A disk (mass m, radius r) spins at the rate s on a light axle OG of length L, O a ball
joint; a spring (k, natural length L0) ties G to W = (d, 0, h). The axle's direction
e3 = R_x(a) R_y(b) z = (sin b, −sin a cos b, cos a cos b). By hand, with I = m r²/4 +
m L² about O across the axle and C = m r²/2 along it,

    T = ½ I (ȧ² cos²b + ḃ²) + ½ C (φ̇ + ȧ sin b)²,
    V = m g L cos a cos b + ½ k (|L e3 − W| − L0)².

φ is cyclic, p = C (φ̇ + ȧ sin b) = C s in the steady motion with the axle at rest, and
Routh's function R = ½ I (ȧ² cos²b + ḃ²) + p sin b ȧ − V − p²/(2C), so the steady
states are V's equilibria (a = 0, ∂V/∂b = 0: solved below with mpmath), and about one

    M = diag(I cos²b₀, I),   G = [[0, p cos b₀], [−p cos b₀, 0]],   K = ∂²V/∂q∂q,

whose det(λ²M + λG + K) = 0 gives the rates (the new user's trial, check_p5b.py, found
the same: 4.48827 and 32.2153 rad/s about b₀ ≈ 0.50938)."""

from __future__ import annotations

import math

import mpmath
import numpy as np
import sympy as sp

import rbdsolve

SCENE = """\
title: a spinning disk on a ball-jointed axle, its centre tied by a spring to a side point
parameters: {m: mass, r: radius, L: length, k: stiffness, L0: length, d: length, h: length, g: acceleration, s: spin}
values: {m: 2 kg, r: 10 cm, L: 20 cm, k: 400 N/m, L0: 10 cm, d: 15 cm, h: 20 cm, g: 9.81 m/s^2, s: 3000 rev/min}
coordinates: [a, b, phi]
gravity: [0, 0, -g]
triads:
  T: {turns: [[x, a], [y, b], [z, phi]], vectors: [e1, e2, e3]}
points:
  O: [0, 0, 0]
  W: [d, 0, h]
  G: L*e3
bodies:
  disk: {shape: disk, mass: m, radius: r, at: G, orientation: [T]}
springs:
  tie: {stiffness: k, between: [G, W], natural_length: L0}
questions:
  - modes: {about: {a: 0, b: 0.509376, dot(phi): s}}
"""

m, r, L, k, L0, d, h, g = 2, sp.Rational(1, 10), sp.Rational(1, 5), 400, sp.Rational(1, 10), sp.Rational(3, 20), \
    sp.Rational(1, 5), sp.Rational(981, 100)
s = 3000 * 2 * sp.pi / 60


def _by_hand() -> tuple[float, list[float]]:
    """b₀ and the two frequencies, from the module docstring's T, V and R."""
    a_, b_ = sp.symbols("a b", real=True)
    e3 = sp.Matrix([sp.sin(b_), -sp.sin(a_) * sp.cos(b_), sp.cos(a_) * sp.cos(b_)])
    V = m * g * L * e3[2] + k * ((L * e3 - sp.Matrix([d, 0, h])).norm() - L0) ** 2 / 2
    slope = sp.lambdify(b_, sp.diff(V, b_).subs(a_, 0), "mpmath")
    with mpmath.workdps(30):
        b0 = mpmath.findroot(slope, 0.509)
    I, C = m * r**2 / 4 + m * L**2, m * r**2 / 2
    p = float(C * s)
    at = {a_: 0, b_: sp.Float(str(b0), 30)}
    K = np.array(sp.hessian(V, (a_, b_)).subs(at).evalf(20).tolist(), dtype=float)
    M = np.diag([float(I) * math.cos(float(b0)) ** 2, float(I)])
    G = np.array([[0.0, p * math.cos(float(b0))], [-p * math.cos(float(b0)), 0.0]])
    # det(λ²M + λG + K) for 2 × 2 is a quartic in λ: its coefficients by hand
    quartic = [M[0, 0] * M[1, 1], 0.0, M[0, 0] * K[1, 1] + M[1, 1] * K[0, 0] + G[0, 1] ** 2, 0.0,
               K[0, 0] * K[1, 1] - K[0, 1] ** 2]
    roots = np.roots(quartic)
    return float(b0), sorted({round(abs(z.imag), 9) for z in roots})


def test_a_six_digit_tilt_is_refined_to_the_steady_state(tmp_path) -> None:
    path = tmp_path / "disk.yaml"
    path.write_text(SCENE, encoding="utf-8")
    (solution,) = rbdsolve.solve(path, route="numeric", budget=600.0)
    b0, rates = _by_hand()
    assert math.isclose(float(solution.answers.about["b"]), b0, rel_tol=1e-12)
    assert [math.isclose(x, y, rel_tol=1e-9) for x, y in zip(solution.answers.frequencies, rates)] == [True, True]
    assert any("refined by Newton's method" in w for w in solution.warnings)


def test_a_point_far_from_any_steady_state_is_still_refused(tmp_path) -> None:
    """b = 0.7 is 0.19 from the steady tilt, beyond the refinement's reach (1e-3)."""
    path = tmp_path / "disk.yaml"
    path.write_text(SCENE.replace("b: 0.509376", "b: 0.7"), encoding="utf-8")
    (solution,) = rbdsolve.solve(path, route="numeric", budget=600.0)
    assert solution.error is not None and "not a steady state" in solution.error


def test_the_exact_routes_remedy_is_not_quoted_where_the_numeric_route_refined(tmp_path) -> None:
    """On auto the exact route refuses the six-digit tilt ("give it exactly …") and the
    numeric route refines it: the note quoting the exact route's reason leaves that
    remedy out (it read beside the refinement's note as advice to do what was done);
    the exact route alone still gives it, naming the scene's own spin."""
    path = tmp_path / "disk.yaml"
    path.write_text(SCENE, encoding="utf-8")
    (auto,) = rbdsolve.solve(path, budget=600.0)
    (exact,) = rbdsolve.solve(path, route="exact", budget=600.0)
    note = next(w for w in auto.warnings if w.startswith("the exact route could not answer"))
    assert "not a steady state" in note and "Give it exactly" not in note
    assert any("refined by Newton's method" in w for w in auto.warnings)
    assert exact.error is not None and exact.error.endswith("is never exactly steady")
    assert "(dot(phi): EXPRESSION under about:)" in exact.error  # the scene's spin, not a ψ it has none of
