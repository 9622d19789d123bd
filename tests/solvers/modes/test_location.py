"""The numeric modes' bound widened by the equilibrium's own error (solvers/modes/location.py).

By hand (problems/contacts/weighted-disk-in-track.expected.yaml): about
φ₀ = −acos(5/6), λ = 12.115643712574851 (sympy's float of the exact formula). The float
root is a few units in the last place from φ₀ and |∂λ/∂φ| ≈ 84 there, so the pencil's
bound alone (1.2e-14) did not cover the 2.5e-14 the numeric λ is off by."""

from __future__ import annotations

import math

import numpy as np
import sympy as sp

from conftest import PROBLEMS
from rbdsolve.model.build import build_model
from rbdsolve.problem import load_file, load_text
from rbdsolve.solvers import solve_problem
from rbdsolve.solvers.modes.location import location_bounds
from rbdsolve.solvers.numeric.numeric_model import linearized
from rbdsolve.solvers.routes.options import Options, RouteChoice

BY_HAND = 12.115643712574851


def test_the_bound_covers_the_hand_value_about_an_equilibrium_found_in_floats() -> None:
    model = build_model(load_file(PROBLEMS / "contacts" / "weighted-disk-in-track.yaml"))
    modes = solve_problem(model, Options(route=RouteChoice.NUMERIC)).solutions[2]
    (lam,), (bound,) = modes.answers.eigenvalues, modes.answers.absolute_errors
    assert abs(lam - BY_HAND) <= bound
    assert bound < 1e-12  # widened, not made useless


PENDULUM = """
parameters: {m: mass, l: length, g: gravity}
values: {m: 1, l: 2, g: 9.81}
coordinates: [theta]
gravity: [0, -g]
points: {P: "l*[sin(theta), -cos(theta)]"}
bodies: {bob: {shape: particle, mass: m, at: P}}
questions: [modes]
"""


def test_an_equilibrium_exact_in_floats_adds_nothing() -> None:
    """The hanging pendulum at θ = 0: ∂V/∂θ = m g l sin 0 = 0 exactly in 50 digits."""
    model = build_model(load_text(PENDULUM, "p.yaml"))
    about = {"theta": sp.Float(0.0, 17)}
    M, K, _ = linearized(model, about)
    lam = np.linalg.eigvals(np.linalg.solve(M, K)).real
    assert not np.any(location_bounds(model, about, K, lam, lambda at: linearized(model, at)[:2]))


def test_a_point_off_the_equilibrium_is_charged_its_slope() -> None:
    """At θ₀ = 1e-3 (not an equilibrium: ∂V/∂θ = m g l sin θ₀, K = m g l cos θ₀),
    δθ = K⁻¹ ∂V/∂θ = tan θ₀, and λ = (g/l) cos θ moves at the slope −(g/l) sin θ₀:
    the bound grows by 2 (g/l) sin θ₀ tan θ₀ (by hand; the slope's central difference is
    good to ~1e-7 relative at this θ₀)."""
    model = build_model(load_text(PENDULUM, "p.yaml"))
    about = {"theta": sp.Float(1e-3, 17)}
    M, K, _ = linearized(model, about)
    lam = np.array([K[0, 0] / M[0, 0]])
    (widened,) = location_bounds(model, about, K, lam, lambda at: linearized(model, at)[:2])
    by_hand = 2 * 9.81 / 2 * math.sin(1e-3) * math.tan(1e-3)
    assert abs(widened - by_hand) <= 1e-5 * by_hand
