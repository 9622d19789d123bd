"""Standard output's Look, found without rich where it is no terminal (cli/writing.py),
is the Look rich's console gives: the same width and no colours, under each of the
variables rich reads."""

from __future__ import annotations

import io
import sys

import pytest
from rich.console import Console

from rbdsolve.cli.writing import Look, _plain_stdout


def richs() -> Look:
    console = Console()
    return Look(console.width, console.color_system, console.is_terminal, console.no_color)


@pytest.mark.parametrize("env", [{}, {"COLUMNS": "57"}, {"COLUMNS": "wide"}, {"NO_COLOR": "1"}, {"NO_COLOR": ""},
                                 {"LINES": "30"}, {"TERM": "dumb"}, {"COLUMNS": "0"}, {"FORCE_COLOR": "1"},
                                 {"TTY_COMPATIBLE": "0"}, {"TTY_COMPATIBLE": "1"}])
def test_a_pipe_looks_as_rich_sees_it(env: dict, monkeypatch) -> None:
    for name in ("COLUMNS", "LINES", "NO_COLOR", "FORCE_COLOR", "TTY_COMPATIBLE", "TERM"):
        monkeypatch.delenv(name, raising=False)
    for name, value in env.items():
        monkeypatch.setenv(name, value)
    monkeypatch.setattr(sys, "stdout", io.StringIO())  # a pipe: no terminal
    assert Look.of_stdout() == richs()
    plain = _plain_stdout()
    assert plain is None or plain == richs()
    if env in ({}, {"COLUMNS": "57"}, {"NO_COLOR": "1"}):
        assert plain is not None  # these are found without rich


def test_a_terminal_is_asked_of_rich(monkeypatch) -> None:
    class Terminal(io.StringIO):
        def isatty(self) -> bool:
            return True

    monkeypatch.setattr(sys, "stdout", Terminal())
    assert _plain_stdout() is None
