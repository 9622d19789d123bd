"""A report as the text the terminal shows, captured into a string: for files, pipes,
and the Python API's ``Result.to_text()``. In colour through rich (render/terminal.py);
without colour laid out here, without importing rich's console (about 20 ms of every
run's start), in the characters rich writes: prose wrapped between words as rich wraps
it, relations broken by render/wrap.py, the title's rule. What this layout does not
do itself (a word longer than the line, which rich folds; a tab; a title too long for
its rule) goes to rich, so the text is rich's in every case (tests/render/test_text.py
compares the two)."""

from __future__ import annotations

import io
import re
from typing import TYPE_CHECKING

if TYPE_CHECKING:  # the report module imports sympy: not when only no_trailing_spaces is wanted
    from rbdsolve.render.lines import Line
    from rbdsolve.report.steps import ProblemReport

RULE_CHARACTER = "─"  # rich's rule, on a console writing UTF-8 (a StringIO: rich takes it for UTF-8)
_WORD = re.compile(r"\s*\S+\s*")  # a word with the spaces after it (and, first on a line, before it)


def terminal_text(report: ProblemReport, width: int = 100, color_system: str | None = None,
                  terminal: bool = False, no_color: bool = False) -> str:
    """The rich rendering of one report, as the text (and colours, when a colour
    system is given) the console shows, ``width`` columns wide."""
    if color_system is None:
        from rbdsolve.render.lines import report_lines

        plain = plain_text(report_lines(report), width)
        if plain is not None:
            return no_trailing_spaces(plain)
    return rich_text(report, width, color_system, terminal, no_color)


def rich_text(report: ProblemReport, width: int = 100, color_system: str | None = None,
              terminal: bool = False, no_color: bool = False) -> str:
    """The report through rich's console (render/terminal.py), captured."""
    from rich.console import Console

    from rbdsolve.render.terminal import render

    console = Console(file=io.StringIO(), width=width, highlight=False, no_color=no_color,
                      color_system=color_system, force_terminal=terminal)
    console.print(render(report))
    return no_trailing_spaces(console.file.getvalue())


def plain_text(lines: list[Line], width: int) -> str | None:
    """The lines laid out ``width`` columns wide without colour, as rich lays them out;
    None where one needs what only rich does (a fold, a tab, a title cut short)."""
    from rbdsolve.render.lines import MATH, RULE
    from rbdsolve.render.wrap import wrap_math

    out: list[str] = []
    for line in lines:
        text = line.text
        if line.kind == RULE:
            shown = _rule(text, width)
        elif line.kind == MATH:
            shown = _joined([_prose(part, width) for part in wrap_math(text, width)])
        else:
            shown = _prose(text, width)
        if shown is None:
            return None
        out += [""] * line.gap + shown
    return "".join(f"{x}\n" for x in out)


def _rule(title: str, width: int) -> list[str] | None:
    """The title, a space, and the rule to the end of the line."""
    from rich.cells import cell_len

    if "\t" in title or "\n" in title or cell_len(title) > width - 2:
        return None
    return [f"{title} {RULE_CHARACTER * (width - cell_len(title) - 1)}"]


def _prose(text: str, width: int) -> list[str] | None:
    """Each line of ``text`` wrapped at ``width`` cells: greedily, word by word, a word
    that does not fit (its spaces after it aside) starting the next line."""
    from rich.cells import cell_len

    if "\t" in text:
        return None
    out = []
    for paragraph in text.split("\n"):
        start, used = 0, 0
        for word in _WORD.finditer(paragraph):
            length = cell_len(word.group().rstrip())
            if length > width:
                return None  # rich folds it, inside the word
            if used + length > width:
                out.append(paragraph[start:word.start()])
                start, used = word.start(), 0
            used += cell_len(word.group())
        out.append(paragraph[start:])
    return out


def _joined(parts: list[list[str] | None]) -> list[str] | None:
    return None if any(p is None for p in parts) else [x for p in parts for x in p]


def no_trailing_spaces(text: str) -> str:
    """Each line without the spaces rich pads it with (before any closing colour code)."""
    return re.sub(r"[ \t]+((?:\x1b\[[0-9;]*m)*)$", r"\1", text, flags=re.MULTILINE)
