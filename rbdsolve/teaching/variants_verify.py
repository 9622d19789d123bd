"""Each checked variant solved again, independently, with its values given: every number
of its row in the table must agree with that solve, within

    |table − full solve| ≤ VERIFY_RTOL·max(|a|, |b|) + VERIFY_ATOL,

and it must list as many elements of each MATCHED list (equilibria, matched by where
they are, not by position) and give each the same kind (its stability, its case); a
disagreement is an UnsolvedError naming the variant and the answer, and no table is
made. Used by teaching/variants.py, which makes the table."""

from __future__ import annotations

import numpy as np

from rbdsolve.errors import UnsolvedError
from rbdsolve.model.build import Model
from rbdsolve.model.values.tree import leaves
from rbdsolve.model.values.values import numeric
from rbdsolve.report.variants import VariantTable
from rbdsolve.solvers import solve_problem
from rbdsolve.solvers.routes.options import Options

VERIFY_RTOL = 1e-9  # |table − full solve| ≤ VERIFY_RTOL·max(|a|, |b|) + VERIFY_ATOL
VERIFY_ATOL = 1e-12
# Lists whose elements a solve at given values may leave out (an equilibrium that does
# not exist there): the check matches them by these entries, not by position. Their
# order is decided with every parameter 1 (equilibria._order), the same in both solves.
MATCHED = {"equilibria": "at"}


def spread(count: int, verify: int) -> list[int]:
    """``verify`` variant indices spread over the table: the first, the last, between."""
    if verify <= 0:
        return []
    return sorted({int(round(x)) for x in np.linspace(0, count - 1, min(verify, count))})


def verify(model: Model, options: Options, table: VariantTable, keys: list[tuple], found_kinds: list, k: int) -> None:
    """Solve variant ``k`` again with its values given (the ordinary solve, any route)
    and compare every number of its row; UnsolvedError on any disagreement."""
    values = dict(zip(table.parameters, table.draws[k]))
    given = model.with_values(values)
    report = solve_problem(given, Options(route=options.route, budget=options.budget,
                                          budget_total=options.budget_total))
    where = f"variant {k + 1} ({', '.join(f'{n} = {float(v):g}' for n, v in values.items())})"
    theirs: dict[tuple, object] = {}
    for q, s in enumerate(report.solutions):
        if not s.solved:
            raise UnsolvedError(f"{table.file}: {where}: the check could not solve '{s.question}' at these "
                                f"values ({s.error}); the table is not written")
        theirs.update({(q, *path): numeric(leaf, given.values) for path, leaf in leaves(s.answers)})
    row = dict(zip(keys, table.answers[k]))
    _same_count(row, theirs, table.file, where)
    _same_kinds(table, found_kinds, k, row, theirs, where)
    for column, key, ours in zip(table.columns, keys, table.answers[k]):
        if ours is None:
            continue  # an empty cell claims nothing
        other = theirs.get(_matched(key, row, theirs))
        if not isinstance(other, float):
            raise UnsolvedError(f"{table.file}: {where}: {column} is {ours:.10g} in the table, but a full "
                                "solve at these values has no real number there; the table is not written")
        if not _close(ours, other):
            raise UnsolvedError(f"{table.file}: {where}: {column} is {ours:.10g} in the table, but a full "
                                f"solve at these values gives {other:.10g}; the table is not written")


def _same_kinds(table: VariantTable, found_kinds: list, k: int, row: dict, theirs: dict, where: str) -> None:
    """Each kind the table gives the variant (its case) is the full solve's there (an
    equilibrium matched by where it is, as for the numbers)."""
    for column, kind, ours in zip(table.kind_columns, found_kinds, table.kinds[k]):
        other = theirs.get(_matched(kind.key, row, theirs))
        if ours is not None and other is not None and other != ours:
            raise UnsolvedError(f"{table.file}: {where}: {column} is {ours} in the table, but a full solve at "
                                f"these values gives {other}; the table is not written")


def _same_count(row: dict[tuple, float | None], theirs: dict[tuple, object], file: str, where: str) -> None:
    """As many elements of each MATCHED list in the row as the full solve finds: the
    element-by-element comparison alone would let two rows match one equilibrium."""
    # in order, not a set's (the hash seed's): where two lists differ, the same one is named
    for q, name in sorted({(k[0], k[1]) for k in row if len(k) > 2 and k[1] in MATCHED}):
        ours = {k[2] for k, x in row.items() if k[:2] == (q, name) and x is not None}
        others = _distinct(q, name, theirs)
        if len(ours) != others:
            raise UnsolvedError(f"{file}: {where}: the table lists {len(ours)} {name}, a full solve at these "
                                f"values finds {others}; the table is not written")


def _distinct(q: int, name: str, theirs: dict[tuple, object]) -> int:
    """How many different elements the full solve lists (by their MATCHED entries): its
    exact branches may meet at these values, as the table's do (_coincident)."""
    sub = MATCHED[name]
    places: list[tuple] = []
    for e in sorted({k[2] for k in theirs if k[:2] == (q, name) and len(k) > 3}):
        at = tuple(x for k, x in sorted(theirs.items(), key=lambda kv: str(kv[0]))
                   if k[:4] == (q, name, e, sub))
        if not any(len(at) == len(p) and all(isinstance(a, float) and isinstance(b, float) and _close(a, b)
                                             for a, b in zip(at, p)) for p in places):
            places.append(at)
    return len(places)


def _close(a: float, b: float) -> bool:
    return abs(a - b) <= VERIFY_RTOL * max(abs(a), abs(b)) + VERIFY_ATOL


def _matched(key: tuple, row: dict[tuple, float | None], theirs: dict[tuple, object]) -> tuple:
    """The full solve's key for the table's ``key``: the same, except in a MATCHED list,
    where the element is the one at the same place (its 'at' entries all close)."""
    if len(key) < 3 or key[1] not in MATCHED or not isinstance(key[2], int):
        return key
    q, name, e = key[:3]
    sub = MATCHED[name]
    ours = {k[4:]: x for k, x in row.items() if k[:4] == (q, name, e, sub)}
    n_theirs = 1 + max((k[2] for k in theirs if k[:2] == (q, name) and len(k) > 2), default=-1)
    for f in range(n_theirs):
        other = {k[4:]: x for k, x in theirs.items() if k[:4] == (q, name, f, sub)}
        if other.keys() == ours.keys() and all(
                isinstance(other[p], float) and x is not None and _close(x, other[p]) for p, x in ours.items()):
            return (q, name, f, *key[3:])
    return (q, name, -1, *key[3:])  # no such element in the full solve
