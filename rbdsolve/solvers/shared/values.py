"""Numbers from exact answers: an answers tree evaluated at the parameter values, and
the check that floating-point work has every value it needs."""

from __future__ import annotations

import dataclasses
import math
from enum import Enum
from typing import Mapping

import sympy as sp
from sympy.core.function import AppliedUndef

from rbdsolve.errors import UnsolvedError
from rbdsolve.report.tree import label, leaves, map_leaves


def sample(value: sp.Expr, values: Mapping[sp.Symbol, sp.Expr]) -> complex:
    """The value at the given parameter values, every other symbol set to 1: used to
    order symbolic results (eigenvalues, moments, equilibria) as they are at a sample."""
    return complex(sp.N(value.xreplace({s: values.get(s, 1) for s in value.free_symbols})))


# --- numeric values --------------------------------------------------------------------


def numeric(value: object, subs: Mapping[sp.Symbol, sp.Expr]) -> object:
    """Numeric values of an answers tree where every symbol has a value.

    Expressions become floats (or [re, im] when complex), matrices nested lists;
    anything that still holds a free symbol or a function of time becomes None. Leaves
    that are not expressions stay as the answers give them (an enum as its value, a
    count, a text), so the tree reads like the answers.
    """
    roots: dict[sp.Expr, sp.Expr] = {}
    return map_leaves(value, lambda leaf: _number(leaf, subs, roots) if isinstance(leaf, sp.Basic) else _plain(leaf))


def not_finite(value: object, subs: Mapping[sp.Symbol, sp.Expr]) -> str | None:
    """A warning naming the answers that hold no free symbol yet have no finite value at
    the parameter values (1e300**3 overflows a float; 1/(1 - 1) divides by zero), which
    the numbers show as null; None when there are none."""
    bad = []
    for path, leaf in leaves(value):
        if isinstance(leaf, sp.Basic) and not isinstance(leaf, sp.MatrixBase) and _overflows(leaf, subs):
            bad.append(label(path))
    if not bad:
        return None
    shown = ", ".join(bad[:6]) + (f" and {len(bad) - 6} more" if len(bad) > 6 else "")
    return (f"no numeric value for {shown}: not a finite floating-point number at the parameter values "
            "(an overflow past about 1.8e308, or a division by zero); shown as null")


def _overflows(leaf: sp.Basic, subs: Mapping[sp.Symbol, sp.Expr]) -> bool:
    number = leaf.xreplace(subs)
    if number.free_symbols or number.atoms(AppliedUndef) or number.has(sp.Derivative, sp.CRootOf):
        return False
    try:
        z = complex(sp.N(number, 17))
    except (TypeError, ValueError):
        return False
    return not (math.isfinite(z.real) and math.isfinite(z.imag))


def _plain(leaf: object) -> object:
    """A leaf that is not an expression: an enum as its value, else itself (a float, an
    int, a text, None)."""
    return leaf.value if isinstance(leaf, Enum) else leaf


def _number(value: object, subs: Mapping[sp.Symbol, sp.Expr],
            roots: dict[sp.Expr, sp.Expr] | None = None) -> float | list | None:
    if isinstance(value, float):
        return value  # a numeric route's answer
    if not isinstance(value, sp.Basic):
        return None  # enums, text: not numbers
    number = value.xreplace(subs)
    if roots is not None and number.has(sp.CRootOf):
        number = number.xreplace(_root_values(number, roots))
    if number.free_symbols or number.atoms(AppliedUndef) or number.has(sp.Derivative):
        return None
    try:
        z = complex(sp.N(number, 17))
    except (TypeError, ValueError):
        return None
    if not (math.isfinite(z.real) and math.isfinite(z.imag)):
        return None
    return z.real if abs(z.imag) <= 1e-14 * max(1.0, abs(z.real)) else [z.real, z.imag]


def _root_values(number: sp.Expr, roots: dict[sp.Expr, sp.Expr]) -> dict[sp.Expr, sp.Expr]:
    """Each polynomial root to 50 digits, isolated once per answers tree (a mode shape
    holds the same root in every entry; isolating it again per entry dominated the
    time). 50 digits leave the 17 asked for intact unless an entry cancels 33 digits."""
    for root in number.atoms(sp.CRootOf):
        if root not in roots:
            roots[root] = root.evalf(50)
    return roots


def missing_values(model, free: tuple[str, ...] = ()) -> tuple[str, ...]:
    """The parameters without a numeric value, in the file's order, except those in
    ``free`` (a route's own unknowns: steady_motion solves for omega0): floating-point
    work (every numeric route, and auto's fallback to it) needs none missing."""
    return tuple(p.name for p in model.problem.parameters
                 if p.name not in free and model.symbols.parameters[p.name] not in model.values)


def require_values(model, what: str, free: tuple[str, ...] = ()) -> None:
    """Refuse floating-point work while ``missing_values`` is not empty, naming them."""
    missing = missing_values(model, free)
    if missing:
        raise UnsolvedError(f"{what} needs a value for every parameter{_except(free)}; give "
                            f"{', '.join(missing)} ('values:' in the file, or --set NAME=VALUE)")


def _except(free: tuple[str, ...]) -> str:
    return f" except {', '.join(free)} (solved for)" if free else ""


def with_floats(value: object, subs: Mapping[sp.Symbol, sp.Expr]) -> object:
    """The same answers (dataclasses, mappings, tuples kept) with every sympy leaf put
    to a float at the parameter values (None where that is not a real number)."""
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        return dataclasses.replace(value, **{f.name: with_floats(getattr(value, f.name), subs)
                                            for f in dataclasses.fields(value)})
    if isinstance(value, Mapping):
        return {k: with_floats(v, subs) for k, v in value.items()}
    if isinstance(value, tuple):
        return tuple(with_floats(v, subs) for v in value)
    if isinstance(value, sp.Basic):
        number = _number(value, subs)
        return number if isinstance(number, float) else None
    return value
