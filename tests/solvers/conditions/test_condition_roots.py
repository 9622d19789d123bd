"""solvers/conditions/condition_roots.py: the roots of a quantity in a parameter come out
the same whatever the hash seed of the run.

The roots of the numerator and of the denominator are gathered in a set; they were
once walked in its iteration order, which decided which of two forms of one value came
first: for (c − a − b)/(c − √(a² + 2ab + b²)), PYTHONHASHSEED 0 listed a + b first and
2 listed the square root first."""

from __future__ import annotations

import math
import os
import subprocess
import sys

import numpy as np
import pytest
import sympy as sp

from rbdsolve.solvers.conditions.condition_roots import (_in_sine_or_cosine, _roots_in, _squared_once,
                                                          _under_two_radicals, radical_roots, vanishes_at)

from conftest import counted_calls

SCENE = """
parameters: {m: mass, a: length, b: length, c: length}
coordinates: [x]
points: {P: [x, 0]}
bodies: {bob: {shape: particle, mass: m, at: P}}
questions: [eom]
"""

ROOTS = """
import sympy as sp
from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.solvers.conditions.condition_roots import parameter_roots
model = build_model(load_text('''SCENE'''))
a, b, c = (model.symbols.parameters[n] for n in "abc")
print(parameter_roots((c - a - b) / (c - sp.sqrt(a**2 + 2*a*b + b**2)), c, {}, model))
""".replace("SCENE", SCENE)


def _roots_with_seed(seed: int) -> str:
    env = {**os.environ, "PYTHONHASHSEED": str(seed)}
    return subprocess.run([sys.executable, "-c", ROOTS], env=env, capture_output=True, text=True,
                          check=True).stdout


def test_the_roots_are_the_same_whatever_the_hash_seed() -> None:
    first = _roots_with_seed(0)
    assert "a + b" in first
    assert first == _roots_with_seed(2)


QUARTIC = ROOTS.replace(
    "print(parameter_roots((c - a - b) / (c - sp.sqrt(a**2 + 2*a*b + b**2)), c, {}, model))",
    "print(parameter_roots(c**4 - a*c**3 - b**2*c + a*b**2 + a**4, c, {}, model))\n"
    "print(parameter_roots((c**2 - a**2)*(c - 2*a), c, {}, model))\n"
    "print(parameter_roots(a**2 - 3*a*b*c**2 + b**2*c**4, c, {}, model))")


def test_a_factor_of_degree_three_or_more_is_left_undecided_at_once() -> None:
    """A quartic in c with no factor of lower degree (at a = b = 1 it is c⁴ − c³ − c + 2,
    which has no rational root: ±1 and ±2 give 1, 5, 8, 28; sympy's factor_list finds no
    factor of it either, checked here): no root is given (None: no condition printed),
    where sympy's solve would write Ferrari's formula; a cubic that splits,
    (c² − a²)(c − 2a), gives its roots inside c > 0, a and 2a; a quadratic in c²,
    a² − 3ab c² + b² c⁴, gives c² = a (3 ∓ √5)/(2b) (the formula in c², by hand), the
    two positive roots √(a (3 − √5)/(2b)) < √(a (3 + √5)/(2b))."""
    a, b, c = sp.symbols("a b c", positive=True)
    assert len(sp.factor_list(c**4 - a * c**3 - b**2 * c + a * b**2 + a**4)[1]) == 1
    first, second, third = subprocess.run([sys.executable, "-c", QUARTIC], capture_output=True, text=True,
                                          check=True).stdout.splitlines()
    assert first == "None"
    assert second == "[a, 2*a]"
    roots = [sp.sympify(x, locals={"a": a, "b": b}) for x in third.strip("[]").split(", ")]
    by_hand = [sp.sqrt(a * (3 - sp.sqrt(5)) / (2 * b)), sp.sqrt(a * (3 + sp.sqrt(5)) / (2 * b))]
    assert len(roots) == 2 and all(sp.simplify(x - y) == 0 for x, y in zip(roots, by_hand))


def test_a_root_that_is_no_number_at_the_samples_leaves_the_parameter_undecided(monkeypatch) -> None:
    """sympy's solve gave a half-cylinder on an incline a root only under a condition of
    its own, Piecewise((…, cond), (nan, True)), and a root with a name the samples do not
    set is no number either: each leaves the parameter undecided (None: no condition
    printed), where both once stopped the run with an internal error (exit 3)."""
    from rbdsolve.model.build import build_model
    from rbdsolve.problem import load_text
    from rbdsolve.solvers.conditions import condition_roots

    model = build_model(load_text(SCENE))
    a, c = model.symbols.parameters["a"], model.symbols.parameters["c"]
    conditional = sp.Piecewise((a, sp.sinh(sp.I * a) > 0), (sp.nan, True))
    stray = a + sp.Symbol("z")
    for root in (conditional, stray):
        monkeypatch.setattr(condition_roots, "_roots_in", lambda factor, p, root=root: [root])
        assert condition_roots.parameter_roots(c - a, c, {}, model) is None


def test_a_factor_with_the_parameter_inside_an_absolute_value_is_not_solved(monkeypatch) -> None:
    """12 π sin α |sin α| − 4 √(16 − 9 π² sin² α) cos α − 9 π (a half-cylinder rocking on
    an incline): sympy's solve split the |…| into cases for 20 s, for a root valid only
    under a condition of its own; decided from the structure, at once: undecided."""
    from rbdsolve.model.build import build_model
    from rbdsolve.problem import load_text
    from rbdsolve.solvers.conditions import condition_roots

    def never(factor, p):
        raise AssertionError(f"solved {factor} for {p}")

    monkeypatch.setattr(condition_roots, "_roots_in", never)
    model = build_model(load_text(SCENE))
    c = model.symbols.parameters["c"]
    f = 12 * sp.pi * sp.sin(c) * sp.Abs(sp.sin(c)) - 4 * sp.sqrt(16 - 9 * sp.pi**2 * sp.sin(c)**2) * sp.cos(c) \
        - 9 * sp.pi
    assert condition_roots.parameter_roots(f, c, {}, model) is None


def test_a_radical_whose_square_is_a_quartic_is_left_undecided_without_solve(monkeypatch) -> None:
    """A plate pendulum on a spring of natural length L₀ from a point at height h above
    the pivot, its stiffness at the hanging position ∝ 2 L₀ h k + (g m − 2 h k) √X with
    X = 2a² + 2√2 a h + h²: squared, (2 L₀ h k)² − (g m − 2 h k)² X is a quartic in h
    (degree 2 from each factor, by hand), whose roots need Ferrari's formula, the
    radical's as the square's. Undecided (None), and sympy's solve, which took minutes
    on it, is never called."""
    from rbdsolve.model.build import build_model
    from rbdsolve.problem import load_text
    from rbdsolve.solvers.conditions import condition_roots

    def never(*args, **kwargs):
        raise AssertionError(f"sympy's solve called on {args}")

    model = build_model(load_text(SCENE.replace("{m: mass, a: length, b: length, c: length}",
                                                "{m: mass, a: length, b: length, c: length, g: gravity, "
                                                "k: stiffness, h: length}")))
    m, a, b, g, k, h = (model.symbols.parameters[n] for n in "mabgkh")
    X = 2 * a**2 + 2 * sp.sqrt(2) * a * h + h**2
    f = sp.sqrt(2) * a * (2 * b * h * k + g * m * sp.sqrt(X) - 2 * h * k * sp.sqrt(X))
    assert sp.degree(_squared_once(f, h), h) == 4
    monkeypatch.setattr(condition_roots.sp, "solve", never)
    assert condition_roots.parameter_roots(f, h, {}, model) is None


def _scanned_roots(f, low: float = -math.pi, high: float = math.pi) -> list[float]:
    """The roots of f(θ) on (low, high], by its sign changes on a fine grid and brentq:
    the independent count for the trigonometric cases below."""
    from scipy.optimize import brentq

    grid = np.linspace(low, high, 20001)
    values = np.array([f(x) for x in grid])
    found = [float(brentq(f, a, b, xtol=1e-14)) for a, b, u, v in zip(grid, grid[1:], values, values[1:]) if u * v < 0]
    found += [float(x) for x, v in zip(grid, values) if v == 0]
    return sorted(found)


def _in_the_turn(roots) -> list[float]:
    """Each root's value as a real number in (−π, π] (complex ones dropped)."""
    out = []
    for r in roots:
        z = complex(sp.N(r, 30))
        if abs(z.imag) < 1e-12:
            out.append(math.remainder(z.real, 2 * math.pi))
    return sorted(set(round(x, 12) for x in out))


@pytest.mark.parametrize("text", [
    "9*pi**2*sin(b)**2 - 16",                  # sin alone: asin s and π − asin s (a half-disk on an incline)
    "3*sin(b)**2 + 2*cos(b) - 2",              # cos with sin²: c = 1, −1/3
    "(3072*pi**2 - 5184)*sin(b)**2 + (6480 - 3840*pi**2)*cos(b) - 6000*pi**2 + 7209 + 1024*pi**4",  # no real root
    "4*cos(b)**2 - 1",
])
def test_a_polynomial_in_sine_or_cosine_has_the_roots_a_scan_finds(text: str) -> None:
    """Solved by the formula in s = sin θ or c = cos θ (sympy's solve took 1.2 s on the
    third, a release angle's condition, to find no root): the same real roots as a scan
    of the function's sign changes."""
    b = sp.Symbol("b")
    expr = sp.sympify(text, locals={"b": b})
    f = sp.lambdify(b, expr, "math")
    assert _in_sine_or_cosine(expr, b) is not None
    assert _in_the_turn(_roots_in(expr, b)) == pytest.approx(_scanned_roots(f), abs=1e-9)


@pytest.mark.parametrize("text", ["sin(b) + cos(b) - 1", "cos(2*b) - sin(b)", "b*cos(b) - 1"])
def test_an_odd_sine_beside_a_cosine_or_another_angle_is_left_to_solve(text: str) -> None:
    b = sp.Symbol("b")
    assert _in_sine_or_cosine(sp.sympify(text, locals={"b": b}), b) is None


def test_a_cosine_with_parameters_has_the_exam_form() -> None:
    """g cos θ − h: θ = ±acos(h/g), the form solve wrote."""
    b, g, h = sp.symbols("b g h", positive=True)
    assert set(_roots_in(g * sp.cos(b) - h, b)) == {sp.acos(h / g), -sp.acos(h / g)}


@pytest.mark.parametrize("h, L0, k, m, has_false_root", [
    ("1/2", "3/5", "200", "1", False), ("1", "2", "10", "1", False), ("1", "1/2", "10", "3", True)])
def test_one_radical_is_squared_away_and_its_other_sign_dropped(h, L0, k, m, has_false_root) -> None:
    """A rod hinged at O, a spring of natural length L₀ from its end to h above O,
    released at 60°: θ̇² at the bottom ∝ 12 L₀ k (h + l) − 12 L₀ k √(h² + h l + l²) +
    3 g l m − 6 h k l. Squared once it is a quadratic in l; its roots where the factor
    itself vanishes are the scan's (sign changes on a fine grid, and l = 0, where
    12 L₀ k h − 12 L₀ k h = 0), and the other one (the radical's other sign) is dropped."""
    l = sp.Symbol("l", positive=True)
    h, L0, k, m, g = (sp.Rational(x) for x in (h, L0, k, m, "981/100"))
    F = 12 * L0 * k * (h + l) - 12 * L0 * k * sp.sqrt(h**2 + h * l + l**2) + 3 * g * l * m - 6 * h * k * l
    assert _squared_once(F, l) is not None
    roots = _roots_in(F, l)
    terms = sp.Add.make_args(sp.expand(F))
    kept = sorted(float(r) for r in roots if vanishes_at(terms, l, r, {}))
    dropped = [r for r in roots if not vanishes_at(terms, l, r, {})]
    f = sp.lambdify(l, F, "math")
    grid = np.linspace(1e-9, 50, 50001)
    values = [f(x) for x in grid]
    scanned = [0.0] + [float(brentq_root(f, a, b)) for a, b, u, v in zip(grid, grid[1:], values, values[1:]) if u * v < 0]
    assert kept == pytest.approx(scanned, abs=1e-9)
    assert bool(dropped) is has_false_root


def brentq_root(f, a: float, b: float) -> float:
    from scipy.optimize import brentq

    return brentq(f, a, b, xtol=1e-14)


def test_two_radicals_in_the_parameter_are_not_solved() -> None:
    """Squared twice they give a quartic of false roots: the parameter is left undecided,
    decided by the structure (sympy's solve took 5–7 s on such a factor)."""
    l, h = sp.symbols("l h", positive=True)
    F = sp.sqrt(h**2 + 2 * h * l + l**2 - l) - sp.sqrt(h**2 + h * l + l**2) + l
    assert _under_two_radicals(F, l) and _under_two_radicals(F, h)
    assert not _under_two_radicals(sp.sqrt(h**2 + h * l + l**2) + l, l)


def test_a_radical_times_constants_has_its_radicands_roots_without_solve(monkeypatch) -> None:
    """R g m √(16 − 9π² sin²β) (a half-disk's push on an incline, problems/contacts/
    half-disk-on-incline.yaml) vanishes where 16 − 9π² sin²β does: sin β = ±4/(3π), by
    hand, i.e. β = ±0.43760 and π ∓ 0.43760 in (−π, π]; the scan of the radicand finds
    the same. Found from the radicand, without sympy's solve."""
    from rbdsolve.solvers.conditions import condition_roots

    def never(*args, **kwargs):
        raise AssertionError(f"sympy's solve called on {args}")

    monkeypatch.setattr(condition_roots.sp, "solve", never)
    R, g, m, beta = sp.symbols("R g m beta", positive=True)
    factor = R * g * m * sp.sqrt(16 - 9 * sp.pi**2 * sp.sin(beta) ** 2)
    _roots_in.cache_clear()
    found = _in_the_turn(condition_roots._solved(factor, beta))
    s = math.asin(4 / (3 * math.pi))
    assert found == pytest.approx(sorted([s, -s, math.pi - s, -(math.pi - s)]), abs=1e-12)
    assert found == pytest.approx(_scanned_roots(lambda b: 16 - 9 * math.pi**2 * math.sin(b) ** 2), abs=1e-9)


def test_a_condition_of_several_parameters_is_factored_once(monkeypatch) -> None:
    """(a − b)(a + b − c)(a b − c²), cubic in each of a, b and c, has by hand the roots
    a = b, c − b, c²/b; b = a, c − a, c²/a; c = a + b, ±√(a b). Each parameter's roots
    come from one factorization of the whole polynomial (a rod on a spring of natural
    length factored one condition of six parameters six times)."""
    from rbdsolve.solvers.conditions import condition_roots

    a, b, c = sp.symbols("a b c", positive=True)
    f = sp.expand((a - b) * (a + b - c) * (a * b - c**2))
    calls = counted_calls(monkeypatch, condition_roots.sp, "factor_list")
    _roots_in.cache_clear()
    condition_roots._factors_of.cache_clear()
    found = {p: set(_roots_in(f, p)) for p in (a, b, c)}
    assert len(calls) == 1
    assert found[a] == {b, c - b, c**2 / b}
    assert found[b] == {a, c - a, c**2 / a}
    assert {sp.simplify(r**2 - a * b) == 0 or sp.expand(r - a - b) == 0 for r in found[c]} == {True}
    assert len(found[c]) == 3


def test_a_condition_with_a_cosine_among_its_coefficients_is_factored_whole() -> None:
    """(k − m cos α)(k² − 3m)(k + 1), quartic in k with cos α in its coefficients: by hand
    k = m cos α, ±√(3m), −1; and with a factor m² − k, quartic in m: m = k/cos α, k²/3, ±√k.
    (The whole polynomial is factored in cos α as one of its generators, not in α.)"""
    a, k, m = sp.symbols("alpha k m", positive=True)
    _roots_in.cache_clear()
    f = sp.expand((k - m * sp.cos(a)) * (k**2 - 3 * m) * (k + 1))
    assert set(_roots_in(f, k)) == {m * sp.cos(a), -1, sp.sqrt(3 * m), -sp.sqrt(3 * m)}
    g = sp.expand(f * (m**2 - k))
    assert set(_roots_in(g, m)) == {k / sp.cos(a), k**2 / 3, sp.sqrt(k), -sp.sqrt(k)}


def test_a_value_followed_along_each_parameter_is_put_over_one_denominator_once(monkeypatch) -> None:
    """(c − a − b)/(a b) + 1/c = (c² − (a + b) c + a b)/(a b c) = (c − a)(c − b)/(a b c), by
    hand: along c its roots are a and b (in the order of the samples, a < b or not: the
    order changes, so None), along a its root is c (the denominator's a = 0 is the
    range's end), along b its root c. One ``together`` for the three parameters (a
    plate on a spring of natural length split one K six times, 0.1 s each)."""
    from rbdsolve.form import quotient as quotient_module
    from rbdsolve.model.build import build_model
    from rbdsolve.problem import load_text
    from rbdsolve.solvers.conditions import condition_roots

    model = build_model(load_text(SCENE))
    a, b, c = (model.symbols.parameters[n] for n in "abc")
    value = (c - a - b) / (a * b) + 1 / c
    calls = counted_calls(monkeypatch, quotient_module.sp, "together")
    quotient_module.quotient.cache_clear()
    _roots_in.cache_clear()
    along = {p: condition_roots.parameter_roots(value, p, {}, model) for p in (a, b, c)}
    assert len([x for x in calls if x[0] == value]) == 1
    assert along[a] == [c] and along[b] == [c]
    assert along[c] is None


def test_a_parameter_inside_an_atan2_is_left_undecided_without_solve(monkeypatch) -> None:
    """cos(β − atan2(R k sin β, m g + R k cos β)) − c (a hoop in a track on a cord: its
    rest angle is that atan2): no root in k is looked for (sympy's solve ran past the
    minute's budget), the parameter is left undecided (None) at once."""
    from rbdsolve.model.build import build_model
    from rbdsolve.problem import load_text
    from rbdsolve.solvers.conditions import condition_roots

    def never(*args, **kwargs):
        raise AssertionError(f"sympy's solve called on {args}")

    monkeypatch.setattr(condition_roots.sp, "solve", never)
    model = build_model(load_text(SCENE))
    a, b, c = (model.symbols.parameters[n] for n in "abc")
    beta = sp.pi / 5
    f = sp.cos(beta - sp.atan2(a * c * sp.sin(beta), b + a * c * sp.cos(beta))) - sp.Rational(1, 2)
    assert condition_roots.parameter_roots(f, c, {}, model) is None


def test_a_root_too_long_to_read_is_no_critical_value(monkeypatch) -> None:
    """A disk on an incline held by a spring of natural length to a point off its line
    had N linear in k, but with every parameter open its root k_c ran to 7 345
    operations, tested at each sample for 2 s: a root of more than LONG_ROOT_OPS
    operations leaves the parameter undecided at once (None: no condition printed);
    a short one is still a critical value (control)."""
    from rbdsolve.model.build import build_model
    from rbdsolve.problem import load_text
    from rbdsolve.solvers.conditions import condition_roots

    model = build_model(load_text(SCENE))
    a, b, c = (model.symbols.parameters[n] for n in "abc")
    long_root = sum(a**k * b / (b + k * a) for k in range(1, 90))
    assert sp.count_ops(long_root) > condition_roots.LONG_ROOT_OPS
    monkeypatch.setattr(condition_roots, "_roots_in", lambda factor, p: (long_root,))
    assert condition_roots.parameter_roots(c - long_root, c, {}, model) is None
    monkeypatch.setattr(condition_roots, "_roots_in", lambda factor, p: (a,))
    assert condition_roots.parameter_roots(c - a, c, {}, model) == [a]


def test_radical_roots_drop_the_squares_own_roots_and_keep_the_undecided() -> None:
    """Roots in x with x under a radical, without sympy's checks (which ran simplify for
    seconds), each judged at the samples. By hand, a, b > 0:
    √(x² + a²) + a is never 0 (both terms positive), but squared, x² + a² = a², gives
    x = 0: dropped. √(x² + a²) − 2a = 0 at x² = 3a²: both ±√3 a kept. b √(x² + a²) − a²
    = 0 at x² = a⁴/b² − a², real where a > b only: kept (undecided, as sympy keeps it)."""
    from rbdsolve.model.build import build_model
    from rbdsolve.problem import load_text

    model = build_model(load_text(SCENE))
    a, b = model.symbols.parameters["a"], model.symbols.parameters["b"]
    x = sp.Dummy("x", real=True)
    assert radical_roots(sp.sqrt(x**2 + a**2) + a, x, model) == []
    found = radical_roots(sp.sqrt(x**2 + a**2) - 2 * a, x, model)
    assert sorted(found, key=lambda r: float(r.subs(a, 1))) == [-sp.sqrt(3) * a, sp.sqrt(3) * a]
    undecided = radical_roots(b * sp.sqrt(x**2 + a**2) - a**2, x, model)
    assert len(undecided) == 2
    for r in undecided:
        assert sp.simplify(r**2 - (a**4 / b**2 - a**2)) == 0
