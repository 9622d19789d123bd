"""Renderers: one per output format, each a function of reports only.

Only this package (and the CLI) knows about rich.
"""

from enum import Enum


class Format(Enum):
    TERMINAL = "terminal"
    MARKDOWN = "markdown"
    LATEX = "latex"
    JSON = "json"
