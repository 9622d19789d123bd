"""Each student's kind of answer — an equilibrium's stability, a mode's motion — in an
exam's variants.

The exact solve, with the ranged parameters symbolic, gives a kind either once for all
values or case by case (``stability_cases``, a mode's ``cases``: "stable when Ω < Ω_c").
A variant's kind is the case whose condition holds at its values; none where its
values sit on a boundary (Ω = Ω_c exactly: the cases do not say) or where the record
does not exist there (``exists_when`` false). Read off the conditions with the values
put in exactly, never guessed.
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import Enum
from typing import Callable, Sequence

import sympy as sp
from sympy.logic.boolalg import BooleanAtom

from rbdsolve.model.symbols import exact_number
from rbdsolve.problem.quantities.quantity import Value
from rbdsolve.report.numbers import Path
from rbdsolve.model.values.tree import leaves

KIND_FIELDS = ("stability", "motions")  # the answers' fields that hold a kind


@dataclass(frozen=True)
class Kind:
    """One kind-valued answer: where it is, its kind when it does not depend on the
    parameters, its cases ((condition, kind)) when it does, and where its record exists."""

    question: int
    path: Path
    fixed: str | None
    cases: tuple[tuple[sp.Basic, str], ...]
    exists: sp.Basic = sp.true

    @property
    def key(self) -> tuple:
        return (self.question, *self.path)


def kinds(solutions: Sequence, fixed_values: dict) -> list[Kind]:
    """The kind-valued answers of every solution, with their cases and existence (the
    fixed parameter values put in)."""
    out = []
    for q, solution in enumerate(solutions):
        for path, leaf in leaves(solution.answers):
            if is_kind(path, leaf):
                out.append(_kind(q, path, leaf, solution.answers, fixed_values))
    return out


def is_kind(path: Path, leaf: object) -> bool:
    """Is this leaf a kind (a stability, a mode's motion) that ``kinds`` reads?"""
    return isinstance(leaf, Enum) and _field(path) in KIND_FIELDS


def _field(path: Path) -> str | None:
    """'stability' for (… 'stability'), 'motions' for (… 'motions', i); not the kinds
    inside the cases themselves (they are read through their record)."""
    if "stability_cases" in path or "cases" in path:
        return None
    if path and path[-1] == "stability":
        return "stability"
    if len(path) >= 2 and path[-2] == "motions" and isinstance(path[-1], int):
        return "motions"
    return None


def _kind(q: int, path: Path, leaf: Enum, answers, fixed_values: dict) -> Kind:
    put = (lambda c: c.xreplace(fixed_values))
    if _field(path) == "stability":
        record = _at(answers, path[:-1])
        cases = tuple((put(c.when), c.stability.value) for c in getattr(record, "stability_cases", ()))
        exists = put(getattr(record, "exists_when", sp.true))
    else:
        holder = _at(answers, path[:-2])
        per_mode = getattr(holder, "cases", ())
        found = per_mode[path[-1]] if per_mode else ()
        cases = tuple((put(c.when), c.kind.value) for c in found)
        exists = sp.true
    return Kind(q, path, None if leaf.value == "depends" else leaf.value, cases, exists)


def _at(value, path: Path):
    for part in path:
        value = value[part] if isinstance(part, int) else getattr(value, part)
    return value


Progress = Callable[[int], None]  # told how many variants are done so far
TICK = 1000  # variants between two calls of a Progress


def per_variant(found: list[Kind], symbols: list[sp.Symbol], draws: list[tuple[Value, ...]],
                progress: Progress | None = None) -> tuple[tuple[str | None, ...], ...]:
    """Each variant's kind, in the order of ``found`` (None: no kind claimed there).
    Each record's existence is made strict once, not once per variant."""
    exists = [_strict(k.exists) for k in found]
    exact: dict[Value, sp.Expr] = {}  # a range has few distinct values: each converted once
    rows = []
    for n, draw in enumerate(draws, 1):
        values = {s: exact[v] if v in exact else exact.setdefault(v, exact_number(v)) for s, v in zip(symbols, draw)}
        rows.append(tuple(_one(k, e, values) for k, e in zip(found, exists)))
        if progress is not None and (n % TICK == 0 or n == len(draws)):
            progress(n)
    return tuple(rows)


def _one(kind: Kind, exists: sp.Basic, values: dict) -> str | None:
    if _holds(exists, values) is not True:
        return None  # absent there, or on its boundary (Ω = Ω_c: branches meet, K = 0)
    if kind.fixed is not None:
        return kind.fixed
    return next((name for when, name in kind.cases if _holds(when, values) is True), None)


def _strict(condition: sp.Basic) -> sp.Basic:
    """Ω ≥ Ω_c as Ω > Ω_c: the kind of an equilibrium is not claimed where it appears."""
    return condition.replace(lambda e: isinstance(e, (sp.GreaterThan, sp.LessThan)),
                             lambda e: (sp.StrictGreaterThan if isinstance(e, sp.GreaterThan)
                                        else sp.StrictLessThan)(e.lhs, e.rhs))


def _holds(condition: sp.Basic, values: dict) -> bool | None:
    decided = condition.xreplace(values)
    return bool(decided) if isinstance(decided, BooleanAtom) else None
