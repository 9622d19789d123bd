"""Numbers from exact answers: an answers tree evaluated at the parameter values (which
values a route needs, and the refusal that names those missing, are the routes':
solvers/routes/needed.py)."""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from enum import Enum
from typing import TYPE_CHECKING, Mapping

import sympy as sp
from sympy.core.function import AppliedUndef
from sympy.core.relational import Relational
from sympy.logic.boolalg import BooleanAtom, BooleanFunction

from rbdsolve.form.tidy import tidy_fraction
from rbdsolve.model.values.tree import label, leaves, map_paths

if TYPE_CHECKING:
    from rbdsolve.report.numbers import Path


SAMPLE_POINTS = (1, sp.Rational(13, 10), sp.Rational(17, 7))  # each symbol without a value, in turn


def sample(value: sp.Expr, values: Mapping[sp.Symbol, sp.Expr]) -> complex:
    """The value at the given parameter values, every other symbol set to 1 (or, where
    that divides by zero, as k − m Ω² does, to other plain numbers, each symbol its
    own): used to order symbolic results (eigenvalues, moments, equilibria) as they are
    at a sample. NaN where no sample gives a number."""
    free = sorted(value.free_symbols - set(values), key=str)
    for k, base in enumerate(SAMPLE_POINTS):
        point = {s: base + sp.Rational(k * i, 11) for i, s in enumerate(free)}
        try:
            z = complex(sp.N(value.xreplace({**point, **{s: values[s] for s in value.free_symbols if s in values}})))
        except (TypeError, ValueError):
            continue
        if math.isfinite(z.real) and math.isfinite(z.imag):
            return z
    return complex(math.nan, 0)


def parameter_sample(model, rng) -> dict[sp.Symbol, sp.Expr]:
    """The parameters at their values, the others at pseudo-random rationals in
    [1.1, 2.9] drawn from ``rng`` (seeded by the caller: the same every run): a generic
    point to test an identity, a rank or a twin at."""
    return {s: model.values.get(s, sp.Rational(rng.randint(1100, 2900), 1000))
            for s in model.symbols.parameters.values()}


# --- numeric values --------------------------------------------------------------------


def numeric(value: object, subs: Mapping[sp.Symbol, sp.Expr]) -> object:
    """Numeric values of an answers tree where every symbol has a value.

    Expressions become floats, matrices nested lists; anything that still holds a free
    symbol or a function of time becomes None, and so does a value that is not a real
    number (every quantity rbdsolve answers is real: a complex value is no value, never
    a pair of reals; ``not_real`` names them). Leaves that are not expressions stay as
    the answers give them (an enum as its value, a count, a text), so the tree reads
    like the answers.
    """
    return numbers(value, subs).tree


@dataclass(frozen=True)
class Numbers:
    """An answers tree's numeric values, and the paths of its leaves whose value is a
    number but not a real one (shown as None)."""

    tree: object
    not_real: tuple[Path, ...]


def numbers(value: object, subs: Mapping[sp.Symbol, sp.Expr]) -> Numbers:
    """``numeric``'s tree, with the paths of the values that are not real."""
    roots: dict[sp.Expr, sp.Expr] = {}
    complex_at: list[Path] = []

    def leaf(path: Path, x: object) -> object:
        if not isinstance(x, sp.Basic):
            return _plain(x)
        number = _number(x, subs, roots)
        if isinstance(number, complex):
            complex_at.append(path)
            return None
        return number

    tree = map_paths(value, leaf, row=lambda _, floats: list(floats))  # a numeric route's floats are their own values
    return Numbers(tree, tuple(complex_at))


def not_real(found: Numbers) -> str | None:
    """A warning naming the answers whose value at the parameter values is a complex
    number (shown as null), except those of a record whose own ``exists_when`` or
    ``when`` is false there (a steady motion that does not exist at these values says
    so itself; a stability case that does not hold there, such as the growth rate of a
    sleeping top spun above its least spin); None when there are none."""
    bad = [label(p) for p in found.not_real if not _absent_record(found.tree, p)]
    if not bad:
        return None
    shown = ", ".join(bad[:6]) + (f" and {len(bad) - 6} more" if len(bad) > 6 else "")
    return (f"no numeric value for {shown}: not a real number at the parameter values (a quantity that "
            "exists only where it is real); shown as null")


def _absent_record(tree: object, path: Path) -> bool:
    """Whether a record on the way to ``path`` has ``exists_when`` or ``when`` false, or
    is the frequencies of a motion unstable at the values (a gyroscopic one's roots ω
    are real only where it is stable; its growth rate is given instead)."""
    for part in path:
        if isinstance(tree, dict) and (tree.get("exists_when") is False or tree.get("when") is False):
            return True
        if isinstance(tree, dict) and part == "frequencies" and tree.get("stability") == "unstable":
            return True
        try:
            tree = tree[part]
        except (KeyError, IndexError, TypeError):
            return False
    return False


CONDITIONS = (Relational, BooleanAtom, BooleanFunction)  # exists_when, a case's when


def not_finite(value: object, subs: Mapping[sp.Symbol, sp.Expr]) -> str | None:
    """A warning naming the answers that hold no free symbol yet have no finite value at
    the parameter values (1e300**3 overflows a float; 1/(1 - 1) divides by zero), which
    the numbers show as null; None when there are none."""
    bad = []
    for path, leaf in leaves(value, floats=False):  # a float is its own value, finite or not
        if isinstance(leaf, sp.Basic) and not isinstance(leaf, sp.MatrixBase) and _overflows(leaf, subs):
            bad.append(label(path))
    if not bad:
        return None
    shown = ", ".join(bad[:6]) + (f" and {len(bad) - 6} more" if len(bad) > 6 else "")
    return (f"no numeric value for {shown}: not a finite floating-point number at the parameter values "
            "(an overflow past about 1.8e308, or a division by zero); shown as null")


def _overflows(leaf: sp.Basic, subs: Mapping[sp.Symbol, sp.Expr]) -> bool:
    if isinstance(leaf, CONDITIONS):
        return False  # a condition is true or false, never a number
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
            roots: dict[sp.Expr, sp.Expr] | None = None) -> float | complex | bool | None:
    """A leaf's value: a float, a complex where it is not real (the callers refuse it:
    ``numbers``), true or false for a condition, None where it has none."""
    if isinstance(value, float):
        return value  # a numeric route's answer
    if not isinstance(value, sp.Basic):
        return None  # enums, text: not numbers
    if isinstance(value, CONDITIONS):  # a condition: true or false at the values, if they decide it
        try:
            decided = value.xreplace(subs)
        except TypeError:  # a side not real, or infinite (a string through its own peg), at the values: undecided
            return None
        return bool(decided) if isinstance(decided, BooleanAtom) else None
    number = value.xreplace(subs)
    if roots is not None and number.has(sp.CRootOf):
        number = number.xreplace(_root_values(number, roots))
    if number.free_symbols or number.atoms(AppliedUndef) or number.has(sp.Derivative):
        number = _constant(number)
        if number is None:
            return None
    try:
        z = complex(sp.N(number, 17))
    except (TypeError, ValueError):
        return None
    if not (math.isfinite(z.real) and math.isfinite(z.imag)):
        return None
    return z.real if abs(z.imag) <= 1e-14 * max(1.0, abs(z.real)) else z


MAX_CONSTANT_OPS = 400  # larger leaves are not worth the reduction (they are rarely constant)


def _constant(number: sp.Expr) -> sp.Expr | None:
    """An entry that depends on the coordinates only through identities, as a turned
    cube's isotropic tensor R J Rᵀ = J does (sin² + cos² = 1), reduced to its constant
    value (``tidy_fraction``: sin and cos as symbols on the unit circle, exact); None
    when it does depend on them, or on a parameter without a value."""
    if number.has(sp.Derivative) or sp.count_ops(number) > MAX_CONSTANT_OPS:
        return None
    reduced = tidy_fraction(sp.expand_trig(number))
    return None if reduced.free_symbols or reduced.atoms(AppliedUndef) else reduced


def _root_values(number: sp.Expr, roots: dict[sp.Expr, sp.Expr]) -> dict[sp.Expr, sp.Expr]:
    """Each polynomial root to 50 digits, isolated once per answers tree (a mode shape
    holds the same root in every entry; isolating it again per entry dominated the
    time). 50 digits leave the 17 asked for intact unless an entry cancels 33 digits."""
    for root in number.atoms(sp.CRootOf):
        if root not in roots:
            roots[root] = root.evalf(50)
    return roots


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
