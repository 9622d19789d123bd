"""Numeric values as text lines, for every renderer (no rich here)."""

from __future__ import annotations


def numeric_lines(values: object, prefix: str = "") -> list[str]:
    """Flatten a numeric values tree into 'name = value' lines, skipping the empty."""
    if isinstance(values, dict):
        return [line for k, v in values.items() for line in numeric_lines(v, f"{prefix}{k}" if not prefix else f"{prefix}.{k}")]
    if isinstance(values, list) and values and all(isinstance(v, float) or v is None for v in values):
        if all(v is None for v in values):
            return []
        return [f"{prefix} = [" + ", ".join("—" if v is None else f"{v:.6g}" for v in values) + "]"]
    if isinstance(values, list):
        return [line for i, v in enumerate(values, 1) for line in numeric_lines(v, f"{prefix}[{i}]")]
    if isinstance(values, float):
        return [f"{prefix} = {values:.6g}"]
    return []


def route_text(solution) -> str:
    """'numeric, 0.23 s, relative error ≤ 1.0e-15': how a question was answered."""
    text = f"{solution.route.value}, {solution.seconds:.2f} s"
    if solution.error_estimate is not None:
        text += f", relative error ≤ {solution.error_estimate:.1e}"
    return text
