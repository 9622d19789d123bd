"""Principal moments of tensors of numbers with π in them (a cylinder segment's centroid,
2 r sin³α/(3(α − sin α cos α)), puts α = π/3 in every entry): decided from the entries,
before any cubic is expanded (that took minutes and printed a page). Expected values by
quadrature of the segment's cross-section (scipy), not by rbdsolve."""

from __future__ import annotations

import math

import numpy as np
import pytest
import sympy as sp
from scipy import integrate

import rbdsolve.solvers.inertia.exact as exact
from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.solvers import solve_problem

ALPHA, R, H = math.pi / 3, 1.0, 2.0  # half-angle, radius, length (a = 1, height 2a)


def _segment_about_its_centre() -> tuple[list[float], float]:
    """The principal moments about G of a unit-mass segment (its own axes are principal:
    x ↦ −x and z ↦ −z are symmetries), and the distance ȳ of G from the axis."""
    half_chord = R * math.sin(ALPHA)

    def mean(f) -> float:
        area = integrate.dblquad(lambda y, x: 1.0, -half_chord, half_chord, lambda x: R * math.cos(ALPHA),
                                 lambda x: math.sqrt(R * R - x * x), epsabs=1e-13, epsrel=1e-13)[0]
        return integrate.dblquad(lambda y, x: f(x, y), -half_chord, half_chord, lambda x: R * math.cos(ALPHA),
                                 lambda x: math.sqrt(R * R - x * x), epsabs=1e-13, epsrel=1e-13)[0] / area

    y_bar = mean(lambda x, y: y)
    xx, yy, zz = mean(lambda x, y: x * x), mean(lambda x, y: (y - y_bar) ** 2), H * H / 12
    return sorted([yy + zz, xx + zz, xx + yy]), y_bar


def _solved(about: str, monkeypatch):
    def no_cubic(*args):
        raise AssertionError("the cubic's closed form was tried on numbers with π")

    monkeypatch.setattr(exact, "_closed_form", no_cubic)
    text = ("parameters: {m: mass, a: radius}\nbodies:\n"
            '  body: {shape: cylinder_segment, mass: m, radius: a, height: 2*a, half_angle: pi/3, at: "[a, 0, 0]", '
            'axis: "[1, 1, 0]"}\n'
            f"questions:\n  - inertia: {about}\n")
    (solution,) = solve_problem(build_model(load_text(text, "segment.yaml"))).solutions
    assert solution.solved, solution.error
    return solution


def _number(x) -> float:
    return float(sp.sympify(x).subs({sp.Symbol("m", positive=True): 1, sp.Symbol("a", positive=True): 1}))


def test_about_its_centre_an_axis_decouples_and_the_moments_are_exact(monkeypatch) -> None:
    """Turned about [1, 1, 0], the segment's own z axis lies in the scene's xy-plane and
    e_z is principal: J_zz and the block's a ± |c| (a = b), exact, without a warning."""
    solution = _solved("{body: body}", monkeypatch)
    expected, _ = _segment_about_its_centre()
    moments = solution.answers.principal_moments
    assert not any(isinstance(x, sp.Float) for m in moments for x in sp.preorder_traversal(m)), moments
    assert [_number(x) for x in moments] == pytest.approx(expected, rel=1e-10)
    assert not solution.warnings


def test_about_a_point_off_its_axes_the_moments_are_numbers_with_the_cubic_in_numbers(monkeypatch) -> None:
    """About (a, 0, a), in axes (z, x, y): no axis decouples. The moments are numpy's, the
    cubic det(κ1 − Ĵ) is written in numbers, and a warning says so. Checked against the
    quadrature through the trace (J₁ + J₂ + J₃ = tr J_G + 2 m |G − P|², G at ȳ from the
    body's origin (a, 0, 0)) and against the tensor's own eigenvalues."""
    solution = _solved('{about: "[a, 0, a]", axes: [[0, 0, 1], [1, 0, 0], [0, 1, 0]]}', monkeypatch)
    about_G, y_bar = _segment_about_its_centre()
    answers = solution.answers
    G = np.array([_number(x) for x in answers.centre])
    assert np.linalg.norm(G - [1, 0, 0]) == pytest.approx(y_bar, rel=1e-10)
    moments = [_number(x) for x in answers.principal_moments]
    assert sum(moments) == pytest.approx(sum(about_G) + 2 * np.linalg.norm(G - [1, 0, 1]) ** 2, rel=1e-10)
    J = np.array([[_number(x) for x in row] for row in sp.Matrix(answers.J).tolist()])
    assert moments == pytest.approx(sorted(np.linalg.eigvalsh(J)), rel=1e-12)
    assert any("numeric" in w for w in solution.warnings)
    step = next(s for s in solution.steps if "in numbers" in s.text)
    cubic = sp.Poly(sum(term.value() for term in step.math[1].lhs.items), sp.Symbol("kappa"))
    assert [float(c) for c in cubic.all_coeffs()] == pytest.approx(np.poly(J), rel=1e-12)  # J₀ = m a² = 1
