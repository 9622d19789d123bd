"""Saving a chart: PNG (for the docs) and SVG beside it, for report.py and scale.py."""

from __future__ import annotations

from pathlib import Path


def save(fig, stem: Path) -> None:
    fig.savefig(stem.with_suffix(".png"), dpi=110, bbox_inches="tight")
    fig.savefig(stem.with_suffix(".svg"), bbox_inches="tight")
