"""solvers/conditions/conditions.py: where values are real."""

from __future__ import annotations

import sympy as sp


# A rod as a conical pendulum (problems/steady/rod-conical-pendulum.yaml): Ω =
# √6 √g/(2 √l √(cos α)) is real and finite only where cos α > 0: at α = π/2 it is
# infinite, so the condition is α < π/2, not α ≤ π/2. Sampled on both sides and at it.
def test_a_root_in_a_denominator_needs_its_radicand_positive() -> None:
    from rbdsolve.solvers.conditions.conditions import divided_radicands

    g, l, a = sp.symbols("g l alpha", positive=True)
    omega = sp.sqrt(6) * sp.sqrt(g) / (2 * sp.sqrt(l) * sp.sqrt(sp.cos(a)))
    assert set(divided_radicands([omega])) == {l, sp.cos(a)}
    assert divided_radicands([sp.sqrt(sp.cos(a))]) == []
    at = {g: sp.Rational(981, 100), l: sp.Rational(3, 5)}
    assert omega.subs(at | {a: sp.pi / 2 - sp.Rational(1, 100)}).evalf().is_real
    assert not omega.subs(at | {a: sp.pi / 2}).is_finite
    assert not omega.subs(at | {a: sp.pi / 2 + sp.Rational(1, 100)}).evalf().is_real
