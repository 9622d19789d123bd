"""A report as the text the terminal shows (render/terminal.py through rich), captured
into a string: for files, pipes, and the Python API's ``Result.to_text()``."""

from __future__ import annotations

import io
import re
from typing import TYPE_CHECKING

if TYPE_CHECKING:  # the report module imports sympy: not when only no_trailing_spaces is wanted
    from rbdsolve.report.steps import ProblemReport


def terminal_text(report: ProblemReport, width: int = 100, color_system: str | None = None,
                  terminal: bool = False, no_color: bool = False) -> str:
    """The rich rendering of one report, as the text (and colours, when a colour
    system is given) the console shows, ``width`` columns wide."""
    from rich.console import Console

    from rbdsolve.render.terminal import render

    console = Console(file=io.StringIO(), width=width, highlight=False, no_color=no_color,
                      color_system=color_system, force_terminal=terminal)
    console.print(render(report))
    return no_trailing_spaces(console.file.getvalue())


def no_trailing_spaces(text: str) -> str:
    """Each line without the spaces rich pads it with (before any closing colour code)."""
    return re.sub(r"[ \t]+((?:\x1b\[[0-9;]*m)*)$", r"\1", text, flags=re.MULTILINE)
