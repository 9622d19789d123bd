"""Numeric values as text lines, for every renderer (no rich here)."""

from __future__ import annotations

from rbdsolve.report.tree import Path, label


def numeric_lines(values: object, path: Path = ()) -> list[str]:
    """Flatten a numeric values tree into 'name = value' lines, skipping the empty; names
    are spelled by ``report.tree.label``."""
    prefix = label(path)
    if isinstance(values, dict):
        return [line for k, v in values.items() for line in numeric_lines(v, (*path, k))]
    if isinstance(values, list) and values and all(isinstance(v, float) or v is None for v in values):
        if all(v is None for v in values):
            return []
        return [f"{prefix} = [" + ", ".join("—" if v is None else f"{v:.6g}" for v in values) + "]"]
    if isinstance(values, list):
        return [line for i, v in enumerate(values) for line in numeric_lines(v, (*path, i))]
    if isinstance(values, float):
        return [f"{prefix} = {values:.6g}"]
    return []


def route_text(solution) -> str:
    """'numeric, 0.23 s, relative error ≤ 1.0e-15': how a question was answered."""
    text = f"{solution.route.value}, {solution.seconds:.2f} s"
    if solution.error_estimate is not None:
        text += f", relative error ≤ {solution.error_estimate:.1e}"
    return text
