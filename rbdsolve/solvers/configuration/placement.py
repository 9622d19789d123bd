"""Where the scene is for given coordinates, and where the coordinates fail to say it.

The placement φ(q) lists what the energies can see of a configuration: each body's
centre r_G, the rotation R of each body that has rotational inertia and turns, and each
spring's stretch. Two coordinate values describe the same configuration when their
placements are equal; the coordinates are singular at q₀ where the Jacobian ∂φ/∂q
loses rank there while it has full rank nearby (gimbal lock of three successive
turns at β = ±π/2; the pole of spherical angles). There ∂V/∂q = Jᵀ ∂V/∂φ = 0 is no
longer enough for an equilibrium: it tests fewer directions than the scene can move
in (e.g. Goldstein, ch. 4.4, on Euler angles at θ = 0).

The fibre test decides. Along a direction k of the kernel of J at q₀, the points
q₀ + t k with the same placement (a straight fibre, as gimbal lock's α ± γ = const)
are the same configuration written otherwise, and the coordinates there test other
directions: a nonzero ∂V/∂q at any of them shows that V changes to first order along
a path through the configuration, which is then no equilibrium; zero at all of them,
with their Jacobians together reaching the full rank, shows that it is one.

Rank and fibre tests are numeric: 30 digits, the parameters at their values or at fixed
random samples, rank against a relative 1e-20; they classify, never print, a number.
Float64 screens first (placement_screen.py): a point is regular where ∂φ/∂q has full
column rank by a margin no rounding can close (the 30-digit rank there is full too), and
two placements differ where an entry of φ(a) − φ(b) at the sampled parameters is far
larger than rounding could make of zero (no identity can cancel it).
"""

from __future__ import annotations

import random
from dataclasses import dataclass
from enum import Enum
from typing import Mapping

import mpmath as mp
import sympy as sp

from rbdsolve.form.tidy import tidy, tidy_fraction
from rbdsolve.model.build import Model
from rbdsolve.model.numeric.compiled import numpy_function
from rbdsolve.model.energies.energy import memoized, potential_energy
from rbdsolve.model.state import t
from rbdsolve.solvers.configuration.placement_screen import clearly_different, clearly_full_rank
from rbdsolve.model.values.values import parameter_sample

DIGITS = 30
APART = 1e-15  # a relative gap no 30-digit evaluation of equal values leaves
RANK_TOL = mp.mpf(10) ** -20
FIBRE_STEPS = (mp.mpf("0.37"), mp.mpf("1.3"), mp.mpf("-2.2"))

SUGGESTION = ("choose angles whose singular points lie away from the configurations asked about (e.g. "
              "turns in another order, or a triad that starts turned so that the lock falls elsewhere)")


class Verdict(Enum):
    EQUILIBRIUM = "equilibrium"  # the same configuration is an equilibrium in a regular chart too
    NOT_AN_EQUILIBRIUM = "not an equilibrium"  # ∂V/∂q ≠ 0 at the same configuration written otherwise
    UNDECIDED = "undecided"  # the fibre test could not decide


@dataclass(frozen=True)
class Singularity:
    """A singular point of the coordinates: the directions (numeric) of q that do not
    move the scene there, and the verdict of the fibre test with its reason."""

    kernel: tuple[tuple[float, ...], ...]
    verdict: Verdict
    reason: str


@memoized
def placement(model: Model) -> sp.Matrix:
    """φ(q): r_G of every body, R of every body with rotational inertia that turns, the
    stretch of every spring, stacked in one column. A body spun at a constant rate about
    an axis of symmetry (a last turn [z, s t], in a scene whose T holds no t) is placed
    as at t = 0: the spin moves nothing T or V sees."""
    parts: list[sp.Expr] = []
    for body in model.bodies:
        if body.position is not None:
            parts += list(body.position)
        if body.inertia != sp.zeros(3, 3) and (body.angle is not None or body.turns_3d):
            parts += list(body.rotation.xreplace({t: 0}) if body.turns else body.rotation)
    parts += [s.stretch for s in model.springs]
    return sp.Matrix(parts)


@memoized
def _jacobian(model: Model) -> sp.Matrix:
    return placement(model).jacobian(sp.Matrix(model.q))


@memoized
def _gradient(model: Model) -> sp.Matrix:
    V = potential_energy(model).total
    return sp.Matrix([sp.diff(V, q) for q in model.q])


@memoized
def _sample(model: Model) -> dict[sp.Symbol, sp.Expr]:
    """The parameters at their values, or at fixed random samples in [1.1, 2.9]."""
    return parameter_sample(model, random.Random(2026))


NUMERIC_TOL = mp.mpf(10) ** -7  # for a point known to floating-point accuracy only


def singularity(model: Model, at: Mapping[sp.Symbol, sp.Expr], tol=RANK_TOL) -> Singularity | None:
    """None where the coordinates are regular at ``at`` (or it is not real at the
    sampled parameters); else the kernel and the fibre test's verdict. ``tol``: the
    relative size below which a singular value, a change of placement and (times 10⁵)
    a gradient count as zero (NUMERIC_TOL for a floating-point root)."""
    if not model.q or placement(model).rows == 0:
        return None
    with mp.workdps(DIGITS):
        q0 = _point(model, at)
        if q0 is None or _clearly_regular(model, q0):  # the common case, without 30-digit work
            return None
        try:
            rank, kernel = _rank_and_kernel(_numeric_jacobian(model, q0), tol)
            if rank >= _generic_rank(model) or not kernel:
                return None
            verdict, reason = _fibre_test(model, q0, kernel, tol)
        except _NotFinite:  # the placement has no derivative there (a spring of zero length): no test
            return None
        shown = tuple(tuple(0.0 if abs(x) < 1e-15 else float(x) for x in k) for k in kernel)
        return Singularity(shown, verdict, reason)


def _point(model: Model, at: Mapping[sp.Symbol, sp.Expr]) -> list | None:
    """The coordinates at ``at``, the parameters sampled, to 30 digits; None where one is
    not real (its real part taken where the imaginary part is below 1e-12 of it), or not
    a number: a family of equilibria (x = √(L² − y²) for every y) is no one point."""
    parts = _complex_point(model, at)
    if not all(real.is_Number and imag.is_Number for real, imag in parts):
        return None
    if any(abs(imag) > 1e-12 * max(1, abs(real)) for real, imag in parts):
        return None
    with mp.workdps(DIGITS):
        return [mp.mpf(str(real)) for real, _ in parts]


def _float_point(model: Model, at: Mapping[sp.Symbol, sp.Expr]) -> list[float] | None:
    """The coordinates at ``at`` in float64, None unless each is a real number to far
    below a float's resolution (the screens must see the point the exact test sees)."""
    parts = _complex_point(model, at)
    if not all(real.is_Number and (imag == 0 or imag.is_Number and abs(imag) <= 1e-25 * max(1, abs(real)))
               for real, imag in parts):
        return None
    return [float(real) for real, _ in parts]


def _complex_point(model: Model, at: Mapping[sp.Symbol, sp.Expr]) -> tuple:
    """Real and imaginary part of each coordinate, 30 digits; kept per model (the listing
    asks about each solution several times)."""
    key = tuple(sp.sympify(at.get(q, 0)) for q in model.q)
    known = _points(model)
    if key not in known:
        sample = _sample(model)
        known[key] = tuple(sp.N(value.xreplace(sample), DIGITS).as_real_imag() for value in key)
    return known[key]


@memoized
def _points(model: Model) -> dict:
    return {}


@memoized
def _float_sample(model: Model) -> dict[sp.Symbol, float]:
    """The sampled parameters that are plain numbers, as floats (any other stops the screen)."""
    out = {}
    for s, v in _sample(model).items():
        try:
            out[s] = float(v)
        except TypeError:
            continue
    return out


def _clearly_regular(model: Model, q: list) -> bool:
    """∂φ/∂q at q of full column rank by the float64 screen: then its 30-digit rank is
    full as well, at least the generic rank, and singularity's answer is None."""
    return clearly_full_rank(list(placement(model)), model.q, [float(x) for x in q], _float_sample(model))


class _NotFinite(ArithmeticError):
    """A placement or its derivative is not a finite number at a point."""


def _evaluate(matrix: sp.Matrix, model: Model, q: list) -> mp.matrix:
    subs = {**_sample(model), **{qi: sp.Float(str(x), DIGITS) for qi, x in zip(model.q, q)}}
    values = [[sp.N(x.xreplace(subs), DIGITS) for x in matrix.row(i)] for i in range(matrix.rows)]
    if any(not v.is_finite or not v.is_real for row in values for v in row):
        raise _NotFinite
    return mp.matrix([[mp.mpf(v) for v in row] for row in values])


def _numeric_jacobian(model: Model, q: list) -> mp.matrix:
    return _evaluate(_jacobian(model), model, q)


@memoized
def _generic_rank(model: Model) -> int:
    """The rank of ∂φ/∂q at two random configurations (the larger)."""
    rng = random.Random(7)
    with mp.workdps(DIGITS):
        points = [[mp.mpf(rng.uniform(-3, 3)) for _ in model.q] for _ in range(2)]
        if all(_clearly_regular(model, p) for p in points):  # full column rank at both, by the screen
            return len(model.q)
        return max(_rank_and_kernel(_numeric_jacobian(model, p))[0] for p in points)


def _image_rank(J: mp.matrix, tol) -> int:
    """The dimension of the column space of J (rank of Jᵀ: svd wants rows ≥ cols)."""
    return _rank_and_kernel(J.T if J.rows < J.cols else J, tol)[0]


def _rank_and_kernel(J: mp.matrix, tol=RANK_TOL) -> tuple[int, list[list]]:
    """Rank of J (singular values above RANK_TOL × the largest) and a basis of its
    kernel (right singular vectors of the others)."""
    n = J.cols
    if J.rows < n:  # pad: svd wants rows ≥ cols
        J = mp.matrix([[J[i, j] if i < J.rows else 0 for j in range(n)] for i in range(n)])
    _, S, V = mp.svd_r(J)
    largest = max(abs(S[i]) for i in range(len(S))) or mp.mpf(1)
    rank = sum(1 for i in range(len(S)) if abs(S[i]) > tol * largest)
    kernel = [[V[i, j] for j in range(n)] for i in range(len(S)) if abs(S[i]) <= tol * largest]
    return rank, kernel


def _fibre_test(model: Model, q0: list, kernel: list[list], tol) -> tuple[Verdict, str]:
    """Walk each kernel direction; where the placement stays the same, ∂V/∂q decides."""
    phi0 = _evaluate(placement(model), model, q0)
    scale = max([abs(x) for x in phi0] + [mp.mpf(1)])
    gradient = _gradient(model)
    jacobians = [_numeric_jacobian(model, q0)]
    same_seen = False
    for k in kernel:
        for t in FIBRE_STEPS:
            q1 = [a + t * b for a, b in zip(q0, k)]
            if mp.norm(_evaluate(placement(model), model, q1) - phi0) > tol * scale:
                continue
            same_seen = True
            g = _evaluate(gradient, model, q1)
            if mp.norm(g) > 10**5 * tol * _force_scale(model, q1):
                where = ", ".join(f"{n} = {float(x):.6g}" for n, x in zip(model.coordinate_names(), q1))
                return (Verdict.NOT_AN_EQUILIBRIUM,
                        f"the same configuration is also written ({where}), where ∂V/∂q ≠ 0")
            jacobians.append(_numeric_jacobian(model, q1))
    if not same_seen:
        return Verdict.UNDECIDED, "the configurations along the lost directions could not be followed"
    # the images side by side: together they must span as many directions of the
    # scene's motion as the coordinates reach at a regular point
    rows = jacobians[0].rows
    side_by_side = mp.matrix([[J[i, j] for J in jacobians for j in range(J.cols)] for i in range(rows)])
    if _image_rank(side_by_side, tol) < _generic_rank(model):
        return Verdict.UNDECIDED, "the configurations along the lost directions do not test every direction"
    return Verdict.EQUILIBRIUM, "∂V/∂q = 0 also where the same configuration is written with regular coordinates"


def _force_scale(model: Model, q: list):
    """A size for ∂V/∂q: the largest |∂V/∂qᵢ| at two nearby generic points, at least 1."""
    rng = random.Random(11)
    sizes = [mp.norm(_evaluate(_gradient(model), model, [x + mp.mpf(rng.uniform(0.3, 1)) for x in q]))
             for _ in range(2)]
    return max(sizes + [mp.mpf(1)])


def exact_kernel(model: Model, at: Mapping[sp.Symbol, sp.Expr]) -> list[sp.Matrix]:
    """The kernel of ∂φ/∂q at ``at``, exactly (sin and cos reduced on the unit circle)."""
    J = _jacobian(model).xreplace(dict(at)).applyfunc(tidy_fraction)
    return [v.applyfunc(tidy) for v in J.nullspace(simplify=True)]


def same_placement(model: Model, a: Mapping[sp.Symbol, sp.Expr], b: Mapping[sp.Symbol, sp.Expr],
                   free: tuple[sp.Symbol, ...] = ()) -> bool:
    """Do ``a`` and ``b`` describe one configuration, for some values of the ``free``
    coordinates (those V does not depend on) in ``b``? Exact: φ(a) − φ(b) reduced with
    sin² + cos² = 1 vanishes, or, with free angles, the polynomial system in their sines
    and cosines on the unit circle has a real solution."""
    phi = placement(model)
    if _clearly_apart(model, a, b, free):  # the common case, without reducing anything
        return False
    left = phi.xreplace(dict(a))
    fixed = {q: v for q, v in b.items() if q not in free}
    right = phi.xreplace(fixed)
    if not _real_points(model, a, b) and _apart_off_the_reals(model, left, right, free):
        return False
    difference = [tidy_fraction(sp.expand_trig(x)) for x in (left - right)]
    if not free:
        return all(x == 0 for x in difference)
    return _solvable(difference, free, model)


def _clearly_apart(model: Model, a: Mapping[sp.Symbol, sp.Expr], b: Mapping[sp.Symbol, sp.Expr],
                   free: tuple[sp.Symbol, ...]) -> bool:
    """An entry of φ without a free coordinate differs between ``a`` and ``b`` at the
    sampled parameters (float64 screen): then it is not zero as an expression either,
    and same_placement's exact test would answer no."""
    entries = [e for e in placement(model) if not e.has(*free)]
    if not entries:
        return False
    left, right = _float_point(model, a), _float_point(model, b)
    if left is None or right is None:
        return False
    return clearly_different(entries, model.q, left, right, _float_sample(model))


def _real_points(model: Model, a: Mapping[sp.Symbol, sp.Expr], b: Mapping[sp.Symbol, sp.Expr]) -> bool:
    """Are both roots real points at the sampled parameters (``_clearly_apart`` has
    screened them in floats already)?"""
    return _float_point(model, a) is not None and _float_point(model, b) is not None


def _apart_off_the_reals(model: Model, left: sp.Matrix, right: sp.Matrix, free: tuple[sp.Symbol, ...]) -> bool:
    """An entry of φ(a) and φ(b) without a free coordinate clearly differs at the sampled
    parameters, each evaluated to 30 digits: the screen where ``_clearly_apart`` has no
    real point (acos(c) of a c past ±1 there). The roots are put in as written before
    evaluating (sin(acos(c)) is √(1 − c²) already), so each number is its expression's
    value at the sample, complex or not; they differ by far more than 30 digits' rounding
    only where the expressions differ too."""
    sample = _sample(model)
    for x, y in zip(left, right):
        if x.has(*free) or y.has(*free):
            continue
        u, v = (complex(z) if z.is_number and z.is_finite else None
                for z in (sp.N(e.xreplace(sample), DIGITS) for e in (x, y)))
        if u is not None and v is not None and abs(u - v) > APART * max(1.0, abs(u), abs(v)):
            return True
    return False


def _solvable(equations: list[sp.Expr], free: tuple[sp.Symbol, ...], model: Model) -> bool:
    s = {q: sp.Dummy(f"s_{q.name}", real=True) for q in free if q in model.angles}
    c = {q: sp.Dummy(f"c_{q.name}", real=True) for q in free if q in model.angles}
    system = [sp.numer(sp.together(e.xreplace({sp.sin(q): s[q] for q in s} | {sp.cos(q): c[q] for q in c})))
              for e in equations]
    system = [e for e in system if e != 0]
    if not system:
        return True
    unknowns = [*s.values(), *c.values(), *[q for q in free if q not in s]]
    if any(e.has(*free) for e in system):
        return False  # a free coordinate outside sin and cos: not decided here
    if any(not e.has(*unknowns) for e in system):
        return False  # a nonzero difference the free coordinates cannot change
    system += [s[q] ** 2 + c[q] ** 2 - 1 for q in s]
    roots = sp.solve(system, unknowns, dict=True)
    return any(all(sp.sympify(v).is_real is not False for v in r.values()) for r in roots)


def numeric_listing(model: Model, roots) -> tuple[list, list]:
    """The roots as the report lists them (as the exact route's ``listing``): those at
    singular points of the coordinates set apart unless the fibre test finds an
    equilibrium; roots that are one configuration (up to the continuum a root stands
    for) merged into the first, with the others as its equivalents."""
    kept: list[tuple] = []
    apart: list[tuple] = []
    for r in roots:
        at = dict(zip(model.q, r.at))
        singular = singularity(model, at, NUMERIC_TOL)
        if singular is not None and singular.verdict is not Verdict.EQUILIBRIUM:
            apart.append((r, singular))
            continue
        same = next((i for i, (k, _) in enumerate(kept)
                     if numeric_same_placement(model, dict(zip(model.q, k.at)), at, r.free)), None)
        if same is None:
            kept.append((r, []))
        else:
            kept[same][1].append(r)
    return [_nearest_zero_first(r, equivalent) for r, equivalent in kept], apart


def _nearest_zero_first(root, equivalent: list) -> tuple:
    """One configuration's roots with the one nearest q = 0 as it is written (the hanging
    double pendulum at (0, 0), not at (−10π, −10π) where the search met it first; of two
    as near, the one with fewer negative coordinates, else the first met), the others in
    order of their distance from q = 0."""
    ordered = sorted([root, *equivalent], key=lambda r: (round(sum(x * x for x in r.at), 9), sum(x < 0 for x in r.at)))
    return ordered[0], ordered[1:]


def numeric_same_placement(model: Model, a: Mapping[sp.Symbol, float], b: Mapping[sp.Symbol, float],
                           free: tuple[tuple[float, ...], ...] = ()) -> bool:
    """Floating-point ``same_placement``: φ(a) = φ(b + Σ tᵢ fᵢ) for some t along the
    directions ``free`` of a continuum b represents, to 1e-9 relative (least squares
    from starts across a turn in each t)."""
    import numpy as np

    phi = _compiled(model)
    target = phi(np.array([a[q] for q in model.q], dtype=float))
    base = np.array([b[q] for q in model.q], dtype=float)
    scale = max(1.0, float(np.max(np.abs(target))))
    directions = np.array(free, dtype=float).reshape(len(free), len(model.q))

    def residual(t):
        return (phi(base + t @ directions) - target) / scale

    if not free:
        return bool(np.max(np.abs(residual(np.zeros(0))), initial=0.0) <= 1e-9)
    # imported here, not above: ~0.27 s of a process, for a continuum only
    from scipy.optimize import least_squares

    for start in np.linspace(-np.pi, np.pi, 9):
        fit = least_squares(residual, np.full(len(free), start), xtol=1e-14, ftol=1e-14, gtol=1e-14)
        if np.max(np.abs(fit.fun)) <= 1e-9:
            return True
    return False


@memoized
def _compiled(model: Model):
    """φ(q) as a numpy function, the parameters at their values."""
    import numpy as np

    values = _sample(model)
    f = numpy_function([model.q], placement(model).xreplace(values))
    return lambda x: np.asarray(f(x), dtype=float).ravel()
