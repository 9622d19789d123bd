"""An equilibrium equation quadratic in sin φ, whose eliminant in cos φ is an irreducible
quartic (a new user's hoop with a particle rolling inside a cylinder, reduced): the
exact route took the quartic for the answer's degree and refused. A bob at
P = l (φ, −4 cos φ − sin 2φ) in gravity has V = −m g l (4 cos φ + sin 2φ), so by hand

    ∂V/∂φ = 2 m g l (2 sin φ − cos 2φ) = 2 m g l (2 sin²φ + 2 sin φ − 1) = 0
    ⇒ sin φ = (√3 − 1)/2 (the other root, −(1 + √3)/2, is below −1),
    ∂²V/∂φ² = 4 m g l cos φ (1 + 2 sin φ) = 4 √3 m g l cos φ,

cos φ = ±(3/4)^(1/4): φ₁ = asin((√3 − 1)/2) stable, K = 2 √2 3^(3/4) m g l, and
φ₂ = π − φ₁ unstable, K = −2 √2 3^(3/4) m g l. cos⁴φ = 3/4 is the quartic.
"""

from __future__ import annotations

import sympy as sp

import rbdsolve
from rbdsolve.solvers.conditions.polynomial import polynomial_roots
from tests.conftest import BOB_AT_HEIGHT

SCENE = BOB_AT_HEIGHT.replace("{HEIGHT}", "l*(-4*cos(phi) - sin(2*phi))")


def test_the_quadratic_in_the_sine_is_solved_with_the_sine_last() -> None:
    s, c = sp.symbols("s c")
    roots = polynomial_roots([2 * s**2 + 2 * s - 1, s**2 + c**2 - 1], [s, c], "the equations")
    real = [r for r in roots if all(v.is_real for v in r.values())]
    assert {sp.nsimplify(r[s]) for r in real} == {(sp.sqrt(3) - 1) / 2}
    assert sorted(sp.N(r[c] ** 4, 30) for r in real) == [sp.N(sp.Rational(3, 4), 30)] * 2


def test_both_equilibria_with_the_hands_stiffness(tmp_path) -> None:
    path = tmp_path / "bob.yaml"
    path.write_text(SCENE)
    (solution,) = rbdsolve.solve(path, budget=1200.0)  # a budget far from the work
    assert solution.error is None, solution.error
    first, second = solution.answers.equilibria
    phi1 = sp.asin((sp.sqrt(3) - 1) / 2)
    assert abs(sp.N(first.at["phi"] - phi1, 40)) < 1e-35
    assert abs(sp.N(second.at["phi"] - (sp.pi - phi1), 40)) < 1e-35
    assert (first.stability.value, second.stability.value) == ("stable", "unstable")
    names = {s.name: s for s in first.hessian.free_symbols}
    K = 2 * sp.sqrt(2) * 3 ** sp.Rational(3, 4) * names["m"] * names["g"] * names["l"]
    assert sp.simplify(first.hessian[0, 0] - K) == 0 and sp.simplify(second.hessian[0, 0] + K) == 0
