"""polynomial_roots: every root, or a refusal that names why (never a partial list, never
an exam-unreadable radical)."""

from __future__ import annotations

import pytest
import sympy as sp

from rbdsolve.errors import UnsolvedError
from rbdsolve.solvers.conditions.polynomial import polynomial_roots

x, s, c = sp.symbols("x s c")


def test_a_product_of_linear_factors_is_solved():
    # x³ − x = x (x − 1)(x + 1): reducible, degree 1 factors
    roots = polynomial_roots([x**3 - x], [x], "the equations")
    assert sorted(r[x] for r in roots) == [-1, 0, 1]


def test_a_quadratic_keeps_its_radicals():
    roots = polynomial_roots([x**2 - 2], [x], "the equations")
    assert sorted((r[x] for r in roots), key=float) == [-sp.sqrt(2), sp.sqrt(2)]


@pytest.mark.parametrize("p, degree", [
    (x**3 - 3 * x + 1, 3),  # irreducible over ℚ, three real roots: casus irreducibilis
    (x**4 - 10 * x**2 + 1, 4),  # irreducible (the minimal polynomial of √2 + √3)
])
def test_an_irreducible_cubic_or_quartic_is_refused_with_its_degree(p, degree):
    with pytest.raises(UnsolvedError, match=f"irreducible factor of degree {degree}"):
        polynomial_roots([p], [x], "the equations")


def test_a_trig_system_eliminating_to_a_quartic_is_refused():
    """The rod on a turning arm with values: g l/2 s = Ω²/2 (a l c + 2 l²/3 s c) and
    s² + c² = 1 (l = 3/5, a = 1/5, Ω = 5, g = 981/100) eliminate to a quartic in c with
    no rational root."""
    g, l, a, w = sp.Rational(981, 100), sp.Rational(3, 5), sp.Rational(1, 5), 5
    eq = g * l / 2 * s - sp.Rational(w**2, 2) * (a * l * c + 2 * l**2 / 3 * s * c)
    with pytest.raises(UnsolvedError, match="degree 4"):
        polynomial_roots([eq, s**2 + c**2 - 1], [s, c], "the equilibrium equations")


def test_a_system_that_factors_into_small_pieces_is_still_solved():
    """s (g − l Ω² c) = 0 with s² + c² = 1 (the rod on the axis): the eliminant factors
    into degrees ≤ 2, and every root is listed."""
    eq = s * (3 - 4 * c)
    roots = polynomial_roots([eq, s**2 + c**2 - 1], [s, c], "the equations")
    assert sorted((r[s], r[c]) for r in roots if r[s] == 0) == [(0, -1), (0, 1)]
    assert {r[c] for r in roots if r[s] != 0} == {sp.Rational(3, 4)}


def test_a_root_of_two_in_the_coefficients_does_not_make_a_cubic():
    """A square plate of side a hung by a corner on a shaft turning at Ω: ∂V/∂θ ∝
    s (√2 g − Ω² a c), s² + c² = 1, eliminates to (c² − 1)(Ω² a c − √2 g), which
    factor_list over the rationals left whole ("an irreducible factor of degree 3"). Over
    ℚ(√2) it splits: c = ±1 (s = 0) and c = √2 g/(Ω² a), s = ±√(1 − c²)."""
    g, a, w = sp.symbols("g a Omega", positive=True)
    eq = s * (sp.sqrt(2) * g - w**2 * a * c)
    roots = polynomial_roots([eq, s**2 + c**2 - 1], [s, c], "the equations")
    assert {r[c] for r in roots if r[s] == 0} == {-1, 1}
    off = [r for r in roots if r[s] != 0]
    assert len(off) == 2 and all(sp.simplify(r[c] - sp.sqrt(2) * g / (w**2 * a)) == 0 for r in off)
    assert all(sp.simplify(r[s] ** 2 + r[c] ** 2 - 1) == 0 for r in off)


def test_a_long_linear_polynomial_over_ex_has_its_root_without_simplify(monkeypatch) -> None:
    """a x + b with a, b long over sympy's EX domain (a radical and an atan2 of the
    parameters, as a hoop tied by a cord in a track has): x = −b/a, by hand, and sympy's
    simplify is not run on it (it ran past a minute there); a short one is left to
    sympy's roots (None), whose form the answers keep."""
    import importlib

    from rbdsolve.solvers.conditions.polynomial import plain_linear_root

    from conftest import counted_calls

    R, k, m, g, beta, x = sp.symbols("R k m g beta x", positive=True)
    rho = sp.sqrt(R**2 * k**2 + 2 * R * g * k * m * sp.cos(beta) + g**2 * m**2)
    a = sum((R * k) ** j * rho + (g * m) ** j for j in range(1, 16))
    b = sp.cos(beta - sp.atan2(R * k * sp.sin(beta), g * m + R * k * sp.cos(beta))) * rho * R * k - g * m
    calls = counted_calls(monkeypatch, importlib.import_module("sympy.simplify.simplify"), "simplify")
    polynomial = sp.Poly(a * x + b, x)
    assert polynomial.get_domain().is_EX and sp.count_ops(polynomial.as_expr()) > 200
    root = plain_linear_root(polynomial)
    assert not calls
    assert sp.expand(root * a + b) == 0
    assert plain_linear_root(sp.Poly(rho * x - g, x)) is None  # short: sympy's roots
    assert plain_linear_root(sp.Poly(x**2 - g, x)) is None  # not linear


def test_a_condition_linear_root_with_a_radical_in_it_is_minus_b_over_a_without_simplify(monkeypatch):
    """A cylinder on an incline held by a spring of natural length to a point off its
    line: N ≥ 0 at the release solved for k is linear in k with the spring's length
    √(a² + 2ar sin α − 2ax cos α + b² − …) in both coefficients, 173 operations; sympy's
    roots ran simplify on −b/a for 20 s to minutes, as the hash seed ordered its terms
    (a new user's trial). Past RADICAL_OPS with a radical of a sum: −b/a, by hand."""
    import importlib

    from rbdsolve.solvers.conditions.polynomial import RADICAL_OPS, plain_linear_root, radical_linear_root

    from conftest import counted_calls

    k, m, g, r, l0, a, b, alpha = sp.symbols("k m g r l0 a b alpha", positive=True)
    ell = sp.sqrt(a**2 + 2 * a * r * sp.sin(alpha) + b**2 - 2 * b * r * sp.cos(alpha) + r**2)
    A = (ell - l0) * (b * sp.cos(alpha) - a * sp.sin(alpha) - r) / ell
    B = -g * m * sp.cos(alpha) * ell + l0 * g * m
    polynomial = sp.Poly(sp.expand(A * k * ell + B), k)
    size = sp.count_ops(polynomial.as_expr())
    assert polynomial.get_domain().is_EX and RADICAL_OPS < size <= 200
    calls = counted_calls(monkeypatch, importlib.import_module("sympy.simplify.simplify"), "simplify")
    root = radical_linear_root(polynomial)
    assert not calls
    b, a = polynomial.nth(0), polynomial.nth(1)
    assert root == -b / a  # −b/a as it stands
    assert plain_linear_root(polynomial) is None  # a modes' λ of this length keeps sympy's roots' form


p_, q_ = sp.symbols("p q", positive=True)


@pytest.mark.parametrize("system, symbols, expected", [
    ([x**3 - p_ * x - 1], [x], 3),  # irreducible over ℚ(p): at a rational point too
    ([x**2 - p_], [x], None),  # a quadratic: solved
    ([x**6 - p_], [x], None),  # a binomial: x = p^(1/6), readable, left to sympy
    ([p_ * s - q_ * c, s**2 + c**2 - 1], [s, c], None),  # eliminates to a quadratic in c
    ([x], [x], None),  # no parameter: the basis over ℚ is already quick
])
def test_the_eliminants_degree_is_found_at_a_point(system, symbols, expected):
    from rbdsolve.solvers.conditions.polynomial import _specialized_degree

    assert _specialized_degree(system, symbols) == expected


def test_a_rod_on_a_spring_to_the_side_is_refused_at_once_as_a_sextic(monkeypatch):
    """A rod OA (length 2l, mass m) on a pivot, its end A on a spring of natural length
    L₀ to W = (d, −2l) (a new user's trial, k open): with w the spring's length,
    w² = d² − 4 d l s + 8 l² − 8 l² c, and w ∂V/∂θ = 0 is
    l (−2 c w d k + 2 c L₀ d k + s w g m + 4 s w k l − 4 s L₀ k l) = 0 with s² + c² = 1.
    Its eliminant in w is an irreducible sextic (checked here at a second point): no
    radicals list its roots. sympy's lexicographic basis with the six parameters as
    symbols ran past 2 minutes; the refusal is found at a point."""
    import random

    from rbdsolve.solvers.conditions import polynomial

    m, l, d, L0, k, g = sp.symbols("m l d L0 k g", positive=True)
    w = sp.Symbol("w")
    system = [l * (-2 * c * w * d * k + 2 * c * L0 * d * k + s * w * g * m + 4 * s * w * k * l - 4 * s * L0 * k * l),
              c**2 + s**2 - 1, 8 * c * l**2 + 4 * s * d * l + w**2 - d**2 - 8 * l**2]
    rng = random.Random(2)  # another point than the solver's
    point = {v: sp.Rational(rng.randint(2, 50), rng.randint(2, 50)) for v in (m, l, d, L0, k, g)}
    eliminant = sp.groebner([e.xreplace(point) for e in system], s, c, w, order="lex").exprs[-1]
    assert [sp.degree(f, w) for f, _ in sp.factor_list(eliminant, w)[1]] == [6]
    symbolic = []
    real = polynomial.sp.groebner

    def groebner(polys, *gens, **options):
        symbolic.append(any(set(p.free_symbols) - set(gens) for p in polys))
        return real(polys, *gens, **options)

    monkeypatch.setattr(polynomial.sp, "groebner", groebner)
    with pytest.raises(UnsolvedError, match="irreducible factor of degree 6, whose roots have no closed form"):
        polynomial_roots(system, [s, c, w], "the equilibrium equations")
    # every basis at a point (one per symbol tried last); none with the parameters as symbols
    assert symbolic and not any(symbolic)
