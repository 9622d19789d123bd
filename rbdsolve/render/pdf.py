"""LaTeX to PDF with the machine's own TeX engine (pdflatex first): nothing is fetched
by rbdsolve.

The document's text is escaped by render.latex, and the engine runs with shell escape
off (``-no-shell-escape``; tectonic's ``--untrusted``), so a problem file cannot make
TeX run a command.
"""

from __future__ import annotations

import os
import shutil
import subprocess
from pathlib import Path

from rbdsolve.errors import InputError, InternalError

ENGINES = ("pdflatex", "lualatex", "xelatex", "tectonic")
ENVIRONMENT = "RBDSOLVE_LATEX"  # a program name or path: the engine to use instead
SECONDS = 300  # a whole exam's key compiles in seconds; minutes means TeX is stuck


def engine() -> str | None:
    """The TeX engine to use: $RBDSOLVE_LATEX, else the first of ENGINES on PATH."""
    chosen = os.environ.get(ENVIRONMENT)
    if chosen:
        return shutil.which(chosen)
    return next((found for name in ENGINES if (found := shutil.which(name))), None)


def require_engine() -> str:
    """The TeX engine, or one line saying what to install and which output needs none.
    The CLI asks this before solving anything: a missing engine found after a whole
    exam is solved wastes the solve (docs/failure-edges.md)."""
    program = engine()
    if program is None:
        raise InputError(_no_engine())
    return program


def command(program: str, name: str) -> tuple[list[str], int]:
    """The engine's command line for ``name.tex`` and how many times to run it: a
    LaTeX engine twice (the second run settles page breaks around the pictures);
    tectonic once (it reruns itself until the document settles), its log kept."""
    if Path(program).name.lower().startswith("tectonic"):
        return [program, "--untrusted", "--keep-logs", f"{name}.tex"], 1
    return [program, "-interaction=nonstopmode", "-halt-on-error", "-no-shell-escape", f"{name}.tex"], 2


def compile_pdf(tex: str, folder: Path, name: str = "key") -> Path:
    """Write ``name.tex`` in ``folder`` (where its pictures are), compile it and return
    the PDF."""
    program = require_engine()
    (folder / f"{name}.tex").write_text(tex, encoding="utf-8")
    line, runs = command(program, name)
    for _ in range(runs):
        try:
            done = subprocess.run(line, cwd=folder, capture_output=True, timeout=SECONDS,
                                  stdin=subprocess.DEVNULL)
        except subprocess.TimeoutExpired:
            raise InternalError(f"{Path(program).name} did not finish in {SECONDS} s") from None
        if done.returncode != 0:
            raise InternalError(f"{Path(program).name} could not compile the key: {_first_error(folder / f'{name}.log')}")
    return folder / f"{name}.pdf"


def _no_engine() -> str:
    chosen = os.environ.get(ENVIRONMENT)
    if chosen:
        return (f"a PDF needs a LaTeX engine, and {ENVIRONMENT}={chosen} names none on PATH; "
                f"unset it to use the first of {', '.join(ENGINES)} found, or write the key as .html, .tex or .md, "
                "which need none (-o key.html)")
    return (f"a PDF needs a LaTeX engine ({', '.join(ENGINES[:-1])} or {ENGINES[-1]}) and none is "
            "installed; install TeX Live (Debian/Ubuntu: apt install texlive-latex-recommended), "
            "or write the key as .html, .tex or .md, which need none (-o key.html)")


def _first_error(log: Path) -> str:
    """The log's first '!' line and the line after it (where TeX says what it read)."""
    try:
        lines = log.read_text(encoding="latin-1").splitlines()
    except OSError:
        return "no log written"
    for i, line in enumerate(lines):
        if line.startswith("!"):
            return " ".join(x.strip() for x in lines[i:i + 2])
    return "see the log"
