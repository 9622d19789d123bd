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

import difflib
from dataclasses import dataclass
from enum import IntEnum


class ExitCode(IntEnum):
    OK = 0
    UNSOLVED = 1
    BAD_INPUT = 2
    INTERNAL = 3


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
        head = f"{self.file}:{self.line}:{self.column}"
        path = self.key_path()
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
        return f"{self.location}: {self.message}" if self.location else self.message


class InternalError(RbdError):
    """A bug: reported in one line with exit code 3 (the traceback with --debug)."""

    exit_code = ExitCode.INTERNAL

    def __init__(self, message: str):
        self.message = message
        self.location = None
        super().__init__(message)


class UnsolvedError(RbdError):
    """A well-formed question that rbdsolve could not answer. Exit code 1."""

    exit_code = ExitCode.UNSOLVED

    def __init__(self, message: str):
        self.message = message
        self.location = None
        super().__init__(message)


def did_you_mean(word: str, choices: object) -> str:
    """A ' (did you mean 'x'?)' suffix naming the closest choice, or ''."""
    close = difflib.get_close_matches(word, [str(c) for c in choices], n=1, cutoff=0.6)
    if not close and word.lower() in {str(c).lower() for c in choices}:
        close = [c for c in map(str, choices) if c.lower() == word.lower()]
    return f" (did you mean '{close[0]}'?)" if close else ""
