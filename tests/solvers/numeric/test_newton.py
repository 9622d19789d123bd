"""Newton from many starts (solvers/numeric/newton.py): runs still going after their first
evaluations are continued once per place they ended, not once per start. The roots are
those of each start's own full run; the work is counted in evaluations, not seconds."""

from __future__ import annotations

import itertools

import numpy as np

from rbdsolve.solvers.numeric.newton import FIRST_EVALUATIONS, from_starts, newton

GRID = [np.array(p) for p in itertools.product(np.linspace(-10, 10, 24), repeat=2)]


def _counted(g):
    calls = [0]

    def counted(x):
        calls[0] += 1
        return g(x)

    return counted, calls


def _singular():
    """V = ½ k (x − y)² + c (x + y)⁴ (k = 3, c = 314): by hand ∇V = 0 only at x = y = 0,
    where H = k [[1, −1], [−1, 1]] is singular (the quartic makes Newton linear there)."""
    k, c = 3.0, 314.0

    def g(q):
        x, y = q
        return np.array([k * (x - y) + 4 * c * (x + y) ** 3, -k * (x - y) + 4 * c * (x + y) ** 3])

    def H(q):
        x, y = q
        s = 12 * c * (x + y) ** 2
        return np.array([[k + s, -k + s], [-k + s, k + s]])

    return g, H


def _pendulums():
    """V = −2 cos x − cos y + ½ (x − y)²/10: roots by hand where 2 sin x = −(x − y)/10 and
    sin y = (x − y)/10; among them (0, 0), (π, π), (0, π)-like pairs: several basins."""
    def g(q):
        x, y = q
        return np.array([2 * np.sin(x) + (x - y) / 10, np.sin(y) - (x - y) / 10])

    def H(q):
        x, y = q
        return np.array([[2 * np.cos(x) + 0.1, -0.1], [-0.1, np.cos(y) + 0.1]])

    return g, H


def _roots(candidates, g) -> set[tuple[float, float]]:
    return {tuple(np.round(x, 6) + 0.0) for x in candidates if x is not None and np.max(np.abs(g(x))) <= 1e-9}


def test_the_slow_runs_into_a_degenerate_root_share_one_continuation() -> None:
    g, H = _singular()
    counted, calls = _counted(g)
    found = _roots(from_starts(GRID, counted, H, lambda x, y: x - y), g)
    assert found == {(0.0, 0.0)}
    # each start's first evaluations, plus the continuations: far below the 166 a start
    # took alone (the median of hybr's own runs on this scene)
    assert calls[0] <= len(GRID) * (FIRST_EVALUATIONS + 10) + 10 * 300
    assert calls[0] < len(GRID) * 166


def test_the_roots_are_each_start_s_own_runs() -> None:
    """Every root a start's full run finds (the oracle: ``newton`` from each start) is found,
    and no other."""
    g, H = _pendulums()
    alone = _roots((newton(x, g, H) for x in GRID), g)
    pooled = _roots(from_starts(GRID, g, H, lambda x, y: x - y), g)
    assert pooled == alone and len(alone) > 4


def test_a_run_onto_a_continuum_of_roots_lands_on_it_to_round_off() -> None:
    """V = ½ k (x + 2y − 1)² (k = 5): ∇V = 0 on the whole line x + 2y = 1, where H is
    singular; from a start off the line the run and its polish end on it to round-off
    (the least-length Newton step moves straight across the line: its foot from the start)."""
    k = 5.0

    def g(q):
        r = q[0] + 2 * q[1] - 1
        return np.array([k * r, 2 * k * r])

    def H(q):
        return k * np.array([[1.0, 2.0], [2.0, 4.0]])

    start = np.array([3.0, -5.0])
    end = newton(start, g, H)
    assert abs(end[0] + 2 * end[1] - 1) <= 4e-16 * 10
    foot = start - (start[0] + 2 * start[1] - 1) / 5 * np.array([1.0, 2.0])
    assert np.max(np.abs(end - foot)) <= 1e-12
