"""The floating-point routes' view of a model: M and K at a configuration as float
arrays, and the equilibria of ∂V/∂q = 0 found numerically.

M and K (``linearized``) come first from the scene itself (``NumericScene``: M(q) and V's
derivatives by forward-mode automatic differentiation of the scene's own expressions, in
floats); only where the scene needs the symbolic model (see NotNumeric) from the
model's exact velocity Jacobians and Hessian of V at the configuration, with the
parameter values put in and rounded once to floats.

Equilibria (``find_numeric``): V's gradient g(q) and Hessian H(q) likewise come from the
scene by automatic differentiation where it allows, else compiled from the symbolic V
with sympy's lambdify (``compiled_gradient``). The search box (``search_box``): a
declared range, else a periodic angle over one turn (one cell more each side, so a root
at ±π is bracketed whatever its rounding), else ±SEARCH_SCALE × the scene's largest
length; equilibria outside the box are not searched. An angle
along which ∂V/∂q is not 2π-periodic (``periodic_angles``: a torsional spring counts
turns) is searched as a length.

* One coordinate: a sign-change scan of g (``scan``: adaptive halving with a sampled
  Lipschitz exclusion test, bisection for each root, extrema of g for roots of
  even multiplicity). Complete, to round-off, under the assumption stated there (|g'|
  within twice its sampled size on each cell; roots more than the smallest cell, box
  width / 2**20, apart); intervals left when its evaluations run out are reported.
* More coordinates: Newton's method, damped where it would not lower |g| (newton.py),
  from every point of a grid over the box, GRID_POINTS per coordinate (fewer in higher
  dimension, at most MAX_STARTS starts; where even 2 per coordinate would exceed
  MAX_STARTS, a fixed pseudo-random sample of MAX_STARTS points instead). No
  completeness claim: an equilibrium whose basin of attraction misses every start is
  not found, and the report says so.

Roots are wrapped into (−π, π] along periodic angles and merged when closer than
MERGE_TOL. A root on a continuum of equilibria (a straight line along which ∂V/∂q
stays zero) is replaced by its family's representative with its free directions
(``continua``), so a family is reported once. Each root is classified from the
eigenvalues of H against CURVATURE_TOL × the Hessian's scale over the box
(``hessian_scale``): the tolerance covers the rounding of H and its change over the
root's own error (up to √ε at a double root of g), so a degenerate Hessian is called
singular (neutral along a continuum, else undetermined), never stable or unstable on
round-off. Where V's terms cancel everywhere (springs that balance a rod's weight at
any angle) ∂V/∂q and H are rounding noise over the whole box, and scales taken from
them are noise too: the root tolerance and the eigenvalues' zero are then floored at
their rounding, ROUNDING_UNITS n ε of the terms they sum (``root_tolerance``,
``curvature_rounding``).
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass
from typing import Mapping

import numpy as np
import sympy as sp

from rbdsolve.errors import UnsolvedError
from rbdsolve.form.printers import to_unicode, unicode_name
from rbdsolve.model.build import Model
from rbdsolve.model.energies.energy import hessian, mass_matrix, memoized, potential_energy, stiffness_matrix
from rbdsolve.model.numeric.compiled import numpy_function
from rbdsolve.model.numeric.numeric import FLOAT, NotNumeric, NumericScene, exact_fraction
from rbdsolve.solvers.configuration import contact_span
from rbdsolve.solvers.configuration.continua import free_directions, is_axis, null_count, representative
from rbdsolve.solvers.numeric.newton import from_starts
from rbdsolve.solvers.numeric.scan import CELLS as SCAN_CELLS
from rbdsolve.solvers.numeric.scan import scan
from rbdsolve.solvers.numeric.search_box import round_a_circle, search_box

GRID_POINTS = 24
MAX_STARTS = 4096
SAMPLE_SEED = 20151029  # fixed: the same starts, and the same answers, every run
SCALE_SAMPLES = 16
ROOT_TOL = 1e-10  # |∂V/∂q| relative to the scale of V's gradient
MERGE_TOL = 1e-6
PERIODIC_SAMPLES = 3
PERIODIC_TOL = 1e-8
CURVATURE_TOL = 1e-7  # a Hessian eigenvalue this small relative to hessian_scale counts as zero
ROUNDING_UNITS = 4  # a float ∂V/∂q or ∂²V/∂q² is within this many n ε of the terms it sums


def rounding(n: int, size: float) -> float:
    """How far a float quantity of n coordinates may be from its value: ROUNDING_UNITS
    n ε times ``size``, the sum of the terms' sizes it adds up."""
    return ROUNDING_UNITS * n * float(np.finfo(float).eps) * size


def to_floats(matrix: sp.Matrix, values: Mapping[sp.Symbol, sp.Expr]) -> np.ndarray:
    """An exact matrix with the parameter values put in, rounded once to floats."""
    filled = matrix.xreplace(dict(values))
    try:
        return np.array([[float(sp.N(x, 20)) for x in row] for row in filled.tolist()], dtype=float)
    except TypeError:
        raise UnsolvedError("a matrix entry is not a real number at the given values") from None


def as_floats(model: Model, about: Mapping[str, sp.Expr]) -> dict[str, float]:
    """A configuration (name -> exact or float value) as floats at the parameter values."""
    return {n: float(sp.N(v.xreplace(dict(model.values)), 20)) for n, v in about.items()}


def linearized(model: Model, about: Mapping[str, sp.Expr]) -> tuple[np.ndarray, np.ndarray, str]:
    """M and K at the configuration ``about`` (coordinate name -> value), as floats: by
    automatic differentiation on the scene's own expressions where the scene allows
    (``NumericScene``), else from the exact Jacobians and Hessian, rounded once."""
    scene = numeric_scene(model)
    if scene is not None:
        q0 = list(as_floats(model, about).values())
        M, K = finite(lambda x: np.stack(scene.linearized(x)), model)(q0)
        return M, (K + K.T) / 2, "by automatic differentiation of the scene"
    at = {q: about[name] for q, name in zip(model.q, model.coordinate_names())}
    M = to_floats(mass_matrix(model, at), model.values)
    K = to_floats(stiffness_matrix(potential_energy(model).total, model.q, at), model.values)
    return M, (K + K.T) / 2, "from the exact Jacobians and Hessian, rounded once"


def finite(evaluate, model: Model):
    """``evaluate`` at a configuration, as a float array, or an UnsolvedError where the
    scene has no finite value there, naming the causes this scene can have."""

    def at(x):
        try:
            with np.errstate(all="ignore"):
                value = np.asarray(evaluate(x), dtype=float)
        except (ArithmeticError, ValueError) as exc:
            raise UnsolvedError(f"M or V cannot be evaluated at q = {_shown(x)} ({exc}): "
                                f"{_causes(model, 'a square root or logarithm out of its domain')}?") from None
        if not np.all(np.isfinite(value)):
            raise UnsolvedError(f"M or V is not finite at q = {_shown(x)}: {_causes(model, 'a division by zero there')}?")
        return value

    return at


HUGE = 1e100  # a parameter value this far from 1 (or its inverse) can overflow a float in T or V


def _causes(model: Model, otherwise: str) -> str:
    """What makes T or V infinite in this scene: parameter values past floating point's
    range first, a spring of zero length only where there is a spring."""
    extreme = [f"{k} = {float(v):.3g}" for k, v in model.values.items()
               if v != 0 and not 1 / HUGE < abs(float(v)) < HUGE]
    causes = [f"an overflow of floating point from the parameter values ({', '.join(extreme)})"] if extreme else []
    if model.problem.springs:
        causes.append("a spring of zero length")
    return ", or ".join(causes + [otherwise])


def _shown(x) -> str:
    return "(" + ", ".join(f"{float(v):.6g}" for v in x) + ")"


def numeric_scene(model: Model, arithmetic=FLOAT) -> NumericScene | None:
    """The scene for floating-point evaluation, or None where it needs the symbolic model
    (3D orientations, frames, prescribed motion, …: see NotNumeric)."""
    return _float_scene(model) if arithmetic is FLOAT else _scene(model, arithmetic)


@memoized  # the gradient, the Hessian and M of one model share it
def _float_scene(model: Model) -> NumericScene | None:
    return _scene(model, FLOAT)


def _scene(model: Model, arithmetic) -> NumericScene | None:
    values = {str(k): exact_fraction(v) for k, v in model.values.items()}
    try:
        return NumericScene.build(model.problem, values, arithmetic, model.state)
    except NotNumeric:
        return None


def continuum_text(free: tuple[tuple[float, ...], ...], names: list[str]) -> str:
    """'every x is an equilibrium (a continuum); shown at x = 0', or the direction."""
    parts = []
    for v in free:
        axis = is_axis(v)
        if axis is not None:
            parts.append(f"every {names[axis]} is an equilibrium (a continuum); shown at {names[axis]} = 0")
        else:
            direction = ", ".join(f"{c:.6g}" for c in v)
            parts.append(f"the equilibria form a continuum along ({', '.join(names)}) ∝ ({direction}); "
                         "shown at its point nearest q = 0")
    return "; ".join(parts)


@memoized  # the search, the equilibria's error estimates and a refined 'about' share them
def compiled_gradient(model: Model):
    """g(q) = ∂V/∂q and H(q) = ∂²V/∂q∂q with the parameter values in, as numpy functions:
    from the numeric scene where it applies, else compiled from the symbolic V (once per
    model: lambdify is the costly part)."""
    scene = numeric_scene(model)
    if scene is not None:
        return finite(scene.gradient, model), finite(lambda x: scene.potential(x)[2], model)
    V = potential_energy(model).total.xreplace(dict(model.values))
    q = sp.symbols(f"x0:{len(model.q)}", real=True)  # so that d|x|/dx is sign(x), which lambdify prints
    V = V.xreplace(dict(zip(model.q, q)))
    grad = [sp.diff(V, x) for x in q]
    # ∂²|u|/∂q² = 2 δ(u) (∂u/∂q)²: 0 wherever u ≠ 0, and where u = 0 (a spring through
    # zero length) V has a kink and no Hessian at all; numpy has no DiracDelta
    H = hessian(V, tuple(q)).applyfunc(lambda e: e.replace(sp.DiracDelta, lambda *_: sp.Integer(0)))
    return finite(numpy_function([q], grad), model), finite(numpy_function([q], H.tolist()), model)


def scale_points(model: Model) -> np.ndarray:
    """The SCALE_SAMPLES fixed pseudo-random points of the search box at which the
    sizes of ∂V/∂q, of its terms and of the Hessian are sampled."""
    box = _box(model)
    low, high = np.array([b[0] for b in box]), np.array([b[1] for b in box])
    return low + np.random.default_rng(SAMPLE_SEED).random((SCALE_SAMPLES, len(box))) * (high - low)


def gradient_scale(model: Model, g) -> float:
    """The size of ∂V/∂q over the search box: roots are judged relative to it."""
    samples = []
    for x in scale_points(model):
        try:
            samples.append(np.max(np.abs(g(x)), initial=0.0))
        except UnsolvedError:  # a sample where V has no value tells nothing of its scale
            continue
    return max(max(samples, default=1.0), 1e-300)


@dataclass(frozen=True)
class Root:
    """An equilibrium found numerically: where, its kind ("stable" | "unstable" |
    "neutral", from the Hessian of V), the directions along which it is one point of a
    continuum of equilibria (unit vectors in coordinate order; empty when isolated),
    and whether V curves upward across them (H ≥ 0 with zero eigenvalues only along
    the free directions)."""

    at: tuple[float, ...]
    kind: str
    free: tuple[tuple[float, ...], ...] = ()
    stable_across: bool = False


@dataclass(frozen=True)
class NumericEquilibria:
    equilibria: tuple[Root, ...]
    starts: int  # Newton starts; in one coordinate, the points the scan evaluated
    sampling: str  # how the starts were placed: a grid, a fixed pseudo-random sample, or the scan
    unresolved: tuple[tuple[float, float], ...] = ()  # intervals the scan could not settle
    off_edge: tuple = ()  # contact_span.OffEdge's: roots where a contact point would leave its edge
    dropped: tuple[str, ...] = ()  # roots dropped where a spring's V is not its own (zero length, past it): why


@memoized
def find_numeric(model: Model) -> NumericEquilibria:
    """In one coordinate, the sign-change scan (``scan``); in more, Newton from every
    start (see the module's docstring). Each root is wrapped, replaced by its continuum's
    representative if it lies on one, classified against the Hessian's scale, and merged.
    Once per model: the equilibria question and the modes about the stable one ask for
    the same search (a particle on a spring on an incline: 5 s each)."""
    g, H = compiled_gradient(model)
    tol, curvature = root_tolerance(model), hessian_scale(model, H)
    if len(model.q) == 1:
        candidates, starts, sampling, unresolved = _scanned(model, g, H, tol)
    else:
        starts, sampling = _starts(model, GRID_POINTS)
        candidates, unresolved = from_starts(starts, g, H, lambda x, y: difference(model, x, y)), ()
    roots: list[Root] = []
    for x in candidates:
        try:
            found = _accepted(model, x, g, H, tol, curvature, roots)
        except UnsolvedError:  # Newton wandered where V has no value: this start finds nothing
            continue
        if found is not None:
            roots.append(found)
    kept, off = _on_edges(model, roots)
    kept, kinks = _off_kinks(model, kept)
    kept, past = _on_drawn_sides(model, kept)
    return NumericEquilibria(tuple(sorted(kept, key=lambda r: r.at)), len(starts), sampling, unresolved, off,
                             kinks + past)


KINK_TOL = 1e-9  # |u| at a root, relative to its terms' size, that counts as a spring of zero length


def _off_kinks(model: Model, roots: list[Root]) -> tuple[list[Root], tuple[str, ...]]:
    """The roots where no spring with a length |u| kept (its sign not decided: model/
    spring_length.py) has u = 0, and why each other one is not an equilibrium: there
    ½ k (|u| − l₀)² has a kink, ∂V/∂q jumps by 2 k l₀ |∂u/∂q| and numpy's sign(0) = 0
    makes it look like a root (a bead on a turning rod, its distance r from the axis the
    coordinate, on a spring of natural length l₀ from the axis: r = 0)."""
    held = [(s.name, x.inside.xreplace(dict(model.values))) for s in model.springs for x in s.lengths
            if x.sign is None]
    if not held:
        return roots, ()
    kept, dropped = [], []
    for r in roots:
        at = dict(zip(model.q, r.at))
        zero = [name for name, u in held if _vanishes_at(u, at)]
        if zero:
            dropped.append(f"{_shown_at(model, r)} solves ∂V/∂q = 0 only through sign(0) = 0: spring '{zero[0]}' has zero "
                           "length there, where V has a kink and no derivative; it is not listed")
        else:
            kept.append(r)
    return kept, tuple(dropped)


def _on_drawn_sides(model: Model, roots: list[Root]) -> tuple[list[Root], tuple[str, ...]]:
    """Where ∂V/∂q is compiled from the symbolic V (no numeric scene: a turning frame,
    applied loads), the roots where every spring length |u| written s·u has s·u ≥ 0
    (``held_sides``, as the exact route's existence asks), and why each other one is
    not an equilibrium: there V, written for s·u ≥ 0, is not the spring's. A bead on a
    turning rod, its spring's length |a + x| written a + x, with m Ω² > k: x = m Ω² a/
    (k − m Ω²) solves the compiled ∂V/∂q = 0 with a + x < 0, the bead past the axis,
    and was given as an equilibrium (the numeric scene keeps |u| itself)."""
    held = [(s.name, x.sign * x.inside) for s in model.springs for x in s.lengths if x.sign is not None]
    if not held or numeric_scene(model) is not None:
        return roots, ()
    valued = [(name, u, u.xreplace(dict(model.values))) for name, u in held]  # u written, u with the values in
    kept, dropped = [], []
    for r in roots:
        at = dict(zip(model.q, r.at))
        past = [(name, u) for name, u, number in valued if _negative_at(number, at)]
        if past:
            name, u = past[0]
            dropped.append(f"{_shown_at(model, r)} solves ∂V/∂q = 0 only with spring '{name}' past zero length "
                           f"({to_unicode(model.readable(u))} < 0 there, where V, written for it ≥ 0, is not the "
                           "spring's); it is not listed")
        else:
            kept.append(r)
    return kept, tuple(dropped)


def _shown_at(model: Model, root: Root) -> str:
    """'θ = 0.5, x = -1.2': where a dropped root lies, for its reason."""
    return ", ".join(f"{unicode_name(n)} = {float(v):.6g}" for n, v in zip(model.coordinate_names(), root.at))


def _negative_at(u: sp.Expr, at: dict) -> bool:
    """u < 0 at ``at``, beyond rounding relative to its terms' size."""
    value, size = _summed_at(u, at)
    return value.real < -KINK_TOL * size


def _vanishes_at(u: sp.Expr, at: dict) -> bool:
    value, size = _summed_at(u, at)
    return abs(value) <= KINK_TOL * size


def _summed_at(u: sp.Expr, at: dict) -> tuple[complex, float]:
    """u at ``at`` (20 digits, term by term) and the size of its terms (their |·| summed)."""
    terms = [complex(sp.N(t.xreplace(at), 20)) for t in sp.Add.make_args(sp.expand(u))]
    return sum(terms), max(sum(abs(t) for t in terms), 1e-300)


def _on_edges(model: Model, roots: list[Root]) -> tuple[list[Root], tuple]:
    """The roots with every contact point on its edge, and the others with the reason
    (solvers/configuration/contact_span.py)."""
    if not any(c.span is not None for c in model.contacts):
        return roots, ()
    kept, off = [], []
    for r in roots:
        at = {q: sp.Float(x, 17) for q, x in zip(model.q, r.at)}
        outside = contact_span.outside(model, at)
        (kept.append(r) if outside is None else off.append(outside))
    return kept, tuple(off)


def _scanned(model: Model, g, H, tol: float):
    """The scan's candidate roots in the one coordinate, the points it evaluated,
    its description and the intervals it left unresolved."""
    (low, high), = _box(model)
    if model.q[0] in periodic_angles(model):  # one cell more each side: a root at ±π, whatever its rounding
        low, high = low - (high - low) / SCAN_CELLS, high + (high - low) / SCAN_CELLS
    result = scan(_slope_and_curvature(model, g, H), low, high, tol)
    sampling = (f"points ({SCAN_CELLS} cells over [{low:.6g}, {high:.6g}], halved where they may hold a root, "
                f"down to {result.smallest:.3g})")
    return [np.array([x]) for x in result.roots], list(range(result.evaluations)), sampling, result.unresolved


def _slope_and_curvature(model: Model, g, H):
    """x -> (∂V/∂q, ∂²V/∂q²) in one coordinate: one pass of the scene's automatic
    differentiation where it applies, else the two compiled functions."""
    scene = numeric_scene(model)
    if scene is None:
        return lambda x: (g(np.array([x]))[0], H(np.array([x]))[0][0])
    both = finite(lambda x: _first_derivatives(scene.potential(x)), model)
    return lambda x: tuple(both(np.array([x])))


def _first_derivatives(potential) -> list[float]:
    """(∂V/∂q, ∂²V/∂q²) from the scene's (V, gradient, Hessian) in one coordinate."""
    _, gradient, hess = potential
    return [float(np.asarray(gradient, dtype=float).ravel()[0]), float(np.asarray(hess, dtype=float).ravel()[0])]


def _accepted(model: Model, x, g, H, tol: float, curvature: float, roots: list[Root]) -> Root | None:
    """The candidate x as a new Root, or None: not a root, outside the box, or one
    already found (on a family found, or within MERGE_TOL of a root)."""
    if x is None:
        return None
    x = _wrapped(model, x)
    if np.max(np.abs(g(x))) > tol or not _inside(model, x) or _on_a_family(model, x, roots):
        return None
    found = _as_root(model, x, g, H, tol, curvature)
    if any(np.max(np.abs(difference(model, np.array(found.at), np.array(r.at)))) <= MERGE_TOL for r in roots):
        return None
    return found


def _on_a_family(model: Model, x: np.ndarray, roots: list[Root]) -> bool:
    """x differs from a continuum's representative only along its free directions."""
    for r in roots:
        if r.free:
            d = difference(model, x, np.array(r.at))
            F = np.array(r.free, dtype=float).T
            if np.max(np.abs(d - F @ (F.T @ d))) <= MERGE_TOL:
                return True
    return False


def _as_root(model: Model, x: np.ndarray, g, H, tol: float, curvature: float) -> Root:
    """The root x classified, or its continuum's representative with the free directions."""
    hess = np.asarray(H(x), dtype=float)
    half_widths = [(hi - lo) / 2 for lo, hi in _box(model)]
    floor = curvature_rounding(model, x)
    free = free_directions(x, g, hess, half_widths, tol, floor) if null_count(hess, floor) else ()
    if free:
        rep = _wrapped(model, representative(x, free))
        if np.max(np.abs(g(rep))) <= tol:
            x, hess = rep, np.asarray(H(rep), dtype=float)
            floor = curvature_rounding(model, x)
        else:
            free = ()
    kind = _kind(hess, curvature, floor)
    across = bool(free) and kind == "singular" and null_count(hess, floor) == len(free)
    if kind == "singular":
        kind = "neutral" if across else "undetermined"
    return Root(tuple(float(v) for v in x), kind, free, across)


def _kind(H: np.ndarray, curvature: float, floor: float = 0.0) -> str:
    """stable (every eigenvalue of H above CURVATURE_TOL × curvature, and above H's
    rounding ``floor``), unstable (one below −that), else singular: zero within the
    tolerance, which rounding cannot decide (the caller makes it neutral along a
    continuum, else undetermined)."""
    eig = np.linalg.eigvalsh((H + H.T) / 2)
    tol = max(CURVATURE_TOL * max(curvature, np.max(np.abs(eig), initial=0.0)), floor)
    if np.all(eig > tol):
        return "stable"
    if np.any(eig < -tol):
        return "unstable"
    return "singular"


def curvature_rounding(model: Model, x: np.ndarray) -> float:
    """The rounding of the Hessian's eigenvalues at x: ROUNDING_UNITS n ε ‖Σ |∂²(term)/
    ∂q∂q|‖₂ (each entry is within n ε of the terms it sums; 0 where there is no numeric
    scene). Where the terms cancel (K = (2 a² k − ½ m g l) cos θ = 0 at the values) an
    eigenvalue this small is noise, not a sign."""
    scene = numeric_scene(model)
    if scene is None:
        return 0.0
    with np.errstate(all="ignore"):
        size = float(np.linalg.norm(scene.term_curvatures(x), 2))
    return rounding(len(model.q), size) if math.isfinite(size) else 0.0


@memoized
def root_tolerance(model: Model) -> float:
    """|∂V/∂q| that counts as zero: ROOT_TOL of its size over the box, and never less
    than its rounding, ROUNDING_UNITS n ε of the terms it sums (``term_slopes``). Where
    the terms cancel at every point (springs that balance a rod's weight at any angle:
    ∂V/∂q = (2 a² k − ½ m g l) sin θ = 0 at the values given) its size is rounding
    noise alone, and a tolerance relative to that took each noise's sign change for a
    root: thousands of them, past any budget."""
    return max(ROOT_TOL * slope_scale(model), _slope_rounding(model))


def _slope_rounding(model: Model) -> float:
    """ROUNDING_UNITS n ε times the largest Σ |∂(term)/∂q| at the sample points of
    ``gradient_scale`` (0 where there is no numeric scene to split V into its terms)."""
    scene = numeric_scene(model)
    if scene is None:
        return 0.0
    sizes = [0.0]
    for x in scale_points(model):
        with np.errstate(all="ignore"):
            size = float(np.max(scene.term_slopes(x)))
        if math.isfinite(size):  # a sample where V has no value tells nothing of its rounding
            sizes.append(size)
    return rounding(len(model.q), max(sizes))


@memoized
def slope_scale(model: Model) -> float:
    """``gradient_scale`` with the model's own compiled gradient, once per model."""
    return gradient_scale(model, compiled_gradient(model)[0])


def hessian_scale(model: Model, H) -> float:
    """The size of ∂²V/∂q∂q over the search box (the largest |eigenvalue| at the
    sample points of ``gradient_scale``): curvatures are judged zero relative to it."""
    sizes = []
    for x in scale_points(model):
        try:
            hess = np.asarray(H(x), dtype=float)
        except UnsolvedError:
            continue
        sizes.append(np.max(np.abs(np.linalg.eigvalsh((hess + hess.T) / 2)), initial=0.0))
    return max(max(sizes, default=1.0), 1e-300)


@memoized  # asked for each candidate root
def _box(model: Model) -> tuple[tuple[float, float], ...]:
    """The search box (``search_box``: declared ranges, one turn, the scene's lengths)."""
    return tuple((i.low, i.high) for i in search_box(model, periodic_angles(model)))


@memoized
def periodic_angles(model: Model) -> frozenset:
    """The angle coordinates along which ∂V/∂q is 2π-periodic: an angle that also enters
    V bare (a torsional spring counts turns) is searched, wrapped and merged as a length
    instead.

    Where V is only gravity and springs (no inertial potential of a moving frame), the
    build has already proved it for every angle of ``model.angles``: each enters the
    positions and stretches only through sin and cos of integer multiples of itself
    (model.build: ``_periodic_coordinates``, ``_refuse_winding_angles``), and masses,
    stiffnesses and gravity are constants. Otherwise it is checked at PERIODIC_SAMPLES
    points to PERIODIC_TOL. A contact's travel round a fixed circle (``along`` it,
    searched as an angle that winds up: search_box.py) is one too where ∂V/∂q is checked
    the same after a turn: a uniform wheel inside a cylinder, V = −m g (R − r) cos θ,
    has its equilibria at 0 and π, not again at ±2π, ±4π … (its roll differs there, not
    its V)."""
    travels = round_a_circle(model) - model.angles
    if not model.angles and not travels:
        return frozenset()
    declared = model.angles if not model.inertial else _periodic(model, model.angles, True)
    return declared | (_periodic(model, travels, False) if travels else frozenset())


def _periodic(model: Model, candidates: frozenset, declared: bool) -> frozenset:
    """The candidates along which ∂V/∂q is the same after a turn at every sample point;
    ``declared``: what an undecidable sample says (the declared kind is kept)."""
    g, _ = compiled_gradient(model)
    rng = np.random.default_rng(SAMPLE_SEED)
    points = [np.array([rng.uniform(-math.pi, math.pi) for _ in model.q]) for _ in range(PERIODIC_SAMPLES)]
    periodic = set()
    for i, q in enumerate(model.q):
        if q in candidates and all(_same_after_a_turn(g, x, i, declared) for x in points):
            periodic.add(q)
    return frozenset(periodic)


def _same_after_a_turn(g, x: np.ndarray, i: int, declared: bool = True) -> bool:
    turned = x.copy()
    turned[i] += 2 * math.pi
    try:
        a, b = np.asarray(g(x), dtype=float), np.asarray(g(turned), dtype=float)
    except UnsolvedError:
        return declared  # no value to compare: keep the declared kind
    return bool(np.max(np.abs(a - b), initial=0.0) <= PERIODIC_TOL * max(np.max(np.abs(a)), np.max(np.abs(b)), 1e-300))


def _starts(model: Model, per_axis: int) -> tuple[list[np.ndarray], str]:
    """A grid of per_axis points on each coordinate, cell-centred, while it has at most
    MAX_STARTS points; in more dimensions MAX_STARTS points of a fixed pseudo-random
    sample of the box instead (the same every run). With a description of which."""
    n, box = len(model.q), _box(model)
    per_axis = min(per_axis, int(MAX_STARTS ** (1 / n)))
    if per_axis >= 2:
        axes = [np.linspace(lo, hi, per_axis, endpoint=False) + (hi - lo) / (2 * per_axis) for lo, hi in box]
        grid = " × ".join([str(per_axis)] * n)
        return [np.array(p) for p in itertools.product(*axes)], "starts on a " + (f"{grid} grid" if n > 1 else "grid")
    low, high = np.array([b[0] for b in box]), np.array([b[1] for b in box])
    sample = np.random.default_rng(SAMPLE_SEED).random((MAX_STARTS, n))
    return list(low + sample * (high - low)), (f"starts at fixed pseudo-random points (a grid of even 2 per "
                                               f"coordinate would exceed {MAX_STARTS} starts in {n} dimensions)")


def _wrapped(model: Model, x: np.ndarray) -> np.ndarray:
    """Angles into (−π, π]."""
    out = np.array(x, dtype=float)
    angles = periodic_angles(model)
    for i, q in enumerate(model.q):
        if q in angles:
            out[i] = math.pi - (math.pi - out[i]) % (2 * math.pi)
    return out


def difference(model: Model, x: np.ndarray, y: np.ndarray) -> np.ndarray:
    d = x - y
    angles = periodic_angles(model)
    for i, q in enumerate(model.q):
        if q in angles:
            d[i] = (d[i] + math.pi) % (2 * math.pi) - math.pi
    return d


def _inside(model: Model, x: np.ndarray) -> bool:
    return all(lo - 1e-12 <= v <= hi + 1e-12 for v, (lo, hi) in zip(x, _box(model)))
