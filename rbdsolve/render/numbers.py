"""Numeric values as text lines, for every renderer (no rich here)."""

from __future__ import annotations

from rbdsolve.form.printers import NOISE, float_latex, float_text, latex_name, point_text, relation_text, unicode_name
from rbdsolve.report.numbers import Beside, Note, Number
from rbdsolve.report.numbers import Path
from rbdsolve.model.values.tree import label


ACCURACY = frozenset({"absolute_errors", "relative_errors", "absolute_error", "shape_errors", "condition_M",
                      "spread", "residual", "residuals", "bound", "starts"})
MODES_ACCURACY = ACCURACY | {"conditions"}  # modes: condition numbers (equilibria: where one exists)


def accuracy_keys(question: str) -> frozenset[str]:
    """The keys of a question's numeric values that say how accurate its answers are
    (bounds, condition numbers, residuals, the search's count): shown apart from the
    answers, in a quieter block under them."""
    return MODES_ACCURACY if question == "modes" else ACCURACY


def accuracy_lines(solution) -> list[str]:
    """How accurate a numeric route's answers are (bounds, residuals), as lines; those of
    modes about each of several equilibria under the equilibrium's coordinates, each
    named as in the one-equilibrium case (not by its JSON path, modes[2].spread)."""
    only = accuracy_keys(solution.question)
    entries = solution.values.get("modes") if isinstance(solution.values, dict) else None
    if not (isinstance(entries, list) and len(entries) > 1 and all(isinstance(e, dict) for e in entries)):
        return numeric_lines(solution.values, solution.units, only=only)
    out = []
    for i, entry in enumerate(entries):
        lines = numeric_lines(entry, _part(_part(solution.units, "modes"), i), only=only)
        out += [f"About {point_text(entry.get('about') or {})}:", *("  " + line for line in lines)] if lines else []
    return out


def groups(numbers: tuple[Number, ...]) -> list[tuple[str, list[Number]]]:
    """The numeric block's lines under their headings (Equilibrium 2, Branch 1; '' for
    none): consecutive lines of one heading together, and a heading met again (a steady
    motion's Ω per solution, then its ω per solution) joins its first place, so each
    solution's numbers stand under one heading."""
    out: list[tuple[str, list[Number]]] = []
    named: dict[str, list[Number]] = {}
    for n in numbers:
        if n.accuracy:
            continue
        if out and out[-1][0] == n.group:
            out[-1][1].append(n)
        elif n.group and n.group in named:
            named[n.group].append(n)
        else:
            out.append((n.group, [n]))
            if n.group:
                named[n.group] = out[-1][1]
    return out


def number_text(n: Number) -> str:
    """'ω₁ = 4.33995 rad/s (period 1.44778 s)': a line of the numeric block in unicode."""
    return relation_text(n.relation) + tail_text(n)


def tail_text(n: Number) -> str:
    """' rad/s (period 1.44778 s)': what follows a number's math, its unit and note; a
    tuple's degrees after an equals sign, ' rad = (0°, 180°)', not in a second pair of
    brackets."""
    note = note_text(n.note)
    if n.note is not None and n.note.kind is Beside.OPEN:
        # the unit inside the note: after a sum, "+ 58.86 1/s²" would read as the last term's
        return f" (in {unit_text(n.unit).strip()}, {note})" if n.unit else f" ({note})"
    if note.startswith("("):
        return unit_text(n.unit) + f" = {note}"
    return unit_text(n.unit) + (f" ({note})" if note else "")


def note_text(note: Note | None) -> str:
    """'period 1.44778 s', '60°', '(0°, 180°)', '20 %', 'an energy gained', 'in 1/s², k in m': a note beside
    a number, its numbers to the significant digits asked (form.printers.digits), as the
    number itself is printed."""
    if note is None:
        return ""
    shown = [float_text(x) for x in note.values]
    if note.kind is Beside.PERIOD:
        return f"period {shown[0]} s"
    if note.kind is Beside.PERCENT:
        return f"{shown[0]} %"
    if note.kind is Beside.GAINED:
        return "an energy gained"
    if note.kind is Beside.OPEN:
        name, unit = note.open
        if unit is None:  # its dimension not known: it is read in SI units all the same
            return f"{unicode_name(name)} in SI units"
        return f"{unicode_name(name)} in {unit}" if unit else f"{unicode_name(name)} a number"
    degrees = [f"{x}°" for x in shown]
    return degrees[0] if len(degrees) == 1 else "(" + ", ".join(degrees) + ")"


def numeric_lines(values: object, units: object = None, path: Path = (), skip: frozenset[str] = frozenset(),
                  only: frozenset[str] | None = None) -> list[str]:
    """Flatten a numeric values tree into 'name = value unit' lines, skipping the empty;
    names are spelled by ``model.values.tree.label``; ``units`` is the same tree of SI units
    (``Solution.units``; None or '' where there is none to print). ``skip``: keys left
    out at any depth; ``only``: just the keys named, at any depth, whole. Numbers to the
    significant digits asked (form.printers.digits); an entry of a list of values that
    is zero within rounding beside the list's largest is 0 (the residue of a
    cancellation; bounds and residuals are printed as they are)."""
    prefix = label(path)
    if isinstance(values, dict):
        return [line for k, v in values.items() if k not in skip
                for line in numeric_lines(v, _part(units, k), (*path, k), skip, None if only is None or k in only
                                          else only)]
    if only is not None and not (isinstance(values, list) and not _flat(values)):
        return []
    if isinstance(values, list) and _flat(values):
        if all(v is None for v in values):
            return []
        shown = {_part(units, i) for i, v in enumerate(values) if v is not None}
        unit = shown.pop() if len(shown) == 1 else None
        zeroed = not (path and isinstance(path[-1], str) and path[-1] in ACCURACY | MODES_ACCURACY)
        scale = max(abs(v) for v in values if v is not None)
        texts = ["—" if v is None else "0" if zeroed and abs(v) <= NOISE * scale else float_text(v) for v in values]
        return [f"{prefix} = [" + ", ".join(texts) + "]" + unit_text(unit)]
    if isinstance(values, list):
        return [line for i, v in enumerate(values) for line in numeric_lines(v, _part(units, i), (*path, i), skip, only)]
    if isinstance(values, float):
        return [f"{prefix} = {float_text(values)}" + unit_text(units) + _negative_reading(path, values, units)]
    return []


# A negative value of these reads as its opposite (an impulse that adds energy loses none)
NEGATIVE_READS = {"energy_lost": "energy gained"}


def _negative_reading(path: Path, value: float, units: object) -> str:
    word = NEGATIVE_READS.get(path[-1]) if path and isinstance(path[-1], str) else None
    return f" (an {word} of {float_text(-value)}{unit_text(units)})" if word and value < 0 else ""


def _flat(values: list) -> bool:
    return bool(values) and all(isinstance(v, float) or v is None for v in values)


def _part(units: object, key: str | int) -> object:
    if isinstance(units, dict):
        return units.get(key)
    if isinstance(units, list) and isinstance(key, int) and key < len(units):
        return units[key]
    return None


def value_latex(name: str, value: float) -> str:
    """'\\Omega = 3', 'v_{0} = 300': a parameter's value as LaTeX math (its name as the
    answers print it, the number to the digits asked)."""
    return f"{latex_name(name)} = {float_latex(value)}"


def unit_text(unit: object) -> str:
    """' kg·m²' after a number, '' where there is no unit to print."""
    return f" {unit}" if isinstance(unit, str) and unit else ""


def route_text(solution) -> str:
    """'numeric, 0.23 s, relative error ≤ 1.0e-15': how a question was answered."""
    text = f"{solution.route.value}, {solution.seconds:.2f} s"
    if solution.error_estimate is not None:
        text += f", relative error ≤ {solution.error_estimate:.1e}"
    return text
