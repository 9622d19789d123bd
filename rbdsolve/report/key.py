"""An answer key: one document for a whole exam, problem by problem, each with its
statement, its pictures and its step-by-step solution (render/ lays it out)."""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import PurePath

from rbdsolve.report.steps import ProblemReport


@dataclass(frozen=True)
class Picture:
    """A figure file for the key, its path relative to the key document."""

    path: PurePath
    caption: str


@dataclass(frozen=True)
class KeyEntry:
    """One problem of the exam: its report, or why it has none (a bad file)."""

    source: str
    report: ProblemReport | None
    failure: str | None = None
    pictures: tuple[Picture, ...] = ()


@dataclass(frozen=True)
class AnswerKey:
    title: str
    entries: tuple[KeyEntry, ...]


def default_title(folders: list[str], sources: list[str]) -> str:
    """A title for a key nobody named: the problems' common ``source:`` up to its last
    comma ("SG2150 exam 2015-10-29, problem 1" and ", problem 2" give "SG2150 exam
    2015-10-29"), else the folder's name."""
    common = os.path.commonprefix([s for s in sources if s]) if all(sources) and sources else ""
    head = common.rpartition(",")[0].strip() if "," in common else ""
    if len(sources) > 1 and len(head) >= 4:
        return f"Answer key: {head}"
    name = PurePath(folders[0]).name if len(folders) == 1 else ""
    return f"Answer key: {name}" if name else "Answer key"
