"""Every root of a function of one variable on an interval: the floating-point
equilibria route's search in one coordinate (g = ∂V/∂q, g' = ∂²V/∂q²).

Strategy (a sign-change scan refined adaptively, after the interval-exclusion idea of
Moore, *Interval Analysis*, 1966, with a sampled instead of a proven Lipschitz bound):

1. Sample g and g' at CELLS + 1 evenly spaced points of [low, high].
2. A cell [a, b] with no sign change of g is *excluded* when
   |g(a)| + |g(b)| > L (b − a), L = SAFETY × max(|g'(a)|, |g'(m)|, |g'(b)|) (m the
   midpoint): if |g'| ≤ L on the cell, a root r in it would give |g(a)| ≤ L (r − a)
   and |g(b)| ≤ L (b − r), whose sum is at most L (b − a). A cell not excluded (and
   every cell with a sign change, which may hold three roots) is halved, down to the
   width (high − low) / 2**DEPTH.
3. In a smallest cell: a sign change of g is a root, found by bisection and Newton's
   steps from it (to round-off); without one, a sign change of g' is an extremum of g,
   found by bisection, and a root of even multiplicity (g touches zero) when |g| ≤ tol
   there.
4. A cell of step 1 where g, at both ends and the midpoint, is within tol of zero is
   flat (a continuum of roots, or nearly): its midpoint is returned, not refined.
   Smaller cells are never taken as flat, so that near a multiple root (where |g| ≤ tol
   over a stretch) only the root itself, by bisection, is returned.

Completeness: every root is found, to round-off, provided (i) |g'| on each cell stays
within SAFETY times its largest sampled value (an assumption, not a proof: a spike of
g' narrower than a cell can break it), and (ii) distinct roots are more than one
smallest cell apart (closer ones are reported once, or missed if g between them
exceeds tol). When the scan runs past MAX_EVALUATIONS points (each evaluation counted,
the leaves' bisections too), the cells left are returned as unresolved, so the caller
can say where the search is incomplete.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

from rbdsolve.errors import UnsolvedError

CELLS = 256
DEPTH = 20
SAFETY = 2.0
MAX_EVALUATIONS = 20000
RTOL = 4 * 2.0**-52  # a root's relative tolerance: four units of round-off


@dataclass(frozen=True)
class Sample:
    x: float
    g: float
    dg: float


@dataclass(frozen=True)
class ScanResult:
    roots: tuple[float, ...]  # candidate roots, ascending (to be checked by the caller)
    unresolved: tuple[tuple[float, float], ...]  # cells left when the evaluations ran out
    evaluations: int
    smallest: float  # the width of the smallest cell


def scan(f: Callable[[float], tuple[float, float]], low: float, high: float, tol: float) -> ScanResult:
    """The roots of g on [low, high], f(x) = (g(x), g'(x)): the module's strategy.
    Points where f raises UnsolvedError (V has no value there) are skipped."""
    smallest = (high - low) / 2**DEPTH
    counter = [0]

    def counted(x: float) -> tuple[float, float]:
        """f, every evaluation counted: the cells' samples and the leaves' bisections
        alike, so that MAX_EVALUATIONS bounds the work."""
        counter[0] += 1
        return f(x)

    def at(x: float) -> Sample | None:
        try:
            value, slope = counted(x)
        except UnsolvedError:
            return None
        return Sample(x, float(value), float(slope))

    samples = [at(low + (high - low) * i / CELLS) for i in range(CELLS + 1)]
    roots = [s.x for s in samples if s is not None and s.g == 0.0]
    stack = [(a, b, True) for a, b in zip(samples, samples[1:]) if a is not None and b is not None]
    unresolved = []
    while stack:
        a, b, first = stack.pop()
        if counter[0] >= MAX_EVALUATIONS:
            unresolved.append((a.x, b.x))
            continue
        if b.x - a.x <= smallest * 1.5:
            roots.extend(_leaf(a, b, counted, tol))
            continue
        m = at((a.x + b.x) / 2)
        if m is None:
            continue
        if first and max(abs(a.g), abs(m.g), abs(b.g)) <= tol:
            roots.append(m.x)  # flat: a continuum of roots, or nearly
        elif not _excluded(a, m, b):
            stack.extend([(a, m, False), (m, b, False)])
    return ScanResult(tuple(sorted(roots)), tuple(sorted(unresolved)), counter[0], smallest)


def _excluded(a: Sample, m: Sample, b: Sample) -> bool:
    """No root in [a, b] if g keeps its sign and |g(a)| + |g(b)| > L (b − a)."""
    if (a.g > 0) != (b.g > 0) or a.g == 0 or b.g == 0:
        return False
    lipschitz = SAFETY * max(abs(a.dg), abs(m.dg), abs(b.dg))
    return abs(a.g) + abs(b.g) > lipschitz * (b.x - a.x)


def _leaf(a: Sample, b: Sample, f, tol: float) -> list[float]:
    """A smallest cell: its root by bisection (a sign change of g, or g = 0 at an end),
    else the extremum of g inside (a sign change of g') when |g| ≤ tol there."""
    g = lambda x: float(f(x)[0])  # noqa: E731
    dg = lambda x: float(f(x)[1])  # noqa: E731
    xtol = RTOL * (b.x - a.x)  # rtol alone cannot stop at a root at 0
    try:
        if a.g == 0 or b.g == 0 or (a.g > 0) != (b.g > 0):
            return [_polished(f, bisected(g, a.x, a.g, b.x, b.g, xtol), a.x, b.x)]
        if a.dg == 0 or b.dg == 0 or (a.dg > 0) != (b.dg > 0):
            x = bisected(dg, a.x, a.dg, b.x, b.dg, xtol)
            return [x] if abs(g(x)) <= tol else []
    except UnsolvedError:  # V has no value inside
        return []
    return []


def _polished(f, x: float, low: float, high: float) -> float:
    """Newton's steps x − g/g' from the bisection's point while they stay in the cell and
    lower |g|: the bracket's last halving leaves x a few units of round-off from the
    root, Newton's step takes it to the nearest float that rounding allows."""
    value, slope = (float(v) for v in f(x))
    for _ in range(3):
        if value == 0 or slope == 0:
            return x
        nearer = x - value / slope
        if not low <= nearer <= high or nearer == x:
            return x
        there, slope_there = (float(v) for v in f(nearer))
        if abs(there) >= abs(value):
            return x
        x, value, slope = nearer, there, slope_there
    return x


def bisected(h, a: float, ha: float, b: float, hb: float, xtol: float) -> float:
    """A root of h in [a, b], h(a) and h(b) of opposite signs (or one 0), to within
    xtol + RTOL |x|: the bracket halved, ~50 times from a smallest cell. Where rounding
    blurs h's sign, a point of the last bracket. (Brent's method, which scipy's brentq
    ran here, takes fewer steps but the same to round-off; importing scipy.optimize
    was ~0.27 s of the process, the halvings are microseconds.)"""
    if ha == 0:
        return a
    if hb == 0:
        return b
    while True:
        m = (a + b) / 2
        if (b - a) / 2 <= xtol + RTOL * abs(m) or m in (a, b):
            return m
        hm = h(m)
        if hm == 0:
            return m
        if (hm > 0) == (ha > 0):
            a, ha = m, hm
        else:
            b = m
