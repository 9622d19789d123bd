"""The one-coordinate scan's roots (solvers/numeric/scan.py): every root of g in the
interval to round-off, a touching root as g's extremum, compared with roots known by
hand."""

from __future__ import annotations

import math

import pytest

from rbdsolve.solvers.numeric.scan import RTOL, bisected, scan


def test_every_root_of_a_cubic_to_round_off() -> None:
    """g = (x − 1)(x + 0.5)(x − 2.25) = x³ − 2.75 x² + 0.125 x + 1.125 on [−3, 3]: roots −0.5, 1, 2.25."""
    def f(x: float) -> tuple[float, float]:
        return (x - 1) * (x + 0.5) * (x - 2.25), 3 * x**2 - 5.5 * x + 0.125

    found = scan(f, -3.0, 3.0, 1e-12)
    roots = sorted(set(found.roots))  # 2.25 is a sample point too: candidates, merged by the caller
    assert len(roots) == 3 and not found.unresolved
    for x, exact in zip(roots, (-0.5, 1.0, 2.25)):
        assert abs(x - exact) <= 4 * math.ulp(exact)


def test_a_transcendental_root_to_round_off() -> None:
    """g = cos x − x: the Dottie number 0.7390851332151607 (to the last digit, by hand's
    fixed-point iteration carried to convergence in 50-digit arithmetic)."""
    found = scan(lambda x: (math.cos(x) - x, -math.sin(x) - 1), -2.0, 2.0, 1e-12)
    assert len(found.roots) == 1
    assert abs(found.roots[0] - 0.7390851332151607) <= 2 * math.ulp(0.739)


def test_a_touching_root_is_found_as_an_extremum() -> None:
    """g = (x − 0.3)² touches zero at 0.3 without a sign change."""
    found = scan(lambda x: ((x - 0.3) ** 2, 2 * (x - 0.3)), -1.0, 1.0, 1e-10)
    assert len(found.roots) == 1 and abs(found.roots[0] - 0.3) <= 1e-5


@pytest.mark.parametrize("a, b", [(1.0, 2.0), (1.4142, 1.4143)])
def test_bisection_brackets_the_root_within_its_tolerance(a: float, b: float) -> None:
    h = lambda x: x * x - 2  # noqa: E731
    xtol = RTOL * (b - a)
    x = bisected(h, a, h(a), b, h(b), xtol)
    assert abs(x - math.sqrt(2)) <= 2 * (xtol + RTOL * math.sqrt(2))
    assert bisected(h, math.sqrt(2), 0.0, 2.0, h(2.0), xtol) == math.sqrt(2)  # a root at an end
