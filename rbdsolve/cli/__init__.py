"""The rbdsolve command line: each command is load -> build -> solve -> render.

One module per command, imported when its command runs (``app.Commands``); heavy
modules (sympy, rich, matplotlib) are imported inside the commands that need them, so
``rbdsolve --help`` and ``rbdsolve check`` start fast.
"""

from __future__ import annotations

from rbdsolve.cli.app import main, run

__all__ = ["main", "run"]
