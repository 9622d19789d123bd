"""The audit of issue 38: every problem in problems/ solved, then again with its values
set on each side of each critical value it prints, and no printed value fails its own
check (solvers/routes/checks.py runs on every answer: a failure leaves the question
unanswered with "rbdsolve's own check … failed") and none is a complex number printed
as a pair of reals.

A critical value p_c(a, b, …) is put at numbers: the problem's own values where it
gives them, else a sample inside its assumptions; p is then set to p_c (1 ∓ 5 %) with
the parameters p_c holds at those numbers. A side the problem's assumptions or signs
forbid (bad input there) is skipped.
"""

from __future__ import annotations

import random
from fractions import Fraction

import pytest
import sympy as sp

from conftest import PROBLEMS, solved_file
from rbdsolve.errors import InputError
from rbdsolve.model.values.tree import leaves
from rbdsolve.solvers import solve_problem
from rbdsolve.solvers.conditions.condition_roots import admissible
from rbdsolve.solvers.conditions.conditions import CriticalValue

FILES = sorted(p for p in PROBLEMS.rglob("*.yaml") if not p.name.endswith(".expected.yaml"))
SIDES = (Fraction(95, 100), Fraction(105, 100))


def _criticals(answers) -> list[CriticalValue]:
    """Every critical value an answers tree prints (a family's ``critical``, the modes
    about each equilibrium's own)."""
    found: list[CriticalValue] = []

    def walk(x) -> None:
        if isinstance(x, CriticalValue):
            found.append(x)
        elif isinstance(x, (tuple, list)):
            for y in x:
                walk(y)
        elif isinstance(x, dict):
            for y in x.values():
                walk(y)
        elif hasattr(x, "__dataclass_fields__") and not isinstance(x, type):
            for name in x.__dataclass_fields__:
                walk(getattr(x, name))

    walk(answers)
    return found


def _refusals(report) -> list[str]:
    """The questions refused by their own check, and any value printed as a pair."""
    out = [f"{s.question}: {s.error}" for s in report.solutions if s.error and "own check" in s.error]
    for s in report.solutions:
        for path, leaf in leaves(s.values):
            if isinstance(leaf, complex):
                out.append(f"{s.question}: a complex value at {path}")
    return out


def _sides(model, critical: CriticalValue) -> list[dict[str, Fraction]]:
    """Values for the parameters p_c holds and for p on each side of p_c."""
    p = model.symbols.parameters[critical.parameter]
    point = admissible(model, random.Random(38), (p,), {})
    if point is None:
        return []
    held = {s: point[s] for s in critical.value.free_symbols if s in point}
    z = complex(sp.N(critical.value.xreplace(held), 30))
    if abs(z.imag) > 1e-12 * abs(z) or z.real == 0:
        return []
    names = {s: n for n, s in model.symbols.parameters.items()}
    given = {names[s]: Fraction(str(sp.Rational(v))) for s, v in held.items() if s not in model.values}
    at = Fraction(repr(z.real))
    return [{**given, critical.parameter: at * side} for side in SIDES if (at * side > 0 or not p.is_positive)]


@pytest.mark.parametrize("path", FILES, ids=lambda p: str(p.relative_to(PROBLEMS)))
def test_no_printed_value_fails_its_own_check(path) -> None:
    model, report = solved_file(path)
    assert not _refusals(report)
    criticals = {(c.parameter, c.value): c for s in report.solutions if s.solved for c in _criticals(s.answers)}
    for critical in criticals.values():  # each once (equilibria and modes print the same Ω_c)
        for values in _sides(model, critical):
            try:
                moved = model.with_values(values)
            except InputError:
                continue  # a side the assumptions or the signs forbid
            refused = _refusals(solve_problem(moved))
            assert not refused, f"{critical.parameter} = {float(values[critical.parameter]):g}: {refused}"
