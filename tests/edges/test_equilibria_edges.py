"""Failure edges of the equilibria routes (issue 8): transcendental equations, the
numeric route's completeness, degenerate Hessians, and trigonometric polynomials that
sympy's plain solve gets wrong.

Expected values are independent: roots of the equilibrium equation by mpmath at 30
digits (a dense sign-change scan with findroot on each bracket, plus findroot from
many starts), stabilities from the sign of V'' there worked out by hand, and exact
roots by hand. Numeric roots are compared to 1e-9 absolute (the route polishes to
round-off; the tolerance leaves room for the float evaluation of V).
"""

from __future__ import annotations

import mpmath as mp
import pytest
import sympy as sp

from rbdsolve.errors import InputError
from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.solvers import solve_problem
from rbdsolve.solvers.equilibria import exact as equilibria
from rbdsolve.solvers.equilibria import numeric as equilibria_numeric
from rbdsolve.solvers.routes.options import Options, RouteChoice

TOL = 1e-9

# An inverted rod (mass m, length l) on a pivot, held up by a torsional spring c:
# V = ½ c θ² + m g (l/2) cos θ, ∂V/∂θ = c θ − (m g l/2) sin θ = 0 ⇔ θ = k sin θ with
# k = m g l/(2 c); V'' = c (1 − k cos θ). With m = 1, l = 2, g = 1: k = 1/c.
INVERTED = """\
parameters: {{m: mass, l: length, g: gravity, c: stiffness}}
values: {{m: 1, l: 2, g: 1, c: {c}}}
coordinates: [theta]
gravity: [0, -g]
points:
  G: l/2 * [sin(theta), cos(theta)]
bodies:
  rod: {{shape: rod, mass: m, length: l, at: G, angle: theta, axis: y}}
springs:
  s: {{stiffness: c, angle: theta}}
questions: [equilibria]
"""


def _model(text: str):
    return build_model(load_text(text, "scene.yaml"))


def _oracle_roots(f, low: float, high: float, points: int = 20001) -> list:
    """Every root of f on [low, high]: sign changes on a dense grid, each refined by
    mpmath's findroot (bisection-safe 'anderson' on the bracket), plus findroot from
    many starts; merged at 1e-12."""
    with mp.workdps(30):
        return _roots_at_working_precision(f, low, high, points)


def _roots_at_working_precision(f, low: float, high: float, points: int) -> list:
    xs = [mp.mpf(low) + (mp.mpf(high) - low) * i / (points - 1) for i in range(points)]
    roots = []
    for a, b in zip(xs, xs[1:]):
        fa, fb = f(a), f(b)
        if fa == 0:
            roots.append(a)
        elif fa * fb < 0:
            roots.append(mp.findroot(f, (a, b), solver="anderson"))
    for i in range(400):
        try:
            r = mp.findroot(f, mp.mpf(low) + (high - low) * (i + 0.5) / 400)
        except (ValueError, ZeroDivisionError):
            continue
        if low <= r <= high and abs(f(r)) < mp.mpf(10) ** -20:
            roots.append(r)
    out = []
    for r in sorted(roots):
        if not out or abs(r - out[-1]) > 1e-12:
            out.append(r)
    return out


@pytest.mark.parametrize("k", ["1/2", "1", "2", "15/2", "20"])
def test_theta_equals_k_sin_theta_every_root_numerically(k) -> None:
    """All roots in the search box (±10 × the largest value = ±20 ⊇ |θ| ≤ k) and hence
    all in (−π, π], counted and placed as mpmath's; stable where 1 − k cos θ > 0,
    undetermined at the triple root θ = 0 of k = 1 (V'' = 0 there)."""
    kk = sp.Rational(k)
    model = _model(INVERTED.format(c=1 / kk))
    solution = equilibria_numeric.solve(None, model, Options(route=RouteChoice.NUMERIC))
    got = [(eq.at["theta"], eq.stability.value) for eq in solution.answers.equilibria]
    kf = mp.mpf(kk.p) / kk.q
    want = _oracle_roots(lambda t: t - kf * mp.sin(t), -20, 20)
    assert len(got) == len(want), (got, want)
    for (x, kind), r in zip(got, want):
        assert abs(x - float(r)) <= TOL
        curvature = 1 - kf * mp.cos(r)
        expected = "undetermined" if abs(curvature) < 1e-20 else ("stable" if curvature > 0 else "unstable")
        assert kind == expected, (x, kind, expected)
    inside = [x for x, _ in got if -mp.pi < x <= mp.pi]
    assert len(inside) == {"1/2": 1, "1": 1, "2": 3, "15/2": 3, "20": 3}[k]
    assert "sign-change scan" in solution.warnings[0] and "every equilibrium in it is found provided" in solution.warnings[0]


def test_the_exact_route_gives_the_evident_root_of_theta_equals_k_sin_theta_and_auto_goes_numeric() -> None:
    """θ = 2 sin θ: the exact route lists θ = 0 only (it makes every term vanish) and says
    others may exist; auto, with every value given, takes the numeric route at once,
    chosen from the equations' structure, and finds all three."""
    model = _model(INVERTED.format(c="1/2"))
    exact = equilibria.solve(None, model, Options())
    assert [e.at["theta"] for e in exact.answers.equilibria] == [0]
    assert any("evident roots" in w and "other equilibria may exist" in w.lower() for w in exact.warnings)
    (solution,) = solve_problem(model, Options(route=RouteChoice.AUTO)).solutions
    assert solution.route.value == "numeric" and solution.error is None
    assert solution.warnings[0].startswith("the exact route would answer only in part: the equilibrium equations "
                                           "are transcendental")
    assert [round(eq.at["theta"], 9) for eq in solution.answers.equilibria] == pytest.approx(
        [float(r) for r in _oracle_roots(lambda t: t - 2 * mp.sin(t), -20, 20)], abs=TOL)


# A bead on a corrugated wire y = a cos(x/b), held by a spring to A = (0, y − d):
# V = m g a cos(x/b) + ½ k (x² + d²), ∂V/∂x = k x − (m g a/b) sin(x/b): many wells.
WIRE = """\
parameters: {m: mass, g: gravity, a: amplitude, b: wavelength over 2 pi, k: stiffness, d: offset}
values: {m: 1, g: 10, a: 1, b: 1/2, k: 1, d: 1}
coordinates:
  x: {kind: length, range: [-m*g*a/(k*b), m*g*a/(k*b)]}
gravity: [0, -g]
points:
  P: [x, a*cos(x/b)]
  A: [0, a*cos(x/b) - d]
bodies:
  bead: {shape: particle, mass: m, at: P}
springs:
  s: {stiffness: k, between: [P, A]}
questions: [equilibria]
"""


def test_a_length_coordinate_with_many_wells_every_root_in_the_box() -> None:
    """k x = 20 sin(2x): every root has |x| ≤ m g a/(k b) = 20, the declared range;
    mpmath's set, with stability from V'' = k − 40 cos(2x)."""
    model = _model(WIRE)
    solution = equilibria_numeric.solve(None, model, Options(route=RouteChoice.NUMERIC))
    want = _oracle_roots(lambda x: x - 20 * mp.sin(2 * x), -21, 21, 40001)
    got = solution.answers.equilibria
    assert len(got) == len(want) == 27
    for eq, r in zip(got, want):
        assert abs(eq.at["x"] - float(r)) <= TOL
        assert eq.stability.value == ("stable" if 1 - 40 * mp.cos(2 * r) > 0 else "unstable")


# V = m g c x⁴: x = 0 is an equilibrium whose Hessian vanishes. By hand V⁽⁴⁾(0) = 24 m g c
# > 0: a strict minimum, which the exact route finds (equilibria/higher_order.py); the
# numeric route cannot tell V'' = 0 from a rounding and leaves it undetermined.
QUARTIC = """\
parameters: {m: mass, g: gravity, c: shape}
values: {m: 1, g: 1, c: 1}
coordinates: [x]
gravity: [0, -g]
points:
  P: [x, c*x**4]
bodies:
  bead: {shape: particle, mass: m, at: P}
questions: [equilibria]
"""

# The hoop turning at the critical rate Ω² R = g (R = 109/100, Ω = 3, g = 981/100: exact
# in rationals, not in floats): V'' = m R (g − Ω² R) = 0 at θ = 0 (V ≈ m g R θ⁴/8 there).
HOOP = """\
parameters: {m: mass, R: radius, g: gravity, Omega: rate}
values: {m: 1, R: 1.09, g: 9.81, Omega: 3}
coordinates: [theta]
gravity: [0, -g, 0]
frames:
  hoop: {axis: y, rate: Omega}
points:
  P: R * [sin(theta)*cos(Omega*t), -cos(theta), -sin(theta)*sin(Omega*t)]
bodies:
  bead: {shape: particle, mass: m, at: P}
questions:
  - equilibria: {frame: hoop}
"""


@pytest.mark.parametrize("route", [RouteChoice.EXACT, RouteChoice.NUMERIC])
def test_a_vanishing_hessian_is_decided_by_the_fourth_derivative_exactly_and_left_numerically(route) -> None:
    (solution,) = solve_problem(_model(QUARTIC), Options(route=route)).solutions
    (eq,) = solution.answers.equilibria
    if route is RouteChoice.EXACT:
        assert eq.stability.value == "stable"
        assert "∂⁴V/∂x⁴ = 24 c g m, is of even order and positive" in eq.reason
    else:
        assert eq.stability.value == "undetermined"
        assert any("higher-order terms decide" in w for w in solution.warnings)


@pytest.mark.parametrize("route", [RouteChoice.EXACT, RouteChoice.NUMERIC])
def test_the_critical_hoop_is_not_classified_on_round_off(route) -> None:
    """θ = 0 not stable or unstable from a rounding of g − Ω² R: undetermined on the
    numeric route; on the exact route V'' = 0 exactly and V⁽⁴⁾ = m R (4 Ω² R − g) > 0
    decides it, stable (V ≈ m g R θ⁴/8, by hand). θ = π unstable (V'' = −m R (g + Ω² R)
    < 0). The exact route lists the branches ±acos(g/(R Ω²)) that meet at 0 and says
    they coincide."""
    (solution,) = solve_problem(_model(HOOP), Options(route=route)).solutions
    kinds = {}
    for eq, values in zip(solution.answers.equilibria, solution.values["equilibria"]):
        kinds.setdefault(round(float(values["at"]["theta"]), 9), set()).add(eq.stability.value)
    at_zero = "stable" if route is RouteChoice.EXACT else "undetermined"
    assert kinds == {0.0: {at_zero}, round(float(sp.pi), 9): {"unstable"}}
    if route is RouteChoice.EXACT:
        assert any("coincide at the given parameter values" in w for w in solution.warnings)


POINTS = """\
parameters: {{m: mass, l: length, g: gravity}}
values: {{m: 1, l: 1, g: 1}}
coordinates: [theta]
gravity: [0, -g]
points:
{points}
bodies:
{bodies}
questions: [equilibria]
"""


@pytest.mark.parametrize("points, bodies, roots", [
    # V = −m g l cos 3θ: ∂V/∂θ = 3 m g l sin 3θ; sympy's solve(sin(3x)) gives [0, pi/3] only
    ("  P: l*[sin(3*theta), -cos(3*theta)]", "  b: {shape: particle, mass: m, at: P}",
     {"-2*pi/3": "stable", "-pi/3": "unstable", "0": "stable", "pi/3": "unstable", "2*pi/3": "stable",
      "pi": "unstable"}),
    # V = −m g l (cos θ + ½ cos 2θ): ∂V/∂θ = m g l (sin θ + sin 2θ); plain solve misses π
    ("  P: l*[sin(theta), -cos(theta)]\n  Q: l/2*[sin(2*theta), -cos(2*theta)]",
     "  b: {shape: particle, mass: m, at: P}\n  c: {shape: particle, mass: m, at: Q}",
     {"-2*pi/3": "unstable", "0": "stable", "2*pi/3": "unstable", "pi": "stable"}),
])
def test_trigonometric_polynomials_get_every_root_where_plain_solve_misses(points, bodies, roots) -> None:
    """By hand: sin 3θ = 0 ⇔ θ = jπ/3, V'' = 3 m g l cos 3θ; sin θ (1 + 2 cos θ) = 0 ⇔
    θ ∈ {0, π, ±2π/3}, V'' = m g l (cos θ + 2 cos 2θ): 3 at 0, 1 at π, −3/2 at ±2π/3."""
    model = _model(POINTS.format(points=points, bodies=bodies))
    theta = sp.Symbol("theta", real=True)
    plain = sp.solve(equilibria.gradient(model)[0].xreplace({model.q[0]: theta}), theta)
    assert len(plain) < len(roots)  # the edge: plain solve misses some
    # P at 3θ: θ and θ ± 2π/3 are one configuration, listed once with the others as
    # equivalent; every root is still there, each with its stability.
    got = _every_root(equilibria.solve(None, model, Options()).answers.equilibria)
    assert len(got) == len(roots)
    for at, stability in got:
        match = [r for r in roots if sp.simplify(at - sp.sympify(r)) == 0]
        assert match and stability == roots[match[0]], (at, stability)
    numeric = _every_root(equilibria_numeric.solve(None, model, Options()).answers.equilibria)
    assert sorted(round(at, 9) for at, _ in numeric) == pytest.approx(
        sorted(float(sp.sympify(r)) for r in roots), abs=TOL)


def _every_root(listed) -> list:
    """(θ, stability) for every equilibrium and every equivalent value of it."""
    return [(where["theta"], eq.stability.value) for eq in listed for where in (eq.at, *eq.equivalent)]


# A torsional spring with rest angle 3π/2 on a declared angle: V = ½ c (θ − 3π/2)² is not
# 2π-periodic, so its equilibrium θ = 3π/2 must not be turned to −π/2 (V' ≠ 0 there).
REST = """\
parameters: {c: stiffness}
values: {c: 1}
coordinates: {theta: {kind: angle, periodic: false}}
points:
  P: [cos(theta), sin(theta)]
bodies:
  b: {shape: particle, mass: 1, at: P}
springs:
  s: {stiffness: c, angle: theta, rest: 3*pi/2}
questions: [equilibria]
"""


def test_a_declared_angle_that_is_not_periodic_keeps_its_equilibrium() -> None:
    """Declared 'periodic: false', θ = 3π/2 is not folded to −π/2 (on either route)."""
    model = _model(REST)
    exact = equilibria.solve(None, model, Options())
    assert [sp.simplify(eq.at["theta"] - 3 * sp.pi / 2) for eq in exact.answers.equilibria] == [0]
    numeric = equilibria_numeric.solve(None, model, Options())
    assert [eq.at["theta"] for eq in numeric.answers.equilibria] == pytest.approx([3 * float(sp.pi) / 2], abs=TOL)
    assert any("θ in [-31.4159, 31.4159] (±10π: an angle that winds up" in w for w in numeric.warnings)


def test_the_same_angle_declared_periodic_is_refused() -> None:
    with pytest.raises(InputError, match="'theta' is declared an angle, which repeats after a turn, but spring 's' "
                                         "holds it outside sin and cos"):
        _model(REST.replace("{theta: {kind: angle, periodic: false}}", "{theta: angle}"))
