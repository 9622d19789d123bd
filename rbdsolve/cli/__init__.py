"""The rbdsolve command line: each command is load -> build -> solve -> render.

One module per command, each registering itself on the ``main`` group. Heavy modules
(sympy, rich, matplotlib) are imported inside the commands that need them, so
``rbdsolve --help`` and ``rbdsolve check`` start fast.
"""

from __future__ import annotations

from rbdsolve.cli.app import main, run
from rbdsolve.cli import check, draw, grade, key, new, solve, variants, watch  # noqa: E402,F401 - each registers its command on main

__all__ = ["main", "run"]
