"""Solutions of ∂V/∂q = 0 outside a coordinate's declared ``range``: not listed. A range
says where the coordinate lives (a bead on a rod of length 2 l: x in [0, 2 l]); the
numeric route searches only there, and a spring's length takes its sign over it
(model/energies/spring_length.py), so the exact route's list keeps to it too. A block
on a spring of natural length 0.5 m, y its depth in [0.7, 5], has y = L₀ + m g/k =
0.5981 m: outside, said in a warning. Decided by the parameters' signs or values (or the
assumptions), else by samples of the parameters left open where the solution is real; a
solution inside the range for some of them is kept."""

from __future__ import annotations

import random
from typing import Mapping

import sympy as sp

from rbdsolve.form.printers import to_unicode, unicode_name
from rbdsolve.model.build import Model, declared_ranges
from rbdsolve.solvers.conditions.signs import Undecided, sign_of


def split(model: Model, solutions) -> tuple[list, list[str]]:
    """The solutions kept, and a warning for each dropped (``_outside``)."""
    ranges = declared_ranges(model.problem.coordinates, model.symbols)
    if not ranges:
        return list(solutions), []
    names = dict(zip(model.q, model.coordinate_names()))
    kept, warnings = [], []
    for sol in solutions:
        q = _outside(model, sol, ranges)
        if q is None:
            kept.append(sol)
            continue
        low, high = ranges[q]
        shown = ", ".join(f"{unicode_name(names.get(x, str(x)))} = {to_unicode(v)}" for x, v in sol.items())
        warnings.append(f"{shown} solves ∂V/∂q = 0 outside the range declared for {unicode_name(names[q])}, "
                        f"[{to_unicode(low)}, {to_unicode(high)}]: not listed")
    return kept, warnings


def _outside(model: Model, sol: Mapping, ranges: Mapping) -> sp.Symbol | None:
    """The first coordinate whose value in ``sol`` is decided below its range's low end or
    above its high end (``_below``); None where none is."""
    for q, (low, high) in ranges.items():
        if q not in sol:
            continue
        value = sp.sympify(sol[q])
        if _below(value - low, model) or _below(high - value, model):
            return q
    return None


SAMPLES = 12  # parameter points where a gap's sign is read when the signs do not decide it


def _below(gap: sp.Expr, model: Model) -> bool:
    """gap < 0: by the parameters' signs or values, else at every one of SAMPLES admissible
    points of the parameters left open where the solution is real (at least three of
    them). A collar at s = −√(L₀² − d²) on a rod whose stop is at s = 0, d open: below
    the range wherever the equilibrium exists (d < L₀), though no sign rule sees it, the
    radicand's sign being the equilibrium's own condition."""
    sign = sign_of(gap, model.decided_by)
    if not isinstance(sign, Undecided):
        return sign < 0
    from rbdsolve.solvers.conditions.condition_roots import admissible  # only for a gap the signs leave open

    seen = []
    for k in range(SAMPLES):
        point = admissible(model, random.Random(53 + k))
        if point is None:
            continue
        z = complex(sp.N(gap.xreplace(point), 20))
        if abs(z.imag) <= 1e-12 * max(1.0, abs(z.real)):
            seen.append(z.real)
    return len(seen) >= 3 and all(x < 0 for x in seen)
