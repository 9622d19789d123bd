"""Each file's answer turned into text on its own: a file whose report cannot be
rendered (a bug in a renderer) becomes that file's failure, and every other file's
solution and JSON line is still written."""

from __future__ import annotations

import os
import sys
import time
from dataclasses import dataclass
from typing import Callable

from rbdsolve.cli.batch import Outcome, crashed
from rbdsolve.render.text import terminal_text


@dataclass(frozen=True)
class Piece:
    """One file's text in the chosen format ('' for a failure outside JSON), and its
    outcome (a rendering failure folded in)."""

    outcome: Outcome
    text: str


@dataclass(frozen=True)
class Look:
    """How terminal output looks where it goes: a file gets 100 columns, no colour."""

    width: int = 100
    color_system: str | None = None
    terminal: bool = False
    no_color: bool = False

    @staticmethod
    def of_stdout() -> Look:
        """How rich's console would write to standard output; where that is plainly no
        terminal, found without rich (``_plain_stdout``: its console costs a run ~15 ms)."""
        plain = _plain_stdout()
        if plain is not None:
            return plain
        from rich.console import Console

        console = Console()
        return Look(console.width, console.color_system, console.is_terminal, console.no_color)


_TERMINAL_SAYERS = ("FORCE_COLOR", "TTY_COMPATIBLE")  # rich takes these over isatty()


def _plain_stdout() -> Look | None:
    """The Look rich's console gives standard output when it is no terminal (a pipe, a
    file): no colours, and rich's width (COLUMNS, else the first of standard input,
    output and error that is a terminal, else 80). None where rich must be asked:
    standard output a terminal, or anything else that decides it (the variables above,
    Windows, a notebook or IDLE)."""
    if sys.platform == "win32" or any(name in os.environ for name in _TERMINAL_SAYERS):
        return None
    if "IPython" in sys.modules or "idlelib" in sys.modules or _isatty(sys.stdout):
        return None
    width = _width()
    if width is None:
        return None
    return Look(width, None, False, os.environ.get("NO_COLOR", "") != "")


def _isatty(stream) -> bool:
    try:
        return stream is None or stream.isatty()  # no stream: rich's own question
    except (AttributeError, ValueError):
        return True


def _width() -> int | None:
    columns = os.environ.get("COLUMNS")
    if columns is not None and columns.isdigit():
        return int(columns) or None  # COLUMNS=0: rich's own answer
    for descriptor in (0, 1, 2):
        try:
            return os.get_terminal_size(descriptor).columns or 80
        except (OSError, ValueError):
            pass
    return 80


def rendered(outcomes: list[Outcome], fmt: str, look: Look = Look(), debug: bool = False,
             digits: int | None = None) -> list[Piece]:
    """Every outcome's text, each rendered inside its own guard, numbers in text to
    ``digits`` significant digits (the printers' default where None)."""
    from contextlib import nullcontext

    render = _renderer(fmt, look)
    if digits is None:
        shown = nullcontext()
    else:
        from rbdsolve.form.printers import significant_digits

        shown = significant_digits(digits)
    with shown:
        return [_guarded(outcome, render, fmt, debug) for outcome in outcomes]


def _guarded(outcome: Outcome, render: Callable, fmt: str, debug: bool) -> Piece:
    if outcome.report is None:
        return Piece(outcome, _error_line(outcome) if fmt == "json" else "")
    start = time.perf_counter()
    try:
        return Piece(outcome, render(outcome.report))
    except Exception as exc:  # noqa: BLE001 - one file's rendering bug must not lose the others
        if debug:
            import traceback  # only for a bug's traceback (--debug)

            traceback.print_exc()
        failed = crashed(outcome.source, exc, outcome.seconds + time.perf_counter() - start)
        return Piece(failed, _error_line(failed) if fmt == "json" else "")


def _error_line(outcome: Outcome) -> str:
    from rbdsolve.render.json import render_error

    return render_error(outcome.source, outcome.failure)


def _renderer(fmt: str, look: Look) -> Callable:
    if fmt == "json":
        from rbdsolve.render.json import render_report

        return render_report
    if fmt == "markdown":
        from rbdsolve.render.markdown import render

        return lambda report: render(report) + "\n"
    if fmt == "latex":
        from rbdsolve.render.latex import body

        return lambda report: "\n".join(body(report))
    return lambda report: rendered_text(report, look)


def rendered_text(report, look: Look) -> str:
    """The rich rendering of one report, as the text (and colours) the console shows."""
    return terminal_text(report, look.width, look.color_system, look.terminal, look.no_color)


def joined(fmt: str, pieces: list[Piece]) -> str:
    """The whole output: the pieces in file order (a LaTeX document around them)."""
    texts = [p.text for p in pieces if p.text]
    if fmt == "markdown":
        return "".join(texts)[:-1]  # one blank line between problems, none after the last
    if fmt == "latex":
        if not texts:
            return ""
        from rbdsolve.render.latex import document

        reports = [p.outcome.report for p in pieces if p.text]
        return document(reports[0].title if len(reports) == 1 else "Solutions", texts)
    return "".join(texts)
