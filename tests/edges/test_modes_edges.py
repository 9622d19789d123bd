"""Failure edges of the `modes` routes (issue 8): repeated and near-repeated eigenvalues,
ill-conditioned mass and stiffness, unstable and neutral modes. Each case gets a correct
answer or a stated reason, never a silent wrong number, NaN or hang
(docs/failure-edges.md).

Expected values are derived by hand in each test (M and K written down from T and V)
and, for numbers, solved here in mpmath at 50 digits; none is taken from rbdsolve.
"""

from __future__ import annotations

import json
from fractions import Fraction

import mpmath
import pytest
import sympy as sp

from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.render.json import render_report
from rbdsolve.solvers import Options, RouteChoice, solve_problem
from rbdsolve.solvers.modes.answers import Motion

from conftest import CART_PENDULUM

EXACT, NUMERIC = Options(route=RouteChoice.EXACT), Options(route=RouteChoice.NUMERIC)


@pytest.fixture(autouse=True)
def _fifty_digits():
    """The references in 50 digits, without changing mpmath's precision for other tests."""
    with mpmath.workdps(50):
        yield


def _solve(text: str, options: Options):
    report = solve_problem(build_model(load_text(text, "scene.yaml")), options)
    return report, report.solutions[0]


def _strict(report) -> dict:
    def refuse(token: str):
        raise AssertionError(f"non-strict JSON constant {token}")

    return json.loads(render_report(report), parse_constant=refuse)


def _mp(x) -> mpmath.mpf:
    """An exact int, Fraction or float as an mpf (fractions divided at 50 digits)."""
    if isinstance(x, Fraction):
        return mpmath.mpf(x.numerator) / x.denominator
    return mpmath.mpf(x)


def _mp_eigen(K, M):
    """Eigenvalues ascending and M-normalized vectors of K a = λ M a at 50 digits, by the
    symmetric form of a diagonal M: A = M^(-1/2) K M^(-1/2), mpmath.eigsy."""
    n = len(M)
    D = [mpmath.sqrt(_mp(M[i][i])) for i in range(n)]
    A = mpmath.matrix([[_mp(K[i][j]) / (D[i] * D[j]) for j in range(n)] for i in range(n)])
    lam, Q = mpmath.eigsy(A)
    order = sorted(range(n), key=lambda i: lam[i])
    return [lam[i] for i in order], [[Q[r, i] / D[r] for r in range(n)] for i in order]


def _m_sin(a, b, M) -> float:
    """sin of the angle between a and b in the inner product uᵀ M v (M diagonal)."""
    dot = lambda u, v: sum(_mp(M[i][i]) * _mp(u[i]) * _mp(v[i]) for i in range(len(u)))  # noqa: E731
    cos2 = dot(a, b) ** 2 / (dot(a, a) * dot(b, b))
    return float(mpmath.sqrt(max(1 - cos2, 0)))


# --- 2. Repeated and near-repeated eigenvalues --------------------------------------------

# Three equal masses m on parallel rails, each pair joined by a spring k of zero length:
# T = ½ m (ẋ² + ẏ² + ż²), V = ½ k ((x − y)² + (y − z)² + (z − x)²) + const, so M = m 1,
# K = k [[2, −1, −1], [−1, 2, −1], [−1, −1, 2]]: λ = 0 (a = (1, 1, 1)) and λ = 3k/m twice,
# its mode space every a with a₁ + a₂ + a₃ = 0.
RING = """
parameters: {m: mass, k: stiffness}
values: {m: 2, k: 5}
coordinates: [x, y, z]
points:
  A: [x, 0]
  B: [y, 2]
  C: [z, 4]
bodies:
  a: {shape: particle, mass: m, at: A}
  b: {shape: particle, mass: m, at: B}
  c: {shape: particle, mass: m, at: C}
springs:
  s1: {stiffness: k, between: [A, B]}
  s2: {stiffness: k, between: [B, C]}
  s3: {stiffness: k, between: [C, A]}
questions:
  - modes: {about: {x: 0, y: 0, z: 0}}
"""


def test_exact_double_root_gives_an_m_orthogonal_basis_of_its_plane() -> None:
    report, s = _solve(RING, EXACT)
    a = s.answers
    names = {str(x): x for x in a.M.free_symbols | a.K.free_symbols}
    M = sp.eye(3) * names["m"]
    K = names["k"] * sp.Matrix([[2, -1, -1], [-1, 2, -1], [-1, -1, 2]])
    assert sp.simplify(a.M - M) == sp.zeros(3) and sp.simplify(a.K - K) == sp.zeros(3)
    double = 3 * names["k"] / names["m"]
    assert [sp.simplify(x - y) for x, y in zip(a.eigenvalues, (0, double, double))] == [0, 0, 0]
    assert a.multiplicities == (1, 2, 2)
    assert a.motions == (Motion.NEUTRAL, Motion.OSCILLATION, Motion.OSCILLATION)
    u, v = (sp.Matrix(x) for x in a.shapes[1:])
    assert sp.simplify((K - double * M) * u) == sp.zeros(3, 1) == sp.simplify((K - double * M) * v)
    assert sp.simplify((u.T * M * v)[0]) == 0  # M-orthogonal
    assert sp.Matrix.hstack(u, v).rank() == 2  # a basis of the plane a₁ + a₂ + a₃ = 0
    assert sp.simplify(sp.Matrix(a.shapes[0]) - sp.Matrix([1, 1, 1])) == sp.zeros(3, 1)
    text = " ".join(step.text for step in s.steps)
    assert "multiplicity 2" in text and "M-orthogonal basis" in text
    _strict(report)


def test_numeric_cluster_is_one_mode_space_with_an_m_orthonormal_basis() -> None:
    report, s = _solve(RING, NUMERIC)
    a = s.answers
    M = [[2, 0, 0], [0, 2, 0], [0, 0, 2]]
    K = [[5 * x for x in row] for row in ([2, -1, -1], [-1, 2, -1], [-1, -1, 2])]
    for lam, ref, bound in zip(a.eigenvalues, (0, Fraction(15, 2), Fraction(15, 2)), a.absolute_errors):
        assert isinstance(lam, float) and abs(lam - ref) <= bound
    assert a.clusters == ((1,), (2, 3))
    assert a.motions[0] is Motion.NEUTRAL and a.growth_rates == (None, None, None)
    V = a.orthonormal_shapes
    for lam, v in zip(a.eigenvalues, V):  # (K − λM) a = 0 within rounding (entries of size 10)
        assert max(abs(sum(K[r][c] * v[c] for c in range(3)) - lam * M[r][r] * v[r]) for r in range(3)) < 1e-13
    for i in range(3):
        for j in range(3):  # aᵢᵀ M aⱼ = δᵢⱼ within 1e-14
            assert abs(sum(V[i][r] * M[r][r] * V[j][r] for r in range(3)) - (i == j)) < 1e-14
    # The exact plane {a₁ + a₂ + a₃ = 0}: its basis (1, −1, 0), (1, 1, −2) lies in the computed
    # cluster's span within the stated sin Θ bound (projection residual, M inner product).
    for exact in ([1, -1, 0], [1, 1, -2]):
        coeff = [sum(V[i][r] * M[r][r] * exact[r] for r in range(3)) for i in (1, 2)]
        rest = [exact[r] - coeff[0] * V[1][r] - coeff[1] * V[2][r] for r in range(3)]
        norm = lambda w: sum(M[r][r] * w[r] ** 2 for r in range(3)) ** 0.5  # noqa: E731
        assert norm(rest) / norm(exact) <= a.shape_errors[1] + 1e-15
    assert any("one mode space of dimension 2" in w for w in s.warnings)
    _strict(report)


# Two pendulums (particles m on massless links) hung 3 apart, lengths l and l(1 + d),
# joined by a zero-length spring c between points at heights 5 and 6 moving l·a and
# l·b sideways: T = ½ m l² (ȧ² + (1 + d)² ḃ²), V = −m g l (cos a + (1 + d) cos b)
# + ½ c l² (a − b)² + const, so M = m l² diag(1, (1 + d)²) and
# K = [[m g l + c l², −c l²], [−c l², m g l (1 + d) + c l²]] at a = b = 0.
def _pendulums(d: str, c: str | None) -> str:
    """Without c (None): no spring, the pendulums uncoupled."""
    text = f"""
parameters: {{m: mass, l: length, g: gravity, c: stiffness}}
values: {{m: 1, l: 1, g: 981/100, c: {c or 1}}}
coordinates: [a, b]
gravity: [0, -g]
points:
  P: l * [sin(a), -cos(a)]
  Q: "[3, 0] + l * (1 + {d}) * [sin(b), -cos(b)]"
  R: "[l*a, 5]"
  S: "[l*b, 6]"
bodies:
  p: {{shape: particle, mass: m, at: P}}
  q: {{shape: particle, mass: m, at: Q}}
springs:
  s: {{stiffness: c, between: [R, S]}}
questions:
  - modes: {{about: {{a: 0, b: 0}}}}
"""
    return text if c else text.replace("springs:\n  s: {stiffness: c, between: [R, S]}\n", "")


def _pendulum_matrices(d, c, m=1, l=1, g=Fraction(981, 100)):
    M = [[m * l**2, 0], [0, m * l**2 * (1 + d) ** 2]]
    K = [[m * g * l + c * l**2, -c * l**2], [-c * l**2, m * g * l * (1 + d) + c * l**2]]
    return M, K


def test_two_identical_pendulums_double_on_both_routes() -> None:
    _, exact = _solve(_pendulums("0", None), EXACT)
    g, l = (next(s for s in exact.answers.eigenvalues[0].free_symbols if s.name == n) for n in ("g", "l"))
    assert [sp.simplify(x - g / l) for x in exact.answers.eigenvalues] == [0, 0]
    assert exact.answers.multiplicities == (2, 2)
    shapes = [sp.Matrix(v) for v in exact.answers.shapes]
    assert sp.simplify((shapes[0].T * exact.answers.M * shapes[1])[0]) == 0
    report, numeric = _solve(_pendulums("0", None), NUMERIC)
    a = numeric.answers
    assert a.clusters == ((1, 2),) and a.shape_errors == (0.0, 0.0)  # the space is the whole plane
    assert all(abs(x - 9.81) <= b for x, b in zip(a.eigenvalues, a.absolute_errors))
    assert all(isinstance(w, float) for w in a.frequencies)
    _strict(report)


def test_eigenvalues_split_by_1e_10_are_told_apart_and_their_shapes_bounded() -> None:
    d, c = Fraction(1, 10**10), Fraction(1, 10**9)
    M, K = _pendulum_matrices(d, c)
    ref, vectors = _mp_eigen(K, M)
    report, s = _solve(_pendulums("1/10000000000", "1/1000000000"), NUMERIC)
    a = s.answers
    assert a.clusters == ((1,), (2,))
    for lam, r, bound in zip(a.eigenvalues, ref, a.absolute_errors):
        assert abs(mpmath.mpf(lam) - r) <= bound
    for shape, exact, bound in zip(a.shapes, vectors, a.shape_errors):
        assert _m_sin(shape, exact, M) <= bound
    assert 1e-8 < a.shape_errors[0] < 1e-4  # gap ≈ 2.2e-9, residual and rounding ≈ 1e-14
    assert any("determined only within" in w for w in s.warnings)
    _strict(report)
    _, exact = _solve(_pendulums("1/10000000000", "1/1000000000"), EXACT)
    values = {x: {"m": 1, "l": 1, "g": sp.Rational(981, 100), "c": sp.Rational(1, 10**9)}[x.name]
              for x in exact.answers.M.free_symbols | exact.answers.K.free_symbols}
    for lam, r in zip(exact.answers.eigenvalues, ref):
        assert abs(mpmath.mpf(str(sp.N(lam.xreplace(values), 60, maxn=4000, strict=True))) - r) < mpmath.mpf(10) ** -45


# --- 3. Ill-conditioning: one tiny mass or one stiff spring --------------------------------

# Three masses on rails, wall–k₁–m₁–k₂–m₂–k₃–m₃ with zero-length springs:
# M = diag(m₁, m₂, m₃), K = [[k₁ + k₂, −k₂, 0], [−k₂, k₂ + k₃, −k₃], [0, −k₃, k₃]].
def _chain(masses, springs) -> str:
    return ("coordinates: [x1, x2, x3]\npoints:\n  P0: [0, 0]\n"
            + "".join(f"  P{i}: [x{i}, {i}]\n" for i in (1, 2, 3)) + "bodies:\n"
            + "".join(f"  b{i}: {{shape: particle, mass: {m}, at: P{i}}}\n" for i, m in enumerate(masses, 1))
            + "springs:\n" + "".join(f"  s{i}: {{stiffness: {k}, between: [P{i - 1}, P{i}]}}\n"
                                     for i, k in enumerate(springs, 1))
            + "questions:\n  - modes: {about: {x1: 0, x2: 0, x3: 0}}\n")


def _chain_matrices(masses, springs):
    m, k = masses, springs
    M = [[m[0], 0, 0], [0, m[1], 0], [0, 0, m[2]]]
    K = [[k[0] + k[1], -k[1], 0], [-k[1], k[1] + k[2], -k[2]], [0, -k[2], k[2]]]
    return M, K


RATIOS = [Fraction(1, 10**p) for p in (0, 3, 6, 9, 12)]


def _chains(r: Fraction):
    one = Fraction(1)
    return {"mass": ((one, one, r), (one, one, one)), "stiffness": ((one, one, one), (one, 1 / r, one))}


@pytest.mark.parametrize("kind", ["mass", "stiffness"])
@pytest.mark.parametrize("r", RATIOS, ids=lambda r: f"r=1e-{len(str(r.denominator)) - 1}")
def test_ill_conditioned_numeric_bound_holds_and_is_warned(kind: str, r: Fraction) -> None:
    masses, springs = _chains(r)[kind]
    M, K = _chain_matrices(masses, springs)
    ref, _ = _mp_eigen(K, M)
    report, s = _solve(_chain(masses, springs), NUMERIC)
    a = s.answers
    for lam, x, rel in zip(a.eigenvalues, ref, a.relative_errors):
        assert abs(mpmath.mpf(lam) - x) / abs(x) <= rel  # the stated bound holds
    assert abs(a.condition_M - (float(1 / r) if kind == "mass" else 1.0)) <= 1e-12 * a.condition_M
    loose = any(e > 1e-8 for e in a.relative_errors)
    assert loose == any("ill-conditioned" in w for w in s.warnings)
    if r <= Fraction(1, 10**9):
        assert loose  # past κ ≈ 1e8 the bound passes the tolerance and says so
    if r == 1:
        assert not s.warnings
    _strict(report)


@pytest.mark.parametrize("kind", ["mass", "stiffness"])
@pytest.mark.parametrize("r", [Fraction(1, 10**p) for p in (0, 4, 8, 12)], ids=["r=1", "r=1e-4", "r=1e-8", "r=1e-12"])
def test_ill_conditioned_exact_route_stays_exact_and_fast(kind: str, r: Fraction) -> None:
    """From r = 1e-4 on, sympy's trigonometric cubic formula evaluates cos(acos(x)/3) to 1
    (x within ~1e-8 of 1) and drops a term of the largest root: the exact route must see
    this (modes._agree) and answer with CRootOf instead, never the wrong closed form."""
    masses, springs = _chains(r)[kind]
    M, K = _chain_matrices(masses, springs)
    ref, _ = _mp_eigen(K, M)
    _, s = _solve(_chain(masses, springs), EXACT)
    assert all(not lam.has(sp.Float) for lam in s.answers.eigenvalues)
    for lam, x in zip(s.answers.eigenvalues, ref):
        assert abs(mpmath.mpf(str(sp.N(lam, 60))) - x) / abs(x) < mpmath.mpf(10) ** -40


def test_mass_singular_in_floating_point_is_refused_not_guessed() -> None:
    """m₃ = 1e-17: n ε κ(M) > 1, the numeric route refuses; the exact route answers."""
    text = _chain((1, 1, Fraction(1, 10**17)), (1, 1, 1))
    report, s = _solve(text, NUMERIC)
    assert s.answers is None and "singular in floating point" in s.error
    _strict(report)
    _, exact = _solve(text, EXACT)
    assert exact.error is None and len(exact.answers.eigenvalues) == 3


# --- 4. Unstable and neutral ----------------------------------------------------------------

# A particle m on a link l above a free cart of mass M (x, θ from the downward vertical),
# about θ = π: T = ½ (M + m) ẋ² + m l cos θ ẋ θ̇ + ½ m l² θ̇², V = −m g l cos θ, so
# M = [[M + m, −m l], [−m l, m l²]], K = [[0, 0], [0, −m g l]].
# det(K − λM) = λ ((M + m) m l² λ + (M + m) m g l − m² l² λ)... = λ (M m l² λ + (M + m) m g l):
# λ = 0 (a = (1, 0): the cart slides) and λ = −(M + m) g/(M l), γ = √((M + m) g/(M l)),
# a = (1, (M + m)/(m l)) from the first row −λ((M + m) a₁ − m l a₂) = 0.
CART = CART_PENDULUM + """\
values: {m: 1, M: 2, l: 1, g: 981/100}
questions:
  - modes: {about: {x: 0, theta: pi}}
"""


def test_exact_growth_rate_and_neutral_direction() -> None:
    report, s = _solve(CART, EXACT)
    a = s.answers
    sym = {x.name: x for x in a.M.free_symbols | a.K.free_symbols}
    M_, m, l, g = sym["M"], sym["m"], sym["l"], sym["g"]
    assert a.motions == (Motion.GROWTH, Motion.NEUTRAL)
    assert sp.simplify(a.eigenvalues[0] + (M_ + m) * g / (M_ * l)) == 0 and a.eigenvalues[1] == 0
    assert sp.simplify(a.growth_rates[0] - sp.sqrt((M_ + m) * g / (M_ * l))) == 0
    assert a.growth_rates[1] is None and a.frequencies == (None, None)
    assert sp.simplify(sp.Matrix(a.shapes[0]) - sp.Matrix([1, (M_ + m) / (m * l)])) == sp.zeros(2, 1)
    assert sp.Matrix(a.shapes[1]) == sp.Matrix([1, 0])
    data = _strict(report)
    assert data["results"][0]["values"]["growth_rates"][1] is None


def test_numeric_growth_rate_and_neutral_direction() -> None:
    report, s = _solve(CART, NUMERIC)
    a = s.answers
    lam = -Fraction(3, 2) * Fraction(981, 100)  # −(M + m) g/(M l) at M = 2, m = 1, l = 1
    assert a.motions == (Motion.GROWTH, Motion.NEUTRAL)
    assert abs(a.eigenvalues[0] - lam) <= a.absolute_errors[0] and abs(a.eigenvalues[1]) <= a.absolute_errors[1]
    gamma = mpmath.sqrt(mpmath.mpf(-lam.numerator) / lam.denominator)
    # γ = √(−λ): |Δγ| ≤ |Δλ|/(2γ) to first order, plus a rounding of γ itself
    assert abs(a.growth_rates[0] - gamma) <= a.absolute_errors[0] / (2 * gamma) * 1.01 + 1e-15 * gamma
    assert a.frequencies == (None, None) and a.growth_rates[1] is None
    assert abs(a.shapes[0][1] - 3) < 1e-12 and a.shapes[1] == (1.0, 0.0)
    data = _strict(report)
    assert data["results"][0]["answers"]["motions"] == ["growth", "neutral"]
    assert "γ" in " ".join(step.text for step in s.steps)
