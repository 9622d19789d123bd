"""The numeric block: each named answer's value and unit as one line (report/numbers.py).

    numbers(named, answers, values, units) -> tuple[Number, ...]

``values`` and ``units`` are the trees ``values.numeric`` and ``units.answer_units``
make of the answers; a family's ``named`` says which path is printed as which name. A
line is written only where every number in it is known: an answer that is still a
function of the coordinates (a centre of mass that moves), or that holds an unknown no
question solved for, has no number, and no dash stands in for one. Beside the value:

- the unit, one for the line where its entries share one, else a line per entry
  (M₁₂ = 0.36 kg·m, for a matrix over a length and an angle);
- an angle (a value in rad) also in degrees, 180°/π times it;
- a frequency ω with its period 2π/ω;
- an energy lost that is negative as the energy gained, and a fraction as a percentage.
"""

from __future__ import annotations

import math
from typing import Iterable, Mapping

import sympy as sp
from sympy.core.function import AppliedUndef

from rbdsolve.form.display import Relation
from rbdsolve.report.numbers import Beside, Meaning, Named, Note, Number, Path


def numbers(named: Iterable[Named], answers: object, values: object, units: object,
            given: Mapping[sp.Symbol, sp.Expr] = {}, open_units: Mapping[sp.Symbol, str] = {}) -> tuple[Number, ...]:
    """The lines of the numeric block, in the order the names come. ``given``: the
    parameters' values; ``open_units``: the parameters without one, with their SI units
    (a value that holds one of them alone is written with the others put in:
    ``_partial``)."""
    return tuple(line for n in named for line in _lines(n, at(answers, n.path), at(values, n.path),
                                                            at(units, n.path), given, open_units))


_MISSING = object()


def at(tree: object, path: Path) -> object:
    """The subtree at ``path`` (keys of mappings and dataclasses, indices of sequences),
    or None where the tree has no such branch."""
    for step in path:
        if isinstance(tree, dict):
            tree = tree.get(step, None) if isinstance(step, str) else None
        elif isinstance(tree, (list, tuple)) and isinstance(step, int) and 0 <= step < len(tree):
            tree = tree[step]
        elif isinstance(step, str) and hasattr(tree, "__dataclass_fields__"):
            tree = getattr(tree, step, None)
        elif isinstance(tree, sp.MatrixBase) and isinstance(step, int):
            tree = tree.tolist()[step] if tree.rows > 1 or len(path) > 1 else tree[step]
        else:
            return None
    return tree


def _lines(n: Named, answer: object, value: object, unit: object, given: Mapping = {},
           open_units: Mapping = {}) -> list[Number]:
    if value is None:
        return _partial(n, answer, unit, given, open_units)
    if isinstance(value, dict):  # a state: coordinate -> value, printed as its name's tuple
        units = [unit.get(k) for k in value] if isinstance(unit, dict) else _as_list(unit, len(value))
        return _state(n, list(value.values()), units)
    if _number(value):
        return [_scalar(n, n.name, float(value), unit)]
    if _complex(answer, value):
        return [_line(n, n.name, sp.Float(value[0]) + sp.Float(value[1]) * sp.I, _text(unit))]
    if isinstance(value, list) and value and not _known(value):
        return _partial_vector(n, answer, value, unit, given, open_units)
    if not isinstance(value, list) or not value:
        return []
    if all(_number(v) for v in value):  # a vector
        return _vector(n, [float(v) for v in value], _as_list(unit, len(value)))
    if all(isinstance(v, list) and v and all(_number(x) for x in v) for v in value):  # a matrix
        return _matrix(n, value, unit)
    return []


def _partial(n: Named, answer: object, unit: object, given: Mapping, open_units: Mapping) -> list[Number]:
    """A scalar answer that holds, once the values are put in, one parameter left without
    a value and nothing else (no coordinate, no time): written with the numbers in,
    λ₁ = 24.525/(100 k² + 1) (in 1/s², k in m) — an exam that leaves k open still wants the
    rest as numbers. Roots keep their exponent (√, not ^0.5). Only where the value's
    unit is known ('' for a pure number)."""
    if not given or not isinstance(answer, sp.Expr) or isinstance(answer, sp.MatrixBase) or answer.is_number:
        return []
    if unit is None:  # its dimension not known (g with no value has none): a bare 0.3196 g is not written
        return []
    if answer.atoms(AppliedUndef):
        return []
    expr = answer.xreplace(dict(given))
    free = expr.free_symbols
    if len(free) != 1 or next(iter(free)) not in open_units:
        return []
    (p,) = free
    return [_line(n, n.name, _in_numbers(expr), _text(unit), Note(Beside.OPEN, open=(p.name, open_units[p])))]


def _in_numbers(expr: sp.Expr) -> sp.Expr:
    """An answer with the values put in, its numbers to 15 digits; roots keep their
    exponent (√, not ^0.5)."""
    return sp.N(expr, 15).replace(lambda x: x.is_Pow and x.exp.is_Float, lambda x: sp.Pow(x.base, sp.nsimplify(x.exp)))


def _partial_vector(n: Named, answer: object, value: list, unit: object, given: Mapping,
                    open_units: Mapping) -> list[Number]:
    """A vector answer whose entries are numbers or hold, once the values are put in, the
    same one parameter left without a value (``_partial``'s scalars, side by side): a ball's
    velocity after it strikes a hanging rod at a depth b left open, u_B = (3.4641 (0.6 b²
    − 0.729)/(0.6 b² + 1.215), −2, 0) (in m/s, b in m). Only where every entry's unit is
    the same."""
    entries = list(answer) if isinstance(answer, (tuple, list, sp.MatrixBase)) else None
    units = _as_list(unit, len(value))
    if not given or not entries or len(entries) != len(value) or not all(v is None or _number(v) for v in value):
        return []  # (a matrix's rows are lists: not written so)
    if not all(isinstance(u, str) for u in units) or len(set(units)) != 1:
        return []  # every entry's unit known, and the same
    shared = units[0]
    if not all(isinstance(e, sp.Expr) for e in entries) or any(e.atoms(AppliedUndef) for e in entries):
        return []
    put = [e.xreplace(dict(given)) for e in entries]
    free = set().union(*(e.free_symbols for e in put))
    if len(free) != 1 or next(iter(free)) not in open_units:
        return []
    (p,) = free
    numbers = sp.ImmutableMatrix([[_in_numbers(e) for e in put]])
    return [_line(n, n.name, numbers, shared, Note(Beside.OPEN, open=(p.name, open_units[p])))]


def _number(value: object) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)


def _complex(answer: object, value: object) -> bool:
    """A scalar answer whose value is [re, im] (values.numeric writes a complex number so)."""
    return (isinstance(answer, sp.Expr) and not isinstance(answer, sp.MatrixBase) and isinstance(value, list)
            and len(value) == 2 and all(_number(v) for v in value))


def _known(value: object) -> bool:
    if isinstance(value, list):
        return all(_known(v) for v in value)
    return _number(value)


def _as_list(unit: object, size: int) -> list:
    return list(unit) if isinstance(unit, list) and len(unit) == size else [unit] * size


def _text(unit: object) -> str:
    return unit if isinstance(unit, str) else ""


def _shared(units: list) -> str | None:
    """The one unit of a vector's or a matrix's entries, else None (they differ, or one
    is unknown while another is not)."""
    found = {_text(u) for u in units}
    return found.pop() if len(found) == 1 else None


def _line(n: Named, name: sp.Basic, value: sp.Basic, unit: str, note: Note | None = None) -> Number:
    return Number(Relation(name, value), unit, note, n.group, n.accuracy, n.path)


def _scalar(n: Named, name: sp.Basic, x: float, unit: object) -> Number:
    unit = _text(unit)
    if n.meaning is Meaning.ENERGY_LOST and x < 0:  # read as the energy gained: T_f − Tᵢ
        return _line(n, -name, sp.Float(-x), unit, Note(Beside.GAINED))
    note = None
    if n.meaning is Meaning.FREQUENCY and x > 0:
        note = Note(Beside.PERIOD, (2 * math.pi / x,))
    elif n.meaning is Meaning.FRACTION:
        note = Note(Beside.PERCENT, (100 * x,))
    elif unit == "rad":
        note = _degrees([x])
    if n.meaning is Meaning.LEAST:
        return Number(Relation(name, sp.Float(x), op="≥"), unit, note, n.group, n.accuracy, n.path)
    return _line(n, name, sp.Float(x), unit, note)


def _degrees(xs: list[float]) -> Note | None:
    """Angles in degrees (60°, (0°, 180°)), where any is not 0."""
    if all(x == 0 for x in xs):
        return None
    return Note(Beside.DEGREES, tuple(math.degrees(x) for x in xs))


def _state(n: Named, xs: list, units: list) -> list[Number]:
    """(θ, φ) = (0, 3.14159) rad: a configuration, its coordinates in the name's order;
    one line per coordinate where their units differ (x in m, θ in rad)."""
    names = list(n.name) if isinstance(n.name, (sp.Tuple, tuple)) else [n.name]
    if not all(_number(x) for x in xs) or len(names) != len(xs):
        return []
    unit = _shared(units)
    if len(xs) == 1 or unit is None:
        return [_scalar(n, name, float(x), u) for name, x, u in zip(names, xs, units)]
    note = _degrees([float(x) for x in xs]) if unit == "rad" else None
    return [_line(n, sp.Tuple(*names), sp.Tuple(*[sp.Float(float(x)) for x in xs]), unit, note)]


def _vector(n: Named, xs: list[float], units: list) -> list[Number]:
    unit = _shared(units)
    if unit is None:  # entries of different units: each on its own line, the name indexed
        return [_scalar(n, _entry(n.name, str(i + 1)), x, u) for i, (x, u) in enumerate(zip(xs, units))]
    note = _degrees(xs) if unit == "rad" else None
    return [_line(n, n.name, sp.ImmutableMatrix([[sp.Float(x) for x in xs]]), unit, note)]


def _matrix(n: Named, rows: list[list], unit: object) -> list[Number]:
    units = [_as_list(u, len(rows[0])) for u in _as_list(unit, len(rows))]
    shared = _shared([u for row in units for u in row])
    if shared is None:
        return [_scalar(n, _entry(n.name, f"{i + 1}{j + 1}"), float(x), units[i][j])
                for i, row in enumerate(rows) for j, x in enumerate(row) if j >= i or rows[j][i] != x]
    return [_line(n, n.name, sp.ImmutableMatrix([[sp.Float(float(x)) for x in row] for row in rows]), shared)]


def _entry(name: sp.Basic, index: str) -> sp.Basic:
    """M → M₁₂, v_A → v_A,2: an entry of a named vector or matrix."""
    if isinstance(name, sp.Symbol):
        return sp.Symbol(f"{name.name},{index}" if "_" in name.name else f"{name.name}_{index}")
    return sp.Symbol(f"({name})_{index}")
