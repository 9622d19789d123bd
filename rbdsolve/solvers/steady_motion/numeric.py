"""Steady motion, the floating-point route: the rolling conditions and the balances are
formed as on the exact route (``steady_motion.setup``, ``rolling_velocities``,
``balances``, each component made a relation = 0 by ``steady_motion.relation``), but
the unknown rates are left in them; then every parameter value is put in and the
relations are solved together, in floats, for the unknowns: the declared ``unknowns``
(spin rates, the reactions' N, x_N, …) and the parameters in ``solve_for`` (omega0 in
``solve_for: omega0**2``), which need no value here.

Strategy: scipy.optimize.least_squares (Levenberg–Marquardt; 'trf' with fewer relations
than unknowns) from STARTS starts, x = 0 and a fixed pseudo-random sample in the box
±max(1, the largest parameter value) per unknown, each polished by Gauss–Newton steps.
A point is a solution when every relation's residual is within ROOT_TOL of its size,
Σ|term| + Σ_j |∂r/∂x_j| max(|x_j|, 1). Solutions closer than MERGE_TOL are merged; a positive parameter
solved for keeps its positive roots only (as on the exact route). A solution whose
basin misses every start is not found: a warning says so.

Error estimate (first order, e.g. Kelley, Iterative Methods for Linear and Nonlinear
Equations, §5.1): with the relations scaled by their sizes (W) and the unknowns by
max(|x|, 1) (D), δx ≈ −D (W J D)⁺ W r, so each unknown's absolute error is bounded by
|D (W J D)⁺| (|W r| + ρ), the residual left plus ρ = ROUNDING ε, the rounding of the
relations (and of the values) to floats. A quantity f(x) (ω, a ``solve_for``
expression) gets |∇f| δx + ROUNDING ε |f|. ``error_estimate`` is the largest of these
bounds over the value, among the values that are not zero within their bound. A
Jacobian singular at a solution (σ_min/σ_max of W J D below SINGULAR_TOL: a double root,
or a quantity the relations leave open) is refused when the open directions touch an
asked quantity or ω; an unknown nobody asked for that the relations leave open is
reported as null, with a warning.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import sympy as sp

from rbdsolve.errors import UnsolvedError
from rbdsolve.form.tidy import tidy_fraction
from rbdsolve.model.build import Model
from rbdsolve.model.numeric.compiled import numpy_function
from rbdsolve.problem.options import SteadyMotionOptions
from rbdsolve.problem.schema import Question
from rbdsolve.report.steps import Route, Solution
from rbdsolve.solvers.routes.options import Options
from rbdsolve.solvers.routes.needed import require_values
from rbdsolve.solvers.steady_motion.answers import NumericSteadyMotion, NumericSteadyMotionAnswers
from rbdsolve.solvers.steady_motion.balances import (
    angle_unknown,
    balances,
    relation,
    rolling_velocities,
    setup,
    twin,
)
from rbdsolve.solvers.steady_motion.steps import numeric_steps

EPS = float(np.finfo(float).eps)
STARTS = 24
SAMPLE_SEED = 20151029  # fixed: the same starts, and the same answers, every run
ROOT_TOL = 1e-10  # a relation's residual relative to the size of its terms
MERGE_TOL = 1e-6
SINGULAR_TOL = 1e-6  # σ_min/σ_max of the scaled Jacobian: a root found to √ε shows about √ε
ROUNDING = 8  # ε's per relation (and per quantity) for rounding the values and the evaluation
POLISH = 3  # Gauss–Newton steps after the least-squares search


@dataclass(frozen=True)
class _System:
    """The relations with the values put in, compiled: F(x), J(x), and the size of each
    relation's terms T(x), over the unknowns x."""

    unknowns: tuple[sp.Symbol, ...]
    relations: tuple[sp.Expr, ...]
    F: object  # each a function of the unknowns' vector x
    J: object
    T: object


def solve(question: Question, model: Model, options: Options) -> Solution:
    opts: SteadyMotionOptions = question.options
    targets = tuple(model.symbols.scalar(x) for x in opts.solve_for)
    free = _free_parameters(targets, model)
    require_values(model, "the numeric route", tuple(str(s) for s in free))
    k, vectors = setup(opts, model)
    omega, v_G = k.omega(), k.velocity(k.body.position)
    rolling = [x for v in rolling_velocities(opts, model, k, omega, v_G) for x in v]
    b = balances(opts, model, k, {}, omega, v_G)
    relations = tuple(relation(x, None) for x in (*rolling, *b.components) if tidy_fraction(x) != 0)
    system = _compile(relations, _unknowns(model, free, relations, opts), model)
    roots, closest = _search(system, _scale(model))
    kept = [_turned(x, system) for x in roots if _admissible(x, system.unknowns, free)]
    if not kept:
        raise UnsolvedError(_none_found(roots, free, closest))
    quantities = _Quantities.of(b.omega, targets, opts, system.unknowns, model)
    solutions = _once(_distinct([_analyse(x, system, quantities) for x in kept]), system, model)
    answers = NumericSteadyMotionAnswers(vectors, relations, _summary([s.angular_velocity for s in solutions]),
                                         _solved_summary(solutions), tuple(solutions), STARTS)
    return Solution("steady_motion", Route.NUMERIC, answers, numeric_steps(answers, opts, omega, v_G, model),
                    warnings=_warnings(solutions), error_estimate=_estimate(solutions))


def _free_parameters(targets: tuple[sp.Expr, ...], model: Model) -> tuple[sp.Symbol, ...]:
    """The parameters a solve_for expression holds (omega0 in omega0**2): unknowns here."""
    params = [model.symbols.parameters[p.name] for p in model.problem.parameters]
    held = set().union(*(x.free_symbols for x in targets)) if targets else set()
    return tuple(s for s in params if s in held)


def _unknowns(model: Model, free, relations, opts: SteadyMotionOptions) -> tuple[sp.Symbol, ...]:
    """The declared unknowns and the solve_for parameters that some relation holds; a
    solve_for quantity that none holds is refused."""
    held = set().union(*(r.free_symbols for r in relations)) if relations else set()
    declared = [model.symbols.parameters[u] for u in model.problem.unknowns]
    wanted = [*declared, *free]
    missing = [s for s in free if s not in held]
    asked = set().union(*(model.symbols.scalar(x).free_symbols for x in opts.solve_for)) if opts.solve_for else set()
    missing += [s for s in declared if s in asked and s not in held]
    if missing or not relations:
        raise UnsolvedError(f"no relation holds {', '.join(map(str, missing)) or 'anything'}: "
                            "nothing to solve for it")
    return tuple(s for s in wanted if s in held)


def _compile(relations, unknowns, model: Model) -> _System:
    """F, J and the term sizes T as numpy functions of the unknowns, the values put in."""
    values = {s: v for s, v in model.values.items() if s not in unknowns}
    filled = [r.xreplace(values) for r in relations]
    left = set().union(*(r.free_symbols for r in filled)) - set(unknowns)
    if left:
        raise UnsolvedError(f"the relations still hold {', '.join(sorted(map(str, left)))} with the values put in")
    x = sp.Matrix(unknowns)
    F = sp.Matrix(filled)
    sizes = [sum((sp.Abs(term) for term in sp.Add.make_args(sp.expand(r))), sp.Integer(0)) for r in filled]
    return _System(tuple(unknowns), tuple(relations), numpy_function([x], F),
                   numpy_function([x], F.jacobian(x)), numpy_function([x], sp.Matrix(sizes)))


def _scale(model: Model) -> float:
    return max([1.0, *(abs(float(v)) for v in model.values.values())])


def _call(f, x: np.ndarray) -> np.ndarray:
    with np.errstate(all="ignore"):
        return np.asarray(f(x), dtype=float)


def _search(system: _System, scale: float) -> tuple[list[np.ndarray], float]:
    """Least squares from every start, polished; the points where every relation holds
    within ROOT_TOL of its terms' size, and the smallest such relative residual found."""
    from scipy.optimize import least_squares

    n, m = len(system.unknowns), len(system.relations)
    rng = np.random.default_rng(SAMPLE_SEED)
    starts = [np.zeros(n), *rng.uniform(-scale, scale, size=(STARTS - 1, n))]
    method = "lm" if m >= n else "trf"
    roots, closest = [], float("inf")
    for x0 in starts:
        try:
            fit = least_squares(lambda x: _call(system.F, x).ravel(), x0, lambda x: _call(system.J, x),
                                method=method, xtol=1e-15, ftol=1e-15, gtol=1e-15, max_nfev=100 * (n + 1))
        except ValueError:  # a start where a relation is not finite
            continue
        x = _polish(system, fit.x)
        residual = _relative_residual(system, x) if x is not None else float("inf")
        closest = min(closest, residual)
        if residual <= ROOT_TOL:
            roots.append(x)
    return roots, closest


def _polish(system: _System, x: np.ndarray) -> np.ndarray | None:
    for _ in range(POLISH):
        r, J = _call(system.F, x).ravel(), _call(system.J, x)
        if not (np.all(np.isfinite(r)) and np.all(np.isfinite(J))):
            return None
        x = x - np.linalg.lstsq(J, r, rcond=None)[0]
    return x if np.all(np.isfinite(x)) else None


def _relative_residual(system: _System, x: np.ndarray) -> float:
    r, T = np.abs(_call(system.F, x).ravel()), _sizes(system, x)
    if not (np.all(np.isfinite(r)) and np.all(np.isfinite(T))):
        return float("inf")
    return float(np.max(np.where(T > 0, r / np.where(T > 0, T, 1.0), r), initial=0.0))


def _sizes(system: _System, x: np.ndarray) -> np.ndarray:
    """Each relation's size at x: Σ|term| + Σ_j |∂r/∂x_j| max(|x_j|, 1), so that a
    relation of one term (F2 = 0) is measured against the unknown's scale, not itself."""
    J = _call(system.J, x)
    return _call(system.T, x).ravel() + np.abs(J) @ np.maximum(np.abs(x), 1.0)


def _admissible(x: np.ndarray, unknowns, free) -> bool:
    """A positive parameter solved for (omega0) takes its positive roots only."""
    return all(x[unknowns.index(s)] > MERGE_TOL for s in free if s.is_positive)


def _none_found(roots: list[np.ndarray], free, closest: float) -> str:
    if roots:
        names = ", ".join(str(s) for s in free if s.is_positive)
        return (f"the relations' real solutions all have {names} ≤ 0 (within {MERGE_TOL:g}), and {names} "
                f"{'is' if ',' not in names else 'are'} declared positive: no such steady motion")
    return (f"least squares from {STARTS} starts found no solution of the relations (each within {ROOT_TOL:g} "
            f"of the size of its terms; the closest left a relation at {closest:.2g} of it): no such steady "
            "motion at these values, or one whose basin of attraction misses every start")


@dataclass(frozen=True)
class _Quantities:
    """What the answers evaluate at a solution: ω's components, then each solve_for
    expression, with their gradients and term sizes, compiled over the unknowns."""

    names: tuple[str, ...]
    needs: frozenset[int]  # the unknowns (indices) they hold
    f: object
    grad: object
    sizes: object

    @staticmethod
    def of(omega, targets, opts: SteadyMotionOptions, unknowns, model: Model) -> _Quantities:
        values = {s: v for s, v in model.values.items() if s not in unknowns}
        exprs = sp.Matrix([*omega, *targets]).xreplace(values)
        x = sp.Matrix(unknowns)
        sizes = [sum((sp.Abs(term) for term in sp.Add.make_args(sp.expand(e))), sp.Integer(0)) for e in exprs]
        needs = frozenset(i for i, u in enumerate(unknowns) if exprs.has(u))
        names = ("omega1", "omega2", "omega3", *(q.text for q in opts.solve_for))
        return _Quantities(names, needs, numpy_function([x], exprs),
                           numpy_function([x], exprs.jacobian(x)), numpy_function([x], sp.Matrix(sizes)))


def _analyse(x: np.ndarray, system: _System, quantities: _Quantities) -> NumericSteadyMotion:
    """The values at a solution and their first-order bounds; refused where the Jacobian
    is singular in a direction an answer depends on."""
    r, J, T = _call(system.F, x).ravel(), _call(system.J, x), _sizes(system, x)
    W = 1.0 / np.where(T > 0, T, 1.0)
    D = np.maximum(np.abs(x), 1.0)
    A = (W[:, None] * J) * D[None, :]
    open_ = _open(A)
    if open_ & quantities.needs:
        raise UnsolvedError(_singular(x, system, open_ & quantities.needs, A))
    dx = D * (np.abs(np.linalg.pinv(A, rcond=SINGULAR_TOL)) @ (np.abs(W * r) + ROUNDING * EPS))
    q, G, S = _call(quantities.f, x).ravel(), _call(quantities.grad, x), _call(quantities.sizes, x).ravel()
    dq = np.abs(G) @ dx + ROUNDING * EPS * S
    names = [str(u) for u in system.unknowns]
    unknowns = {n: (None if i in open_ else float(v)) for i, (n, v) in enumerate(zip(names, x))}
    errors = {n: float(e) for i, (n, e) in enumerate(zip(names, dx)) if i not in open_}
    errors.update({n: float(e) for n, e in zip(quantities.names, dq)})
    solved = {n: float(v) for n, v in zip(quantities.names[3:], q[3:])}
    return NumericSteadyMotion(unknowns, tuple(float(v) for v in q[:3]), solved, tuple(float(v) for v in r), errors)


def _open(A: np.ndarray) -> frozenset[int]:
    """The unknowns (indices) along the Jacobian's null directions: σ below SINGULAR_TOL σ_max,
    or missing (fewer relations than unknowns)."""
    _, s, Vt = np.linalg.svd(A)
    rank = int(np.sum(s > SINGULAR_TOL * (s[0] if s.size else 0.0))) if s.size else 0
    null = Vt[rank:]
    return frozenset(int(i) for i in np.flatnonzero(np.sum(null**2, axis=0) > 1e-6))


def _singular(x: np.ndarray, system: _System, bad: frozenset[int], A: np.ndarray) -> str:
    s = np.linalg.svd(A, compute_uv=False)
    at = ", ".join(f"{u} = {v:.6g}" for u, v in zip(system.unknowns, x))
    names = ", ".join(str(system.unknowns[i]) for i in sorted(bad))
    ratio = s[-1] / s[0] if s.size == len(system.unknowns) and s[0] > 0 else 0.0
    return (f"the relations' Jacobian is singular at the solution {at} (σ_min/σ_max = {ratio:.2g}, below "
            f"{SINGULAR_TOL:g}): {names} {'is' if len(bad) == 1 else 'are'} not fixed there (a double root, or "
            "a quantity the relations leave open); the error cannot be bounded")


def _turned(x: np.ndarray, system: _System) -> np.ndarray:
    """Each angle unknown (held by the relations only through sin and cos) in (−π, π]:
    the same motion whatever whole turns a start led to."""
    out = np.array(x, dtype=float)
    for i, u in enumerate(system.unknowns):
        if angle_unknown(u, system.relations):
            out[i] = np.pi - (np.pi - out[i]) % (2 * np.pi)
    return out


TWIN_TOL = 1e-8  # values found to about √ε: compared relative to this


def _once(solutions: list[NumericSteadyMotion], system: _System, model: Model) -> list[NumericSteadyMotion]:
    """Twins merged as on the exact route (``balances.twin``: β + π with −φ̇, the motion
    turned over), the representative the least in size, so the list does not depend
    on which starts found which copy."""
    out: list[NumericSteadyMotion] = []
    for s in sorted(solutions, key=lambda s: [abs(v) if v is not None else 0.0 for v in s.unknowns.values()]):
        a = {u: s.unknowns[str(u)] for u in system.unknowns}
        if any(None in a.values() or twin(a, {u: t.unknowns[str(u)] for u in system.unknowns}, system.relations,
                                          dict(model.values), TWIN_TOL) for t in out):
            continue
        out.append(s)
    return out


def _distinct(solutions: list[NumericSteadyMotion]) -> list[NumericSteadyMotion]:
    """Solutions merged where every unknown found agrees within MERGE_TOL, in a fixed order."""
    out: list[NumericSteadyMotion] = []
    for s in sorted(solutions, key=lambda s: tuple(v if v is not None else 0.0 for v in s.unknowns.values())):
        if not any(_same(s.unknowns, t.unknowns) for t in out):
            out.append(s)
    return out


def _same(a: dict, b: dict) -> bool:
    return all((x is None) == (y is None) and (x is None or abs(x - y) <= MERGE_TOL * max(1.0, abs(x)))
               for x, y in zip(a.values(), b.values()))


def _close(a: float, b: float) -> bool:
    return abs(a - b) <= MERGE_TOL * max(1.0, abs(a))


def _summary(vectors: list[tuple[float, ...]]):
    """One vector when every solution gives the same, else one per solution."""
    if all(all(_close(a, b) for a, b in zip(v, vectors[0])) for v in vectors):
        return vectors[0]
    return tuple(vectors)


def _solved_summary(solutions: list[NumericSteadyMotion]) -> dict[str, float | list[float]]:
    out: dict[str, float | list[float]] = {}
    for name in solutions[0].solved:
        found = [s.solved[name] for s in solutions]
        out[name] = found[0] if all(_close(v, found[0]) for v in found) else found
    return out


def _estimate(solutions: list[NumericSteadyMotion]) -> float | None:
    """The largest bound over its value, among the values not zero within their bound."""
    ratios = []
    for s in solutions:
        values = {**s.unknowns, **dict(zip(("omega1", "omega2", "omega3"), s.angular_velocity)), **s.solved}
        ratios += [e / abs(values[n]) for n, e in s.absolute_errors.items()
                   if values.get(n) is not None and abs(values[n]) > e]
    return float(max(ratios)) if ratios else None


def _warnings(solutions: list[NumericSteadyMotion]) -> tuple[str, ...]:
    search = (f"numeric search: least squares from {STARTS} starts (x = 0 and a fixed pseudo-random sample); "
              "a solution whose basin of attraction misses every start would be missed")
    open_ = sorted({n for s in solutions for n, v in s.unknowns.items() if v is None})
    if not open_:
        return (search,)
    return (search, f"the relations leave {', '.join(open_)} open (no answer depends on "
                    f"{'it' if len(open_) == 1 else 'them'}): null")
