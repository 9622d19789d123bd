"""Numeric values as text lines, for every renderer (no rich here)."""

from __future__ import annotations

from rbdsolve.report.tree import Path, label


def numeric_lines(values: object, units: object = None, path: Path = ()) -> list[str]:
    """Flatten a numeric values tree into 'name = value unit' lines, skipping the empty;
    names are spelled by ``report.tree.label``; ``units`` is the same tree of SI units
    (``Solution.units``; None or '' where there is none to print)."""
    prefix = label(path)
    if isinstance(values, dict):
        return [line for k, v in values.items() for line in numeric_lines(v, _part(units, k), (*path, k))]
    if isinstance(values, list) and values and all(isinstance(v, float) or v is None for v in values):
        if all(v is None for v in values):
            return []
        shown = {_part(units, i) for i, v in enumerate(values) if v is not None}
        unit = shown.pop() if len(shown) == 1 else None
        return [f"{prefix} = [" + ", ".join("—" if v is None else f"{v:.6g}" for v in values) + "]" + unit_text(unit)]
    if isinstance(values, list):
        return [line for i, v in enumerate(values) for line in numeric_lines(v, _part(units, i), (*path, i))]
    if isinstance(values, float):
        return [f"{prefix} = {values:.6g}" + unit_text(units)]
    return []


def _part(units: object, key: str | int) -> object:
    if isinstance(units, dict):
        return units.get(key)
    if isinstance(units, list) and isinstance(key, int) and key < len(units):
        return units[key]
    return None


def unit_text(unit: object) -> str:
    """' kg·m²' after a number, '' where there is no unit to print."""
    return f" {unit}" if isinstance(unit, str) and unit else ""


def route_text(solution) -> str:
    """'numeric, 0.23 s, relative error ≤ 1.0e-15': how a question was answered."""
    text = f"{solution.route.value}, {solution.seconds:.2f} s"
    if solution.error_estimate is not None:
        text += f", relative error ≤ {solution.error_estimate:.1e}"
    return text
