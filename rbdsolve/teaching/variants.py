"""Exam variants: one exact solve, then every student's numbers at once.

    variants(problem, count, seed) -> VariantTable

Each ranged parameter (``values: {m: {range: [1, 5], step: 0.5}}``) gets ``count``
values drawn from its grid with ``numpy.random.default_rng(seed)``. The problem is
solved exactly ONCE with those parameters symbolic; every answer that is a number once
they have values becomes a column, evaluated for all variants together by a numpy
function (``sympy.lambdify``).

An exact answer may hold only for some values, so nothing is written on trust:

- a record with ``conditions`` (an equilibrium that exists only where each is ≥ 0) is
  left empty in the variants where a condition fails;
- a list the exact solve ordered by size at a sample point (eigenvalues with their
  frequencies and shapes, principal moments with their axes) is ordered again per
  variant, at its own values;
- a value that is not a finite real number is an empty cell, with a warning;
- ``verify`` variants are solved again, independently, with their values given, and
  every number in the table must agree with that solve (VERIFY_RTOL); a disagreement
  is an UnsolvedError naming the variant and the answer, and no table is made.

Answers that are not numbers (equations in time, stability, text) are left out, with
one note naming them.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Callable

import numpy as np
import sympy as sp
from sympy.core.function import AppliedUndef

from rbdsolve.errors import InputError, UnsolvedError
from rbdsolve.model.build import Model, build_model
from rbdsolve.model.numeric.compiled import numpy_function
from rbdsolve.problem.schema import Problem, ValueRange
from rbdsolve.problem.quantities.quantity import Value
from rbdsolve.report.steps import ProblemReport
from rbdsolve.report.variants import VariantTable
from rbdsolve.teaching.kinds import is_kind, kinds, per_variant
from rbdsolve.report.numbers import Path
from rbdsolve.model.values.tree import label, leaves
from rbdsolve.solvers import solve_problem
from rbdsolve.solvers.routes.budget import Allowance, OutOfTime, within
from rbdsolve.solvers.routes.options import Options, RouteChoice
from rbdsolve.model.values.units import problem_units
from rbdsolve.model.values.values import numeric
from rbdsolve.teaching import variants_verify
from rbdsolve.teaching.variants_verify import MATCHED, VERIFY_ATOL, VERIFY_RTOL, spread

IMAG_RTOL = 1e-12  # an imaginary part below this times max(1, |real part|) is round-off
DEFAULT_VERIFY = 3


@dataclass(frozen=True)
class _Leaf:
    """One answer of one question: its place in the answers tree and its expression with
    the fixed values put in (only ranged parameters left)."""

    question: int
    path: Path
    expr: sp.Expr

    @property
    def key(self) -> tuple:
        return (self.question, *self.path)


@dataclass(frozen=True)
class _Ordered:
    """A list the exact solve ordered by size at a sample point: ``field`` and the lists
    in the same order (``parallel``); ``key`` is where, inside an element, its sort key
    is (() the element itself; ("at",) the coordinates, lexicographically)."""

    field: str
    key: Path
    parallel: tuple[str, ...]


ORDERED = (
    _Ordered("eigenvalues", (), ("frequencies", "growth_rates", "shapes")),
    _Ordered("principal_moments", (), ("principal_axes",)),
)


Stage = Callable[[str, int, int], None]  # (what is under way, how much of it is done, out of)


def _silent(what: str, done: int, total: int) -> None:
    pass


def variants(problem: Problem, count: int, seed: int, options: Options = Options(),
             verify: int = DEFAULT_VERIFY, progress: Stage = _silent) -> VariantTable:
    """``count`` variants of ``problem`` drawn with ``seed``: see the module docstring.
    ``progress`` is told each stage as it goes (a bar on a terminal: cli/variants.py)."""
    if not problem.ranges:
        raise InputError(f"{problem.file}: no parameter has a range to draw from; give one in "
                         "'values:', e.g. values: {m: {range: [1, 5], step: 0.5}}")
    if count < 1:
        raise InputError(f"--count must be at least 1, found {count}")
    progress("drawing the values", 0, count)
    draws = draw(problem.ranges, count, seed)
    progress("solving the problem exactly", 0, 1)
    checked = spread(count, verify)
    run = Allowance(options.budget)  # one budget: the model and the exact solve, then each check's solve
    try:
        with within(run.left(), "the model (T and V)", options.budget):
            model = build_model(problem)
    except OutOfTime as exc:
        raise UnsolvedError(f"{problem.file}: {exc}") from None
    report = _exact(model, replace(options, budget=run.share(1 + len(checked)), budget_total=options.budget))
    progress("evaluating the answers", 0, count)
    symbols = [model.symbols.parameters[r.name] for r in problem.ranges]
    found, conditions, left_out = _answers(report, model, set(symbols))
    arrays = [np.array([float(d[i]) for d in draws]) for i in range(len(symbols))]
    cells = _evaluate([leaf.expr for leaf in found], symbols, arrays, count)
    conds = _evaluate([c for _, c in conditions], symbols, arrays, count)
    labels = question_labels([s.question for s in report.solutions])
    warnings = _existence(found, conditions, conds, cells, labels)
    warnings += _coincident(found, cells, labels)
    warnings += _reorder(found, cells)
    warnings += _not_real(found, cells, report)
    warnings += _unvalued(problem)
    warnings += _repeats(problem.ranges, count)
    table = _table(problem, report, seed, draws, found, cells, warnings, left_out)
    found_kinds = kinds(report.solutions, dict(model.values))
    table = replace(table, kind_columns=tuple(label((labels[k.question], *k.path)) for k in found_kinds),
                    kinds=per_variant(found_kinds, symbols, draws,
                                      lambda n: progress("each variant's stability and motions", n, count)))
    for n, k in enumerate(checked):
        progress("checking variants by a full solve", n, len(checked))
        share = replace(options, budget=run.share(len(checked) - n), budget_total=options.budget)
        variants_verify.verify(model, share, table, [leaf.key for leaf in found], found_kinds, k)
    return replace(table, verified=tuple(k + 1 for k in checked))


WHOLE_GRID = 100_000  # a grid of at most this many sets of values is shuffled whole


def draw(ranges: tuple[ValueRange, ...], count: int, seed: int) -> list[tuple[Value, ...]]:
    """Each variant's values from the grid of all sets of values (the product of the
    ranges' grids or choices, in file order), each set at most once while the grid has
    sets left, then round again (``repeated`` counts those). Variant i depends on the
    seed and i only, never on ``count``: a teacher who adds students keeps the first ones.

    A small grid is shuffled whole (numpy's ``default_rng(seed).permutation``) and
    variant i is its i-th set; a large one is walked by draws of one set per variant,
    in variant order, a set already given drawn again."""
    sizes = [r.size for r in ranges]
    total = math.prod(sizes)
    rng = np.random.default_rng(seed)
    if total <= WHOLE_GRID:
        order = rng.permutation(total)
        indices = [int(order[k % total]) for k in range(count)]
    else:
        indices, given = [], set()
        while len(indices) < count:
            index = int(sum(int(rng.integers(0, n)) * math.prod(sizes[j + 1:]) for j, n in enumerate(sizes)))
            if index not in given:
                given.add(index)
                indices.append(index)
            if len(given) == total:  # every set given (more students than sets): a new round
                given.clear()
    return [_values(ranges, sizes, index) for index in indices]


def repeated(ranges: tuple[ValueRange, ...], count: int) -> int:
    """How many variants must share their values with an earlier one: the grid has fewer
    sets than students."""
    return max(0, count - math.prod(r.size for r in ranges))


def _values(ranges: tuple[ValueRange, ...], sizes: list[int], index: int) -> tuple[Value, ...]:
    """The set of values at ``index`` of the grid (mixed radix, the last range fastest)."""
    picks = []
    for n in reversed(sizes):
        index, pick = divmod(index, n)
        picks.append(pick)
    return tuple(r.value(k) for r, k in zip(ranges, reversed(picks)))


def _repeats(ranges: tuple[ValueRange, ...], count: int) -> list[str]:
    extra = repeated(ranges, count)
    if not extra:
        return []
    sets = count - extra
    return [f"the ranges give {sets} different set{'s' if sets != 1 else ''} of values for {count} students: "
            f"{extra} share{'s' if extra == 1 else ''} the values of an earlier student (widen a range or add choices)"]


def question_labels(kinds: list[str]) -> list[str]:
    """'modes', and 'modes(2)' for the second modes question of a file."""
    out = []
    for i, kind in enumerate(kinds):
        n = kinds[: i + 1].count(kind)
        out.append(kind if n == 1 else f"{kind}({n})")
    return out


# --- the exact solve and its answers ---------------------------------------------------


def _exact(model: Model, options: Options) -> ProblemReport:
    """The one exact solve, ranged parameters symbolic; every question must answer."""
    report = solve_problem(model, Options(route=RouteChoice.EXACT, budget=options.budget,
                                          budget_total=options.budget_total))
    for s in report.solutions:
        if not s.solved:
            raise UnsolvedError(f"{model.problem.file}: question '{s.question}' has no exact answer with "
                                f"the ranged parameters symbolic ({s.error}); variants need one")
    return report


def _answers(report: ProblemReport, model: Model, ranged: set[sp.Symbol]
             ) -> tuple[list[_Leaf], list[tuple[tuple, sp.Expr]], list[str]]:
    """The numeric answers (columns), the existence conditions (record key, expression)
    and the labels of the answers left out (not numbers)."""
    found, conditions, left_out = [], [], []
    for q, s in enumerate(report.solutions):
        for path, leaf in leaves(s.answers):
            if "conditions" in path:
                record = (q, *path[: path.index("conditions")])
                conditions.append((record, _fixed(leaf, model)))
            elif _is_number(leaf, model, ranged):
                found.append(_Leaf(q, path, _fixed(leaf, model)))
            elif leaf is not None and not is_kind(path, leaf) and "stability_cases" not in path \
                    and "cases" not in path and "exists_when" not in path:
                name = label((s.question, *(p for p in path if isinstance(p, str))))
                left_out.append(name)
    return found, conditions, list(dict.fromkeys(left_out))


def _fixed(expr: sp.Expr, model: Model) -> sp.Expr:
    return expr.xreplace(model.values)


def _is_number(leaf: object, model: Model, ranged: set[sp.Symbol]) -> bool:
    """An expression that is a number once the ranged parameters have values."""
    if not isinstance(leaf, sp.Expr):
        return False
    expr = _fixed(leaf, model)
    return (expr.free_symbols <= ranged and not expr.atoms(AppliedUndef)
            and not expr.has(sp.Derivative))


# --- all variants at once --------------------------------------------------------------


def _evaluate(exprs: list[sp.Expr], symbols: list[sp.Symbol], arrays: list[np.ndarray],
              count: int) -> np.ndarray:
    """Every expression at every variant: complex, shape (len(exprs), count), NaN where
    it is not finite. One numpy function for all of them (common subexpressions shared);
    a number without symbols (a CRootOf among them) is evaluated exactly, once."""
    out = np.full((len(exprs), count), np.nan, dtype=complex)
    varying = [i for i, e in enumerate(exprs) if e.free_symbols]
    for i, e in enumerate(exprs):
        if not e.free_symbols:
            out[i] = _constant(e)
    if varying:
        f = numpy_function(symbols, [exprs[i] for i in varying], cse=True)
        with np.errstate(all="ignore"):
            results = f(*arrays)
        for i, r in zip(varying, results):
            out[i] = np.broadcast_to(np.asarray(r, dtype=complex), (count,))
    out[~np.isfinite(out)] = np.nan
    return out


def _constant(expr: sp.Expr) -> complex:
    value = numeric(expr, {})
    if isinstance(value, float):
        return complex(value)
    if isinstance(value, list):
        return complex(value[0], value[1])
    return complex(np.nan)


def _existence(found: list[_Leaf], conditions: list[tuple[tuple, sp.Expr]], conds: np.ndarray,
               cells: np.ndarray, labels: list[str]) -> list[str]:
    """Empty the cells of a record (an equilibrium) in the variants where one of its
    conditions is not ≥ 0: it does not exist there."""
    missing: dict[tuple, np.ndarray] = {}
    for (record, expr), values in zip(conditions, conds):
        fails = ~((np.abs(values.imag) <= IMAG_RTOL * np.maximum(1, np.abs(values.real)))
                  & (values.real >= -VERIFY_ATOL))
        missing[record] = missing.get(record, np.zeros(len(values), bool)) | fails
    warnings = []
    for record, fails in missing.items():
        if not fails.any():
            continue
        for i, leaf in enumerate(found):
            if leaf.key[: len(record)] == record:
                cells[i, fails] = np.nan
        warnings.append(f"{label((labels[record[0]], *record[1:]))}: does not exist in {int(fails.sum())} of "
                        f"{len(fails)} variants (first: variant {int(np.argmax(fails)) + 1}); "
                        "its cells are empty there")
    return warnings


def _reorder(found: list[_Leaf], cells: np.ndarray) -> list[str]:
    """Order each size-ordered list again per variant, at the variant's values."""
    warnings = []
    for q in sorted({leaf.question for leaf in found}):
        for spec in ORDERED:
            warnings += _reorder_one(q, spec, found, cells)
    return warnings


def _reorder_one(q: int, spec: _Ordered, found: list[_Leaf], cells: np.ndarray) -> list[str]:
    rows = {leaf.key: i for i, leaf in enumerate(found)}
    size = 1 + max((leaf.path[1] for leaf in found if leaf.question == q and len(leaf.path) > 1
                    and leaf.path[0] == spec.field and isinstance(leaf.path[1], int)), default=-1)
    if size < 2:
        return []
    keys = [[i for k, i in rows.items() if k[:3] == (q, spec.field, e) and k[3: 3 + len(spec.key)] == spec.key]
            for e in range(size)]
    if any(len(k) != len(keys[0]) or not k for k in keys):
        return []
    order = _order(np.stack([cells[k].real for k in keys]))  # (size, count)
    moved = (order != np.arange(size)[:, None]).any(axis=0)
    if not moved.any():
        return []
    warnings = []
    for name in (spec.field, *spec.parallel):
        if not _permute(q, name, size, order, rows, cells):
            _blank_field(q, name, rows, cells, moved)
            warnings.append(f"{name}: in {int(moved.sum())} variants the order by size differs from the "
                            "exact solution's and these cells cannot follow it; they are empty there")
    return warnings


def _order(keys: np.ndarray) -> np.ndarray:
    """Per variant, the elements in ascending order of their keys (lexicographic over the
    key's entries); an element with no value (NaN) last. keys: (size, n_keys, count)."""
    size, n_keys, count = keys.shape
    order = np.empty((size, count), dtype=int)
    for v in range(count):
        columns = keys[:, :, v]
        absent = np.isnan(columns).any(axis=1)
        filled = np.where(np.isnan(columns), 0.0, columns)
        order[:, v] = np.lexsort((*filled.T[::-1], absent))
    return order


def _permute(q: int, name: str, size: int, order: np.ndarray, rows: dict, cells: np.ndarray) -> bool:
    """Put the elements of list ``name`` in ``order``, per variant; False when its
    elements do not all have the same cells (then they cannot be moved as a block)."""
    suffixes = [sorted(k[3:] for k in rows if k[:3] == (q, name, e)) for e in range(size)]
    if not any(suffixes):
        return True  # nothing of this list is in the table
    if any(s != suffixes[0] for s in suffixes):
        return False
    for suffix in suffixes[0]:
        idx = [rows[(q, name, e, *suffix)] for e in range(size)]
        cells[idx] = np.take_along_axis(cells[idx], order, axis=0)
    return True


def _blank_field(q: int, name: str, rows: dict, cells: np.ndarray, moved: np.ndarray) -> None:
    for key, i in rows.items():
        if key[:2] == (q, name):
            cells[i, moved] = np.nan


def _not_real(found: list[_Leaf], cells: np.ndarray, report: ProblemReport) -> list[str]:
    """Empty the cells that are not finite real numbers, with one warning per column."""
    labels = question_labels([s.question for s in report.solutions])
    real = np.abs(cells.imag) <= IMAG_RTOL * np.maximum(1, np.abs(cells.real))
    bad = ~real & ~np.isnan(cells)
    warnings = []
    for i, leaf in enumerate(found):
        if bad[i].any():
            warnings.append(f"{label((labels[leaf.question], *leaf.path))}: not a real number in "
                            f"{int(bad[i].sum())} of {cells.shape[1]} variants (first: variant "
                            f"{int(np.argmax(bad[i])) + 1}); those cells are empty")
    cells[bad] = np.nan
    return warnings


# --- the table and its check -----------------------------------------------------------


def _table(problem: Problem, report: ProblemReport, seed: int, draws: list[tuple[Value, ...]],
           found: list[_Leaf], cells: np.ndarray, warnings: list[str], left_out: list[str]) -> VariantTable:
    labels = question_labels([s.question for s in report.solutions])
    columns = tuple(label((labels[leaf.question], *leaf.path)) for leaf in found)
    real = cells.real.reshape(len(found), len(draws)) + 0.0  # −0.0 as 0.0
    answers = tuple(tuple(None if x != x else x for x in row) for row in real.T.tolist())  # NaN: no value
    notes = (f"not numbers, so not in the table: {', '.join(left_out)}",) if left_out else ()
    return VariantTable(problem.file, problem.title, problem.statement, tuple(labels), seed,
                        tuple(r.name for r in problem.ranges), problem.values, columns,
                        tuple(draws), answers, notes, tuple(warnings),
                        units=tuple(problem_units(problem).items()), angles=_angles(problem))


def _angles(problem: Problem) -> frozenset[str]:
    """The parameters a student sheet gives in degrees: those whose value, range or
    choices the file wrote in angle units (20 deg, 45 deg)."""
    ranged = {r.name for r in problem.ranges if r.low.angle or any(c.angle for c in r.choices)}
    return problem.angle_values() | ranged


def _unvalued(problem: Problem) -> list[str]:
    """A parameter with neither a value nor a range keeps every answer holding it out of
    the table: said, so a thin table is not taken for the whole answer."""
    given = {name for name, _ in problem.values} | {r.name for r in problem.ranges}
    missing = [p.name for p in problem.parameters if p.name not in given and p.name not in problem.unknowns]
    if not missing:
        return []
    return [f"{', '.join(missing)} {'has' if len(missing) == 1 else 'have'} neither a value nor a range in "
            "'values:': the answers that hold them are not numbers, so not in the table"]


def _coincident(found: list[_Leaf], cells: np.ndarray, labels: list[str]) -> list[str]:
    """Empty the cells of a MATCHED element (an equilibrium) in the variants where it
    coincides with an earlier one: at a critical value two branches of the exact answer
    meet (acos(g/(Ω²R)) = 0 at Ω²R = g), and the point is one equilibrium, not two."""
    warnings = []
    for (q, name), elements in _elements(found).items():
        sub = MATCHED[name]
        at = {e: {found[i].key[4:]: i for i in leaves_ if found[i].key[3] == sub} for e, leaves_ in elements.items()}
        for later in elements:
            for earlier in (e for e in elements if e < later and at[e].keys() == at[later].keys() and at[e]):
                same = np.all([np.isclose(cells[at[later][p]], cells[at[earlier][p]], rtol=VERIFY_RTOL,
                                          atol=VERIFY_ATOL) for p in at[later]], axis=0)
                if not same.any():
                    continue
                for i in elements[later]:
                    cells[i, same] = np.nan
                warnings.append(f"{label((labels[q], name, later))} is {label((labels[q], name, earlier))} in "
                                f"{int(same.sum())} variants (first: variant {int(np.argmax(same)) + 1}); "
                                "listed once there")
    return warnings


def _elements(found: list[_Leaf]) -> dict[tuple[int, str], dict[int, list[int]]]:
    """For each MATCHED list, its elements' leaf indices, by element."""
    out: dict[tuple[int, str], dict[int, list[int]]] = {}
    for i, leaf in enumerate(found):
        key = leaf.key
        if len(key) > 3 and key[1] in MATCHED and isinstance(key[2], int):
            out.setdefault((key[0], key[1]), {}).setdefault(key[2], []).append(i)
    return out
