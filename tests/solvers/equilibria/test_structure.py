"""The equilibrium equations read before they are solved (equilibria/structure.py), their
evident roots (equilibria/evident.py), and the route chosen from them (issue 37, item 2;
issue 38, items 5 and 6). Expected roots, Hessians and conditions are derived by hand in
each test; printed conditions are sampled on both sides."""

from __future__ import annotations

import math
import random

import pytest
import sympy as sp

from rbdsolve.model.build import build_model
from rbdsolve.problem import load_file, load_text
from rbdsolve.solvers import Options, RouteChoice, solve_problem
from rbdsolve.solvers.equilibria.evident import evident_roots
from rbdsolve.solvers.equilibria.exact import structure
from rbdsolve.solvers.equilibria.structure import Shape, bezout, shape_of, trig_polynomial

from conftest import PROBLEMS

x, y, t, p = sp.symbols("x y theta phi")
a, b, c = sp.symbols("a b c", positive=True)


@pytest.mark.parametrize("equations, unknowns, angles, shape", [
    ([a * sp.sin(t)], [t], {t}, Shape.POLYNOMIAL),
    ([a * sp.sin(t) * sp.cos(p) + b, sp.sin(p) - c], [t, p], {t, p}, Shape.POLYNOMIAL),
    ([x * (sp.sqrt(x**2 + y**2) - a) / sp.sqrt(x**2 + y**2), y], [x, y], set(), Shape.POLYNOMIAL),  # w = √(x² + y²)
    ([x * sp.cbrt(x**2 + y**2) - a, y], [x, y], set(), Shape.ALGEBRAIC),  # a cube root: no w² = B
    ([sp.sqrt(x**2 + 1) + sp.sqrt(x**2 + 2) + sp.sqrt(x**2 + 3) - a], [x], set(), Shape.ALGEBRAIC),  # past ROOTS
    ([a * t * sp.cos(t) - b * sp.sin(t)], [t], {t}, Shape.TRANSCENDENTAL),  # a slab on a drum
    ([sp.sin(t) - a * sp.sin(b * t)], [t], {t}, Shape.TRANSCENDENTAL),  # a half-disk on a drum
    ([sp.sqrt(a - sp.cos(t)) * sp.sin(t) - b], [t], {t}, Shape.POLYNOMIAL),  # a radical of cos θ: w² = a − c
    ([sp.sqrt(1 - sp.cos(t)) * sp.sin(t) + sp.sqrt(2 + sp.cos(t)) + sp.sqrt(3 + sp.sin(t)) - b], [t], {t},
     Shape.TRANSCENDENTAL),  # three radicals of sines: past ROOTS
])
def test_the_shape_of_the_equations(equations, unknowns, angles, shape) -> None:
    assert shape_of(equations, unknowns, angles)[0] is shape


def test_the_bezout_number_is_taken_per_block_of_coupled_unknowns() -> None:
    # sin θ = 0 and sin φ = 0 apart: two blocks, each (degree 1) × (circle, degree 2) = 2.
    apart = trig_polynomial([sp.sin(t), sp.sin(p)], [t, p], {t, p})
    assert bezout(apart) == 2
    # a sin θ cos φ + b = 0, sin φ cos θ − c = 0: one block, 2 · 2 · 2 · 2 = 16.
    coupled = trig_polynomial([a * sp.sin(t) * sp.cos(p) + b, sp.sin(p) * sp.cos(t) - c], [t, p], {t, p})
    assert bezout(coupled) == 16


def test_evident_roots_make_every_equation_vanish_exactly() -> None:
    """θ cos θ − (a/2) sin θ: 0 only (π gives −π, ±π/2 give ∓a/2). sin(θ/2) (a bob on
    θ/2): 0 and ±2π, where θ/2 is a whole turn of π. Two coupled angles,
    a sin θ cos φ and b sin φ cos θ: where both sines vanish (0, ±π each) and where both
    cosines do (±π/2 each)."""
    model = build_model(load_file(PROBLEMS / "contacts" / "slab-on-drum.yaml"))
    assert evident_roots([t * sp.cos(t) - a * sp.sin(t) / 2], [t], model) == [{t: 0}]
    assert {r[t] for r in evident_roots([sp.sin(t / 2)], [t], model)} == {0, 2 * sp.pi, -2 * sp.pi}
    both = evident_roots([a * sp.sin(t) * sp.cos(p), b * sp.sin(p) * sp.cos(t)], [t, p], model)
    sines = {(u, v) for u in (0, sp.pi, -sp.pi) for v in (0, sp.pi, -sp.pi)}
    cosines = {(u, v) for u in (sp.pi / 2, -sp.pi / 2) for v in (sp.pi / 2, -sp.pi / 2)}
    assert {(r[t], r[p]) for r in both} == sines | cosines
    # undefined there (0/0) is no root: x/|x| at x = 0
    assert evident_roots([x / sp.sqrt(x**2)], [x], model) == []


def _stability_at(case_when: sp.Basic, symbols: dict, hessian, rng: random.Random, inside: bool):
    """Sign of the hand-derived Hessian at random values where the case's condition is
    ``inside`` (True) or not; None where no such values were drawn."""
    for _ in range(400):
        point = {s: sp.Rational(rng.randint(1, 400), 40) for s in symbols.values()}
        if bool(case_when.xreplace(point)) is inside:
            return sp.sign(hessian.xreplace(point))
    return None


@pytest.mark.parametrize("name, hessian", [
    ("slab-on-drum-angle", lambda s: s["g"] * s["m"] * (s["R"] - s["a"] / 2)),
    ("half-disk-on-drum", lambda s: s["g"] * s["m"] * s["r"] * (4 * s["R"] + 4 * s["r"] - 3 * sp.pi * s["r"])
     / (3 * sp.pi * (s["R"] + s["r"]))),
])
def test_the_evident_root_is_answered_fully_and_its_cases_hold_on_both_sides(name, hessian) -> None:
    """θ = 0, with the stability case by case; each case's condition, sampled on both sides,
    agrees with the sign of the Hessian derived by hand (the .expected.yaml gives it)."""
    model = build_model(load_file(PROBLEMS / "contacts" / f"{name}.yaml"))
    assert structure(model).shape is Shape.TRANSCENDENTAL and structure(model).why_partial
    (solution,) = solve_problem(model).solutions
    assert solution.route.value == "exact" and solution.solved, solution.error
    (eq,) = solution.answers.equilibria
    assert eq.at == {"theta": 0} and eq.stability.value == "depends"
    symbols = {str(s): s for s in model.symbols.parameters.values()}
    K = hessian(symbols)
    assert sp.simplify(eq.hessian[0, 0] - K) == 0
    rng = random.Random(5)
    for case in eq.stability_cases:
        want = 1 if case.stability.value == "stable" else -1
        assert _stability_at(case.when, symbols, K, rng, True) == want
        assert _stability_at(case.when, symbols, K, rng, False) == -want
    note = next(w for w in solution.warnings if "evident roots" in w)
    assert "θ = 0" in note and "other equilibria may exist" in note.lower()
    assert "in the span where contact 'C' holds" in note  # where the numeric route looks


def test_with_every_value_the_numeric_route_runs_at_once_over_the_contacts_span() -> None:
    """The slab (a = 1/5, b = 2, R = 1, m = g = 1): ∂V/∂θ ∝ θ cos θ − sin θ/10, whose only
    root in the contact's span |θ| ≤ b/(2R) = 1 is 0 (tan θ = 10 θ needs θ > π/2), stable
    since R > a/2. Auto chooses the numeric route from the structure, and searches the span."""
    text = (PROBLEMS / "contacts" / "slab-on-drum-angle.yaml").read_text(encoding="utf-8")
    text = text.replace("questions:", "values: {m: 1, g: 1, a: 1/5, b: 2, R: 1}\nquestions:")
    (solution,) = solve_problem(build_model(load_text(text, "slab.yaml"))).solutions
    assert solution.route.value == "numeric" and solution.solved, solution.error
    assert [(e.at["theta"], e.stability.value) for e in solution.answers.equilibria] == [(0.0, "stable")]
    assert solution.warnings[0].startswith("the exact route would answer only in part: the equilibrium equations "
                                           "are transcendental")
    assert any("theta in [-1, 1] (the span where contact 'C' holds)" in w or
               "θ in [-1, 1] (the span where contact 'C' holds)" in w for w in solution.warnings)


def test_an_angle_declared_on_a_rolling_body_is_taken_as_not_periodic_with_a_note() -> None:
    """`coordinates: {theta: angle}` on the slab: refused before ('the height holds it
    outside sin and cos'); now the same answers as without the kind, and a note."""
    declared = build_model(load_file(PROBLEMS / "contacts" / "slab-on-drum-angle.yaml"))
    assert declared.angles == frozenset()
    report = solve_problem(declared)
    notes = [s.text for s in report.model.steps if "is declared an angle" in s.text]
    assert notes and "does not repeat (periodic: false)" in notes[0]
    assert [e.at for e in report.solutions[0].answers.equilibria] == [{"theta": 0}]


def test_the_numeric_route_on_reactions_takes_an_angle_in_degrees() -> None:
    """30 deg is π/6 exactly: N = m g cos α = 2 · 9.81 · cos 30°, F = m g sin α/3, ẍ = (2/3) g sin α
    (by hand; forces/incline-30-deg.expected.yaml)."""
    import math

    model = build_model(load_file(PROBLEMS / "forces" / "incline-30-deg.yaml"))
    (solution,) = solve_problem(model, Options(route=RouteChoice.NUMERIC)).solutions
    assert solution.solved, solution.error
    at = solution.answers.at["C"]
    assert at["N_C"] == pytest.approx(2 * 9.81 * math.cos(math.pi / 6), rel=1e-12)
    assert at["F_C"] == pytest.approx(2 * 9.81 * 0.5 / 3, rel=1e-12)


WALL_SPRING = """title: a rod hinged on a wall, a spring from its end to the wall 2a above the hinge
parameters: {m: mass, a: half length, k: stiffness, g: acceleration of gravity}
coordinates: [theta]
gravity: [0, -g]
points:
  B: 2*a*[sin(theta), cos(theta)]
  C: [0, 2*a]
bodies:
  rod: {shape: rod, mass: m, length: 2*a, at: B/2, angle: theta, axis: y}
springs:
  s: {stiffness: k, between: [B, C], natural_length: a}
questions:
  - equilibria: {for: k}
"""


def _wall_spring_roots(k: float, m: float = 2.0, a: float = 0.5, g: float = 9.81) -> list[float]:
    """The zeros of ∂V/∂θ in (−π, π] away from θ = 0 (where the spring has no length), by
    sign changes on a fine grid, refined by bisection: V = m g a cos θ + ½ k (|BC| − a)²,
    |BC| = 2√2 a √(1 − cos θ) (an independent numeric scan, not rbdsolve's)."""
    def dV(t: float) -> float:
        root = math.sqrt(1 - math.cos(t))
        length = 2 * math.sqrt(2) * a * root  # and d|BC|/dθ = √2 a sin θ/√(1 − cos θ)
        return -m * g * a * math.sin(t) + k * (length - a) * math.sqrt(2) * a * math.sin(t) / root
    grid = [-math.pi + 1e-6 + i * (2 * math.pi - 2e-6) / 4000 for i in range(4001)]
    roots = []
    for lo, hi in zip(grid, grid[1:]):
        if abs(lo) < 1e-3 or abs(hi) < 1e-3 or dV(lo) * dV(hi) > 0:
            continue
        for _ in range(60):
            mid = (lo + hi) / 2
            lo, hi = (mid, hi) if dV(lo) * dV(mid) > 0 else (lo, mid)
        roots.append((lo + hi) / 2)
    if abs(dV(math.pi)) < 1e-9:  # at the end of the span: no sign change inside it
        roots.append(math.pi)
    return roots


def test_a_square_root_of_the_cosine_is_an_unknown_of_the_polynomial_form() -> None:
    """|BC|² = 4 a² (sin² θ + (cos θ − 1)²) = 8 a² (1 − cos θ) = 16 a² sin²(θ/2), so V = m g a
    cos θ + ½ k a² (4 sin(θ/2) − 1)² and ∂V/∂θ = 2 a cos(θ/2) (k a (4 sin(θ/2) − 1) − m g
    sin(θ/2)) (newuser20): θ = π, and sin(θ/2) = k a/(4 k a − m g), which is ≤ 1 and > 0
    only where k ≥ k_c = m g/(3 a): cos θ₀ = 1 − 2 sin²(θ₀/2) = (14 a² k² − 8 a g k m + g² m²)/
    (4 a k − g m)², V'' there a (3 a k − g m)(5 a k − g m)/(4 a k − g m) > 0. The exact
    route listed only θ = π ("transcendental"); each listed equilibrium that exists at a
    sampled k is a root of the numeric scan, and every root of the scan is listed."""
    model = build_model(load_text(WALL_SPRING, "wall.yaml"))
    (solution,) = solve_problem(model).solutions
    assert solution.solved and not solution.warnings, solution.warnings
    a_, g_, k_, m_ = (model.symbols.parameters[n] for n in "agkm")
    equilibria = solution.answers.equilibria
    assert len(equilibria) == 3
    pair = [e for e in equilibria if e.at["theta"] != sp.pi]
    cos0 = (14 * a_**2 * k_**2 - 8 * a_ * g_ * k_ * m_ + g_**2 * m_**2) / (4 * a_ * k_ - g_ * m_) ** 2
    assert all(sp.simplify(sp.cos(e.at["theta"]) - cos0) == 0 for e in pair)
    want_K = a_ * (3 * a_ * k_ - g_ * m_) * (5 * a_ * k_ - g_ * m_) / (4 * a_ * k_ - g_ * m_)
    assert all(sp.simplify(e.hessian[0] - want_K) == 0 and e.stability.value == "stable" for e in pair)
    values = {m_: 2, a_: sp.Rational(1, 2), g_: sp.Rational(981, 100)}
    for k in (5.0, 10.0, 12.5, 13.5, 20.0, 60.0):  # k_c = 13.08 at these values
        at = {**values, k_: sp.Float(k)}
        listed = sorted(float(sp.N(e.at["theta"].xreplace(at))) for e in equilibria
                        if bool(e.exists_when.xreplace(at)))
        scanned = sorted(_wall_spring_roots(k))
        assert len(listed) == len(scanned) and all(abs(x - y) < 1e-6 for x, y in zip(listed, scanned)), (k, listed, scanned)
