"""The numeric route (rbdsolve.model.numeric.numeric) against independent derivations.

* Every problem in problems/ with coordinates: M(q), ∂V/∂q and ∂²V/∂q² at random
  configurations against the symbolic model (build_model: M = Σ m J_vᵀ J_v + J_ωᵀ J_G J_ω
  from its bodies' Jacobians, and its V differentiated by mpmath.diff at 90 digits),
  evaluated to 60 digits: a code path independent of the jets. Float64 to 1e-12, MP50
  to 1e-40 (norm-wise relative).
* A scene that uses every allowed function, vector function, power, spring and shape
  feature, against the same symbolic model.
* An n-link chain against hand formulas at q = 0 (point masses and rods).
"""

from __future__ import annotations

import random
from fractions import Fraction

import mpmath
import numpy as np
import pytest
import scipy.linalg
import sympy as sp

from rbdsolve.model.symbols import exact_number

from rbdsolve.model.build import build_model
from rbdsolve.model.energies.energy import jacobians, potential_energy
from rbdsolve.model.numeric.numeric import FLOAT, MP50, NotNumeric, NumericScene
from rbdsolve.problem import load_file, load_text

from conftest import PROBLEMS, chain, hand_matrices

TOLERANCE = {FLOAT.name: 1e-12, MP50.name: 1e-40}
SAMPLE_VALUES = [Fraction(13, 10), Fraction(7, 10), Fraction(11, 10), Fraction(9, 10), Fraction(17, 10),
                 Fraction(6, 5), Fraction(3, 2), Fraction(4, 5)]
FILES = sorted(p for p in PROBLEMS.rglob("*.yaml") if not p.name.endswith(".expected.yaml"))


# --- helpers --------------------------------------------------------------------------


def sample_values(problem) -> dict[str, Fraction]:
    """The file's values, else fixed positive numbers in the order of declaration."""
    names = [p.name for p in problem.parameters] + list(problem.unknowns)
    given = problem.value_map()
    return {name: given.get(name, SAMPLE_VALUES[i % len(SAMPLE_VALUES)]) for i, name in enumerate(names)}


def configurations(problem, count: int = 3, values=None) -> list[list[Fraction]]:
    """Random configurations in [−1.5, 1.5] per coordinate, kept where the symbolic
    model's spring lengths hold: a stretch written u for |u| (model/energies/spring_length.py)
    is the model only while u keeps its sign, and the numeric scene keeps √(u²)."""
    rng = random.Random(str(problem.file))
    domain = _spring_domain(problem, values) if values is not None else []
    found = []
    for _ in range(50 * count):
        q = [Fraction(rng.randint(-1500, 1500), 1000) for _ in problem.coordinates]
        if all(holds(q) for holds in domain):
            found.append(q)
        if len(found) == count:
            break
    return found


def _spring_domain(problem, values) -> list:
    model = build_model(problem)
    subs = {s: exact_number(values[k]) for k, s in model.symbols.parameters.items() if k in values}
    tests = []
    for spring in model.springs:
        for length in spring.lengths:
            if length.sign is not None:
                u = sp.Integer(length.sign) * length.inside.xreplace(subs)
                tests.append(lambda q, u=u: u.xreplace(dict(zip(model.q, map(sp.Rational, q)))) > 0)
    return tests


_POTENTIALS: dict = {}


def symbolic(problem, values: dict[str, Fraction], q: list[Fraction]):
    """M from the symbolic model's Jacobians, and ∂V/∂q, ∂²V/∂q² of the symbolic model's
    V, as 60-digit mpmath values. V (values put in) is compiled once per scene and
    differentiated by mpmath's extrapolated differences at 90 digits: a code path
    independent of the jets, and unlike sympy's diff of a large V, it does not grow the
    expression (the scene with every function took minutes that way)."""
    key = (str(problem.file), tuple(sorted(values.items())))
    if key not in _POTENTIALS:
        _POTENTIALS[key] = _potential(problem, values)
    model, subs, V = _POTENTIALS[key]
    at = {qi: sp.Rational(x.numerator, x.denominator) for qi, x in zip(model.q, q)}
    grad, hess = derivatives_at(V, q)
    return mass_matrix_at(model, {**subs, **at}), grad, hess


def mass_matrix_at(model, at: dict) -> np.ndarray:
    """M = Σ (m J_vᵀ J_v + J_ωᵀ J_G J_ω) over the bodies, each Jacobian's entries put at
    the numbers ``at`` and evaluated to 60 digits, the products taken in mpmath (not
    energy.mass_matrix, which tidies M symbolically at the point first: 10 s of the
    scene with every function against 0.2 s)."""
    n = len(model.q)
    with mpmath.workdps(60):
        M = mpmath.zeros(n, n)
        for b in jacobians(model):
            J_v, J_w, J_G = (mpmath.matrix(to_mp(J.xreplace(at)).tolist()) for J in (b.J_v, b.J_w, b.J_G))
            mass = mpmath.mpf(sp.N(sp.sympify(b.body.mass).xreplace(at), 60))
            M += mass * J_v.T * J_v + J_w.T * J_G * J_w
        return np.array(M.tolist(), dtype=object)


def _potential(problem, values: dict[str, Fraction]):
    model = build_model(problem)
    subs = {s: exact_number(values[k]) for k, s in model.symbols.parameters.items()}
    V = potential_energy(model).total.xreplace(subs)
    return model, subs, sp.lambdify(list(model.q), V, modules="mpmath")


def derivatives_at(V, q: list[Fraction]) -> tuple[np.ndarray, np.ndarray]:
    """∂V/∂q_i and ∂²V/∂q_i∂q_j at q by mpmath.diff (Richardson-extrapolated central
    differences, working at 90 digits so that 60 are right)."""
    n = len(q)
    with mpmath.workdps(90):
        x = [mpmath.mpf(v.numerator) / v.denominator for v in q]

        def partial(orders):
            return mpmath.diff(lambda *y: V(*y), x, orders)

        unit = [[int(i == k) for k in range(n)] for i in range(n)]
        grad = np.array([[partial(unit[i])] for i in range(n)], dtype=object)
        hess = np.empty((n, n), dtype=object)
        for i in range(n):  # ∂²V/∂q_i∂q_j = ∂²V/∂q_j∂q_i: the upper half, mirrored
            for j in range(i, n):
                hess[i, j] = hess[j, i] = partial([a + b for a, b in zip(unit[i], unit[j])])
    return grad, hess


def to_mp(matrix: sp.Matrix) -> np.ndarray:
    with mpmath.workdps(60):
        return np.array([[mpmath.mpf(sp.N(x, 60)) for x in row] for row in matrix.tolist()], dtype=object)


def assert_close(numeric, reference, tol: float) -> None:
    """max |numeric − reference| ≤ tol · max |reference| (norm-wise relative; absolute
    when the reference is zero)."""
    with mpmath.workdps(60):
        a = np.array(numeric, dtype=object).reshape(-1)
        b = np.array(reference, dtype=object).reshape(-1)
        assert a.shape == b.shape
        err = max((abs(mpmath.mpf(x) - y) for x, y in zip(a, b)), default=mpmath.mpf(0))
        scale = max((abs(y) for y in b), default=mpmath.mpf(0))
        assert err <= tol * max(scale, mpmath.mpf(1) if scale == 0 else scale), (err, scale)


def check_against_symbolic(problem, values, arithmetics, configs) -> None:
    """Each arithmetic's scene against one symbolic reference per configuration (the
    reference is most of the cost: one test checks both arithmetics)."""
    scenes = [NumericScene.build(problem, values, arithmetic) for arithmetic in arithmetics]
    for q in configs:
        M_ref, grad_ref, hess_ref = symbolic(problem, values, q)
        for arithmetic, scene in zip(arithmetics, scenes):
            M = scene.mass_matrix(q)
            _, grad, hess = scene.potential(q)
            tol = TOLERANCE[arithmetic.name]
            assert_close(M, M_ref, tol)
            assert_close(grad, grad_ref, tol)
            assert_close(hess, hess_ref, tol)


# --- every problem file ---------------------------------------------------------------


@pytest.mark.parametrize("path", FILES, ids=lambda p: str(p.relative_to(PROBLEMS)))
def test_problem_files_against_the_symbolic_model(path) -> None:
    problem = load_file(path)
    if not problem.coordinates:
        pytest.skip("no generalized coordinates")
    values = sample_values(problem)
    try:
        NumericScene.build(problem, values, FLOAT)
    except NotNumeric as exc:
        pytest.skip(f"symbolic route: {exc}")
    configs = configurations(problem, values=values)
    assert len(configs) == 3, "too few configurations keep the springs' signs"
    check_against_symbolic(problem, values, (FLOAT, MP50), configs)


def test_some_problem_files_are_numeric() -> None:
    """The skips above must not hide everything: the seed exam's problem 1 runs."""
    problem = load_file(PROBLEMS / "sg2150-2015-10-29" / "p1-two-rods.yaml")
    assert NumericScene.build(problem, sample_values(problem)).n == 2


# --- every function and feature, in one scene -----------------------------------------

EVERYTHING = """
parameters: {m: mass, a: length, b: length, k: stiffness, c: torsional stiffness, g: gravity, p: exponent}
coordinates: [x, y, th]
gravity: [0, -g, -g/3]
points:
  A: [x, y, a*th]
  B: A + a*[tan(th/3) + cot(1 + th/5), sec(x/4) - csc(2 + y/5), asin(x/5) + acos(y/7)]
  C: B + b*[atan(x*y) + atan2(1 + y/4, 2 + x/3), sinh(x/3)*cosh(y/4), tanh(th)]
  D: C + [exp(x/4)*log(2 + y/3), sqrt(3 + x*y/5) + abs(th - 7), (2 + x/5)**p]
  W: D + cross(A, [1, 2, b]) / (3 + inner(A, A)) + norm(B - A) * [1, 0, 0]
  Z: W + [(1 + y**2)**(x/7), (y - 3)**3 / (4 + x**2)**2, (2 + th**2)**(1/3)]
bodies:
  bob: {shape: particle, mass: m, at: A}
  disk: {shape: disk, mass: 2*m, radius: a, at: B, angle: th + x}
  tilted: {shape: box, mass: m/2, width: a, depth: b, height: a + b, axis: [1, 2, 2], at: C, angle: x*y}
  holed:
    at: D
    angle: y**2
    parts:
      plate: {shape: plate, mass: 4*m, width: 2*a, height: 2*a}
      hole: {shape: disk, mass: m/3, radius: a/2, at: [a/2, a/3], hole: true}
      tip: {shape: triangle, mass: m, base: a, height: b, apex: a/3, at: [a, 0, b]}
  given: {inertia: [[2*m, m/5, 0], [m/5, m, 0], [0, 0, 3*m]], mass: m, at: Z, angle: sin(th)}
springs:
  s1: {stiffness: k, between: [A, W], natural_length: a}
  s2: {stiffness: 2*k, between: [B, [1, 2, 3]]}
  t1: {stiffness: c, angle: th + x/2, rest: pi/6}
questions: [modes]
"""


def test_every_function_against_the_symbolic_model() -> None:
    problem = load_text(EVERYTHING, "everything.yaml")
    values = {"m": Fraction(13, 10), "a": Fraction(7, 10), "b": Fraction(11, 10), "k": Fraction(5, 2),
              "c": Fraction(9, 10), "g": Fraction(981, 100), "p": Fraction(17, 10)}
    configs = [[Fraction(3, 10), Fraction(-1, 2), Fraction(7, 10)], [Fraction(-6, 5), Fraction(4, 5), Fraction(-1, 5)]]
    check_against_symbolic(problem, values, (FLOAT, MP50), configs)


# --- a chain against hand formulas ----------------------------------------------------


@pytest.mark.parametrize("rods", [False, True], ids=["particles", "rods"])
@pytest.mark.parametrize("n", [1, 5, 20])
def test_chain_against_hand_formulas(n: int, rods: bool) -> None:
    m, l, g = Fraction(13, 10), Fraction(7, 10), Fraction(981, 100)
    problem = load_text(chain(n, rods), "chain.yaml")
    M_hand, K_hand = hand_matrices(n, rods, m, l, g)
    scene = NumericScene.build(problem, {"m": m, "l": l, "g": g})
    M = scene.mass_matrix([0.0] * n)
    V, grad, K = scene.potential([0.0] * n)
    M_ref, K_ref = np.array(M_hand, dtype=float), np.array(K_hand, dtype=float)
    assert np.allclose(M, M_ref, rtol=1e-13, atol=0)
    assert np.abs(K - K_ref).max() <= 1e-13 * np.abs(K_ref).max()
    assert np.abs(grad).max() <= 1e-13 * np.abs(K_ref).max()  # q = 0 is an equilibrium
    eig = scipy.linalg.eigh(K, M, eigvals_only=True)
    eig_ref = scipy.linalg.eigh(K_ref, M_ref, eigvals_only=True)
    assert np.allclose(eig, eig_ref, rtol=1e-11, atol=0)
    assert np.all(eig > 0)  # hanging down is stable


@pytest.mark.parametrize("rods", [False, True], ids=["particles", "rods"])
def test_chain_in_50_digits(rods: bool) -> None:
    n = 8
    m, l, g = Fraction(13, 10), Fraction(7, 10), Fraction(981, 100)
    scene = NumericScene.build(load_text(chain(n, rods), "chain.yaml"), {"m": m, "l": l, "g": g}, MP50)
    M_hand, K_hand = hand_matrices(n, rods, m, l, g)
    with mpmath.workdps(60):
        to_mpf = np.vectorize(lambda x: mpmath.mpf(x.numerator) / x.denominator if x else mpmath.mpf(0),
                              otypes=[object])
        M_ref, K_ref = to_mpf(np.array(M_hand, dtype=object)), to_mpf(np.array(K_hand, dtype=object))
    assert_close(scene.mass_matrix([0] * n), M_ref, 1e-45)
    assert_close(scene.potential([0] * n)[2], K_ref, 1e-45)


def test_chain_at_a_random_configuration_against_the_symbolic_model() -> None:
    problem = load_text(chain(4, rods=True), "chain.yaml")
    values = {"m": Fraction(13, 10), "l": Fraction(7, 10), "g": Fraction(981, 100)}
    check_against_symbolic(problem, values, (FLOAT,), configurations(problem, 2))


# --- arithmetic, inputs and refusals --------------------------------------------------

PENDULUM = chain(1, rods=False)  # a particle on a light link: V = −m g l cos θ


def test_mp50_keeps_the_callers_precision_and_returns_mpf() -> None:
    before = mpmath.mp.dps
    scene = NumericScene.build(load_text(PENDULUM), {"m": 1, "l": 2, "g": Fraction(981, 100)}, MP50)
    M = scene.mass_matrix([Fraction(1, 3)])
    V, grad, hess = scene.potential([Fraction(1, 3)])
    assert mpmath.mp.dps == before
    assert all(isinstance(x, mpmath.mpf) for x in (V, *grad, *hess.ravel(), *M.ravel()))
    with mpmath.workdps(50):  # V = −m g l cos θ, ∂²V/∂θ² = m g l cos θ
        assert abs(hess[0, 0] - mpmath.mpf(981) / 100 * 2 * mpmath.cos(mpmath.mpf(1) / 3)) < mpmath.mpf(10) ** -48


def test_values_override_the_file_and_undeclared_ones_are_refused() -> None:
    problem = load_text(PENDULUM + "values: {m: 1, l: 1, g: 10}\n")
    assert NumericScene.build(problem, {}).mass_matrix([0.0])[0, 0] == 1.0
    assert NumericScene.build(problem, {"l": 3.0}).mass_matrix([0.0])[0, 0] == 9.0
    with pytest.raises(ValueError, match="undeclared parameters: zz"):
        NumericScene.build(problem, {"zz": 1.0})


@pytest.mark.parametrize(
    "text, words",
    [
        (PENDULUM, "no value for the parameters g, l, m"),
        (PENDULUM.replace("sin(th1)", "sin(th1 + t)"), "point 'P1' depends on time"),
        ((PROBLEMS / "examples" / "heavy-top-euler-angles.yaml").read_text(), "triads"),
        ((PROBLEMS / "frames" / "rotating-hoop-fast.yaml").read_text(), "moving frames"),
        ((PROBLEMS / "sg2150-2015-10-29" / "p5-accelerated-pendulum.yaml").read_text(), "prescribed motion"),
        ((PROBLEMS / "sg2150-2015-10-29" / "p2-rod-impact.yaml").read_text(), "velocit"),
        (PENDULUM.replace("bob1: {shape: particle, mass: m, at: P1}",
                          "bob1: {shape: disk, radius: l, mass: m, at: P1, orientation: [[x, th1]]}"),
         "3D orientation"),
    ],
    ids=["missing value", "time", "triads", "frames", "prescribed", "instant", "orientation"],
)
def test_what_needs_the_symbolic_route(text: str, words: str) -> None:
    problem = load_text(text, "scene.yaml")
    values = {} if "no value" in words else sample_values(problem)
    with pytest.raises(NotNumeric, match=words):
        NumericScene.build(problem, values)
