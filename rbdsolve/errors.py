"""One exception family for everything rbdsolve reports to a user.

The CLI maps each class to an exit code (documented in the README):

====  ==========================================================
0     every question solved
1     a question could not be answered (:class:`UnsolvedError`)
2     bad input or usage (:class:`InputError`)
3     internal error (anything else; traceback only with --debug)
====  ==========================================================
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from enum import IntEnum

# C0 controls but tab and newline, DEL, C1 (NEL U+0085 included), the bidirectional
# overrides and isolates (text that reads backwards), and the line and paragraph
# separators U+2028/U+2029: what can move a terminal's cursor, set its title, clear
# it, or make a line look other than it is; and lone surrogates (a YAML or JSON escape
# such as "\ud800" makes one), which no UTF-8 file or terminal can hold.
UNPRINTABLE = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f\u200e\u200f\u202a-\u202e\u2028\u2029\u2066-\u2069"
                         "\ud800-\udfff]")
_ALSO_IN_ONE_LINE = re.compile("[\t\n]")


def printable(text: str, lines: bool = False) -> str:
    """Text from a file or the command line, safe to show: each control character as
    its escape (ESC as \\x1b, U+202E as \\u202e). A message is one line, so tabs and
    newlines are escaped too unless ``lines`` (a statement keeps its lines)."""
    text = UNPRINTABLE.sub(_escaped, text)
    return text if lines else _ALSO_IN_ONE_LINE.sub(_escaped, text)


def clipped(text: str, width: int = 60) -> str:
    """The start of a long text (an expression, a cell), for a message that stays one
    readable line: 5,000 digits are said as their first 60 and how many there are."""
    return text if len(text) <= width else f"{text[:width]}… ({len(text):,} characters)"


def shown(value: object) -> str:
    """A value from outside (a key, a name given in Python) for a message: its type and
    its repr, clipped; never a second error (10**5000 has no repr: Python refuses to
    write more than 4,300 digits)."""
    try:
        return f"{type(value).__name__} {clipped(repr(value))}"
    except ValueError:
        return f"{type(value).__name__} (too large to show)"


def unprintable(text: str) -> str | None:
    """The first character ``printable`` would escape (tabs and newlines allowed), or None."""
    found = UNPRINTABLE.search(text)
    return found.group() if found else None


def _escaped(match: re.Match) -> str:
    code = ord(match.group())
    return f"\\x{code:02x}" if code <= 0xFF else f"\\u{code:04x}"


class ExitCode(IntEnum):
    OK = 0
    UNSOLVED = 1
    BAD_INPUT = 2
    INTERNAL = 3
    INTERRUPTED = 130  # 128 + SIGINT, the shells' convention
    TERMINATED = 143  # 128 + SIGTERM


@dataclass(frozen=True)
class Location:
    """Where a value came from: file, 1-based line and column, and its key path."""

    file: str
    line: int
    column: int
    path: tuple[str | int, ...] = ()

    def key_path(self) -> str:
        out = ""
        for part in self.path:
            if isinstance(part, int):
                out += f"[{part}]"
            else:
                out += f".{part}" if out else str(part)
        return out

    def shifted(self, columns: int) -> Location:
        return Location(self.file, self.line, self.column + columns, self.path)

    def __str__(self) -> str:
        head = f"{printable(self.file)}:{self.line}:{self.column}"
        path = printable(self.key_path())
        return f"{head}: {path}" if path else head


class RbdError(Exception):
    """Base of every error rbdsolve explains to the user in one line."""

    exit_code = ExitCode.INTERNAL


class InputError(RbdError):
    """Bad input: a problem file, an option or a value. Exit code 2."""

    exit_code = ExitCode.BAD_INPUT

    def __init__(self, message: str, location: Location | None = None):
        self.message = message
        self.location = location
        super().__init__(str(self))

    def __str__(self) -> str:
        message = printable(self.message)
        return f"{self.location}: {message}" if self.location else message


class InternalError(RbdError):
    """A bug: reported in one line with exit code 3 (the traceback with --debug)."""

    exit_code = ExitCode.INTERNAL

    def __init__(self, message: str):
        self.message = message
        self.location = None
        super().__init__(message)


NUMERIC_REMEDY = "give values for the parameters to solve it numerically"  # where only the exact route cannot


class UnsolvedError(RbdError):
    """A well-formed question that rbdsolve could not answer. Exit code 1. ``remedy``:
    what the user can do that only this route needs (NUMERIC_REMEDY; "give the rate
    exactly"), said after the reason, ``reason; remedy``: on auto, where another route
    answered, its note quotes the reason without it (``Solution.remedy``)."""

    exit_code = ExitCode.UNSOLVED

    def __init__(self, message: str, remedy: str = ""):
        self.reason = message
        self.remedy = remedy
        self.message = f"{message}; {remedy}" if remedy else message
        self.location = None
        super().__init__(self.message)

    def __str__(self) -> str:
        return printable(self.message)


def did_you_mean(word: str, choices: object) -> str:
    """A ' (did you mean 'x'?)' suffix naming the closest choice, or ''."""
    import difflib  # only when a name is wrong: ~1 ms of start-up otherwise

    close = difflib.get_close_matches(word, [str(c) for c in choices], n=1, cutoff=0.6)
    if not close and word.lower() in {str(c).lower() for c in choices}:
        close = [c for c in map(str, choices) if c.lower() == word.lower()]
    return f" (did you mean '{close[0]}'?)" if close else ""
