"""Newton's method on ∂V/∂q = 0 (scipy's hybr with the Hessian as Jacobian), from one
start (``newton``) or from every start of a search (``from_starts``).

From many starts, each run is given FIRST_EVALUATIONS evaluations of ∂V/∂q; a run still
going then is on the slow way into a root, where Newton converges only linearly (a
degenerate root, where the Hessian is singular: V = ½ k (x − y)² + c (x + y)⁴ at 0) or
wanders. Those runs are continued with hybr's full allowance once per place they ended
(POOL_TOL apart), not once per start: hundreds of starts on the slow way into one root
took the whole allowance each (a singular two-coordinate scene: 576 starts, 116 000
evaluations, 18 s; now one continuation). A run that ends within the first evaluations is
what a single run would give; the roots of a regular scene are reached within ~60
(the double pendulum's starts take at most 58).
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator

import numpy as np

from rbdsolve.errors import UnsolvedError

EPS_STEP = 4 * float(np.finfo(float).eps)
FIRST_EVALUATIONS = 60  # hybr's evaluations of ∂V/∂q per start before a run joins the pool
POOL_TOL = 1e-3  # runs ending this close (relative to max(1, |q|)) are continued as one
_MAXFEV = 2  # scipy.optimize.root's status: the evaluations allowed were used


def newton(start: np.ndarray, g, H) -> np.ndarray | None:
    """Newton's method (hybr) from a start, polished; None where V has no value."""
    from scipy.optimize import root

    try:
        return _polished(root(g, start, jac=H, method="hybr").x, g, H)
    except UnsolvedError:
        return None


def from_starts(starts: Iterable[np.ndarray], g, H, apart) -> Iterator[np.ndarray | None]:
    """Candidate roots from every start: each run's polished end (None where V has no
    value), the runs still going after FIRST_EVALUATIONS continued once per place they
    ended (``apart(x, y)``: the difference of two configurations, angles wrapped)."""
    from scipy.optimize import root

    going: list[np.ndarray] = []
    for start in starts:
        try:
            run = root(g, start, jac=H, method="hybr", options={"maxfev": FIRST_EVALUATIONS})
            if run.status == _MAXFEV:
                going.append(run.x)
                continue
            yield _polished(run.x, g, H)
        except UnsolvedError:
            yield None
    for end in _one_per_place(going, apart):
        yield newton(end, g, H)


def _one_per_place(ends: list[np.ndarray], apart) -> list[np.ndarray]:
    """The ends with those within POOL_TOL of one already kept left out."""
    kept: list[np.ndarray] = []
    for x in ends:
        if not any(np.max(np.abs(apart(x, y)) / np.maximum(1.0, np.abs(y))) <= POOL_TOL for y in kept):
            kept.append(x)
    return kept


def _polished(x: np.ndarray, g, H, steps: int = 3) -> np.ndarray:
    """A few plain Newton steps: hybr stops at a relative step of 1.5e-8, Newton's
    quadratic convergence takes the root on to round-off."""
    for _ in range(steps):
        try:
            step = np.linalg.solve(np.asarray(H(x), dtype=float), np.asarray(g(x), dtype=float))
        except np.linalg.LinAlgError:
            break
        x = x - step
        if np.max(np.abs(step)) <= EPS_STEP * max(np.max(np.abs(x)), 1.0):
            break
    return x
