"""A table of exam variants: each student's parameter values and numeric answers
(teaching/variants.py makes it; render/variants.py writes it as CSV, JSON or LaTeX)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import SupportsFloat

# A parameter's value: exact (problem.quantity.Value, which report/ does not import);
# float() gives its number, ``.text`` the value as written.
Number = SupportsFloat


@dataclass(frozen=True)
class VariantTable:
    """One row per variant: its drawn parameter values and its numeric answers (None
    where a cell is empty; ``warnings`` say why)."""

    file: str
    title: str
    statement: str
    questions: tuple[str, ...]  # the question kinds, in file order
    seed: int
    parameters: tuple[str, ...]  # the ranged parameters, in file order
    fixed: tuple[tuple[str, Number], ...]  # values every variant shares
    columns: tuple[str, ...]  # answer labels ('modes.eigenvalues[1]')
    draws: tuple[tuple[Number, ...], ...]  # per variant, per parameter
    answers: tuple[tuple[float | None, ...], ...]  # per variant, per column
    notes: tuple[str, ...] = ()
    warnings: tuple[str, ...] = ()
    verified: tuple[int, ...] = ()  # variant numbers (1-based) checked by a full solve
    kind_columns: tuple[str, ...] = ()  # answers that are kinds ('equilibria[1].stability')
    kinds: tuple[tuple[str | None, ...], ...] = ()  # per variant, per kind column (None: none claimed)
    units: tuple[tuple[str, str], ...] = ()  # parameter -> its SI unit ('' for a pure number), where known
    angles: frozenset[str] = frozenset()  # parameters written in angle units (30 deg): shown in degrees
