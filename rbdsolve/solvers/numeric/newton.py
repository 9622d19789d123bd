"""Newton's method on ∂V/∂q = 0 with the Hessian as Jacobian, from one start
(``newton``) or from every start of a search (``from_starts``).

Each run (``_run``) takes Newton's step s = −H⁻¹ g where it lowers |g|, else the
Levenberg–Marquardt step s = −(HᵀH + μ D)⁻¹ Hᵀ g, D = diag(HᵀH), with μ raised tenfold
until |g| falls (a trial point where V has no value counts as not falling) and lowered
tenfold after each step taken, back to Newton's below MU_START (Levenberg 1944,
Marquardt 1963; Nocedal & Wright, Numerical Optimization, §10.3): near a regular root
Newton's quadratic convergence, far from one a step that never raises |g|. A step is
at most STEP_BOUND max(|q|, 1) long. A run stops where a step is within XTOL of |q|
(MINPACK's hybr, which scipy.optimize.root ran here before, stops at the same relative
step), where no damping lowers |g|, or after its allowance of evaluations of ∂V/∂q.
Written here on numpy rather than asked of scipy: importing scipy.optimize is ~0.27 s
of a process, more than an exam scene's whole search (numeric/dense.py says the same
of scipy.linalg).

From many starts, each run is given FIRST_EVALUATIONS evaluations of ∂V/∂q; a run still
going then is on the slow way into a root, where Newton converges only linearly (a
degenerate root, where the Hessian is singular: V = ½ k (x − y)² + c (x + y)⁴ at 0) or
wanders. Those runs are continued with the full allowance once per place they ended
(POOL_TOL apart), not once per start: hundreds of starts on the slow way into one root
took the whole allowance each (a singular two-coordinate scene: 576 starts, 116 000
evaluations, 18 s; now one continuation). A run that ends within the first evaluations is
what a single run would give; the roots of a regular scene are reached within ~60.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator

import numpy as np

from rbdsolve.errors import UnsolvedError

EPS_STEP = 4 * float(np.finfo(float).eps)
FIRST_EVALUATIONS = 60  # evaluations of ∂V/∂q per start before a run joins the pool
POOL_TOL = 1e-3  # runs ending this close (relative to max(1, |q|)) are continued as one
XTOL = 1.49012e-8  # a step this small relative to |q| ends a run (hybr's default, √ε)
MU_START = 1e-3  # the first damping, relative to diag(HᵀH), once Newton's step fails
MU_GIVE_UP = 1e12  # damping past which no step lowers |g|: the run has ended
STEP_BOUND = 100.0  # the longest step, relative to max(|q|, 1) (hybr's first trust region)


def allowance(n: int) -> int:
    """A run's full allowance of evaluations in n coordinates (hybr's default)."""
    return 200 * (n + 1)


def newton(start: np.ndarray, g, H) -> np.ndarray | None:
    """A full run from a start, polished; None where V has no value at the start or
    where the polishing steps go."""
    try:
        end, _ = _run(start, g, H, allowance(len(start)))
        return _polished(end, g, H)
    except UnsolvedError:
        return None


def from_starts(starts: Iterable[np.ndarray], g, H, apart) -> Iterator[np.ndarray | None]:
    """Candidate roots from every start: each run's polished end (None where V has no
    value), the runs still going after FIRST_EVALUATIONS continued once per place they
    ended (``apart(x, y)``: the difference of two configurations, angles wrapped)."""
    going: list[np.ndarray] = []
    for start in starts:
        try:
            end, still_going = _run(start, g, H, FIRST_EVALUATIONS)
            if still_going:
                going.append(end)
                continue
            yield _polished(end, g, H)
        except UnsolvedError:
            yield None
    for end in _one_per_place(going, apart):
        yield newton(end, g, H)


def _run(start: np.ndarray, g, H, evaluations: int) -> tuple[np.ndarray, bool]:
    """Newton's or the damped step from ``start`` (the module docstring) until a step
    within XTOL, no step lowering |g|, or ``evaluations`` of g: the end, and whether
    it was the evaluations that ran out (the run still going)."""
    x = np.array(start, dtype=float)
    f, J = _vector(g(x)), None
    used, mu = 1, 0.0
    while used < evaluations:
        size = _norm(f)
        if size == 0.0 or not np.isfinite(size):
            return x, False
        J = np.asarray(H(x), dtype=float) if J is None else J
        step = _step(J, f, mu)
        if step is None:  # H not a number here, or the damped matrix singular: damp more
            if mu > MU_GIVE_UP:
                return x, False
            mu = max(mu * 10, MU_START)
            continue
        step = _bounded(step, x)
        ft = _value_at(g, x + step)
        used += 1
        if ft is not None and _norm(ft) < size:
            x, f, J, mu = x + step, ft, None, (mu / 10 if mu > MU_START else 0.0)
            if _norm(step) <= XTOL * (_norm(x) + XTOL):
                return x, False
        elif mu > MU_GIVE_UP:
            return x, False
        else:
            mu = max(mu * 10, MU_START)
    return x, True


def _step(J: np.ndarray, f: np.ndarray, mu: float) -> np.ndarray | None:
    """Newton's step (μ = 0) or the damped one; None where the matrix is singular or
    not a number."""
    try:
        if mu == 0.0:
            return _newton_step(J, f)
        normal = J.T @ J
        scale = np.maximum(np.diag(normal), np.finfo(float).tiny)
        return np.linalg.solve(normal + mu * np.diag(scale), -J.T @ f)
    except np.linalg.LinAlgError:
        return None


def _bounded(step: np.ndarray, x: np.ndarray) -> np.ndarray:
    """The step, shortened to at most STEP_BOUND max(|q|, 1) (a nearly singular H throws
    Newton's step far; hybr's first trust region is as large)."""
    largest = STEP_BOUND * max(_norm(x), 1.0)
    length = _norm(step)
    return step if length <= largest else step * (largest / length)


def _value_at(g, x: np.ndarray) -> np.ndarray | None:
    """g at a trial point; None where V has no value there (the step is then damped)."""
    try:
        return _vector(g(x))
    except UnsolvedError:
        return None


def _vector(value) -> np.ndarray:
    return np.asarray(value, dtype=float).ravel()


def _norm(v: np.ndarray) -> float:
    return float(np.sqrt(np.sum(v * v)))


def _one_per_place(ends: list[np.ndarray], apart) -> list[np.ndarray]:
    """The ends with those within POOL_TOL of one already kept left out."""
    kept: list[np.ndarray] = []
    for x in ends:
        if not any(np.max(np.abs(apart(x, y)) / np.maximum(1.0, np.abs(y))) <= POOL_TOL for y in kept):
            kept.append(x)
    return kept


def _newton_step(J: np.ndarray, f: np.ndarray) -> np.ndarray:
    """s with J s = −f, of least length where J is singular (the Moore–Penrose step: on a
    continuum of roots, where H is singular along it, it moves straight across it, and
    Newton's convergence onto it stays quadratic; Ben-Israel 1966)."""
    if not np.all(np.isfinite(J)):
        raise np.linalg.LinAlgError("not a number")
    return np.linalg.lstsq(J, -f, rcond=None)[0]


def _polished(x: np.ndarray, g, H, steps: int = 3) -> np.ndarray:
    """A few plain Newton steps: a run stops at a relative step of 1.5e-8, Newton's
    quadratic convergence takes the root on to round-off."""
    for _ in range(steps):
        try:
            step = -_newton_step(np.asarray(H(x), dtype=float), _vector(g(x)))
        except np.linalg.LinAlgError:
            break
        x = x - step
        if np.max(np.abs(step)) <= EPS_STEP * max(np.max(np.abs(x)), 1.0):
            break
    return x
