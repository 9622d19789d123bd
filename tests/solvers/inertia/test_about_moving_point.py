"""Inertia about a point that moves with the coordinates (issue 40, item 8): in a planar
scene, the moment about the axis through the point normal to the plane, J_G + m |GC|²,
as a function of the coordinates and at a configuration. Expected values by quadrature
of the body's density, done here (scipy), not by the parallel axis theorem."""

from __future__ import annotations

import math

import numpy as np
import pytest
import sympy as sp
from scipy import integrate

from rbdsolve.errors import InputError
from rbdsolve.model.build import build_model
from rbdsolve.problem import load_file, load_text
from rbdsolve.solvers import solve_problem
from rbdsolve.solvers.routes.options import Options, RouteChoice

from conftest import PROBLEMS

HALF_DISK = PROBLEMS / "inertia" / "half-disk-about-contact.yaml"


def _quadrature_about_contact(theta: float) -> float:
    """∫ |r − C|² dm over a half disk (m = R = 1, curved side down) rocking on the floor:
    its centre O = (−θ, 1) (rolled by θ), C = (−θ, 0) straight below, a point of the plate
    at ρ(cos ψ, sin ψ) with π ≤ ψ ≤ 2π in its own axes, turned by θ."""
    c, s = math.cos(theta), math.sin(theta)

    def integrand(rho: float, psi: float) -> float:
        x, y = rho * math.cos(psi), rho * math.sin(psi)
        dx, dy = c * x - s * y, 1 + s * x + c * y  # O − C + R(θ) p
        return (dx * dx + dy * dy) * rho * 2 / math.pi  # density 1/(π/2)

    value, _ = integrate.dblquad(integrand, math.pi, 2 * math.pi, 0, 1, epsabs=1e-12, epsrel=1e-12)
    return value


def _solutions(path=HALF_DISK, route: RouteChoice = RouteChoice.EXACT, **values):
    model = build_model(load_file(path))
    return solve_problem(model.with_values(values), Options(route=route)).solutions


def _number(expr, theta: float = 0.0, m: float = 1.0, R: float = 1.0) -> float:
    """An answer read back as JSON gives it (sympify of its text), at θ and the values."""
    t, names = sp.Symbol("t"), sp.sympify(str(expr))
    at = {sp.Function("theta")(t): theta, sp.Symbol("m"): m, sp.Symbol("R"): R}
    return float(names.subs(at))


def test_the_half_disk_about_its_contact_point_matches_quadrature() -> None:
    """J_C(θ) at several θ, and its value at θ = π/6 (the second question), both routes."""
    first, second = _solutions()
    assert first.error is None and second.error is None
    for value in (0.0, 0.4, -1.1, math.pi / 2):
        assert abs(_number(first.answers.J_axis, value) - _quadrature_about_contact(value)) < 1e-9
    assert abs(_number(second.answers.J_axis) - _quadrature_about_contact(math.pi / 6)) < 1e-9
    numeric = _solutions(route=RouteChoice.NUMERIC, m=1, R=1)[1]
    assert abs(numeric.answers.J_axis - _quadrature_about_contact(math.pi / 6)) < 1e-9


def test_the_principal_axes_in_the_plane_turn_with_the_configuration() -> None:
    """The tensor about C moves with θ: each principal pair (λ, e) found as formulas in θ
    satisfies J e = λ e with |e| = 1 at sampled θ (the angle form of the in-plane pair)."""
    (first, _) = _solutions()
    answers = first.answers
    for value in np.random.default_rng(40).uniform(-1.5, 1.5, 5):
        J = np.array([[_number(x, value, 1.3, 0.7) for x in row] for row in sp.Matrix(answers.J).tolist()])
        for moment, axis in zip(answers.principal_moments, answers.principal_axes):
            e = np.array([_number(x, value, 1.3, 0.7) for x in axis])
            assert abs(np.linalg.norm(e) - 1) < 1e-12
            assert np.allclose(J @ e, _number(moment, value, 1.3, 0.7) * e, atol=1e-12)


def test_a_contact_point_is_a_point_to_take_inertia_about_but_a_misspelt_one_is_not() -> None:
    text = HALF_DISK.read_text().replace("inertia: {about: C}", "inertia: {about: D}")
    with pytest.raises(InputError, match="unknown point 'D'"):
        load_text(text, "p.yaml")


def test_a_fixed_centre_gives_the_moment_about_the_normal_too() -> None:
    """The rod in the bowl about the bowl's centre O: m L²/12 + m (R/2)² = m R²/2 for the
    chord L = √3 R, the same at every θ (the rod turns about O)."""
    text = (PROBLEMS / "inertia" / "rod-in-bowl-at.yaml").read_text()
    text = text.replace("  - inertia: {about: O, at: {theta: 0}}\n", "  - inertia: {about: O}\n")
    model = build_model(load_text(text, "p.yaml"))
    answer = solve_problem(model, Options()).solutions[0].answers
    for value in (0.3, -2.0):
        assert abs(_number(answer.J_axis, value, 1.5, 0.8) - 1.5 * 0.8**2 / 2) < 1e-12
