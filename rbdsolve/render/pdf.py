"""LaTeX to PDF with the machine's own TeX engine (pdflatex first): nothing is fetched.

The document's text is escaped by render.latex, and the engine runs with shell escape
off, so a problem file cannot make TeX run a command.
"""

from __future__ import annotations

import os
import shutil
import subprocess
from pathlib import Path

from rbdsolve.errors import InputError, InternalError

ENGINES = ("pdflatex", "lualatex", "xelatex")
SECONDS = 300  # a whole exam's key compiles in seconds; minutes means TeX is stuck


def engine() -> str | None:
    """The TeX engine to use: $RBDSOLVE_LATEX, else the first of ENGINES on PATH."""
    chosen = os.environ.get("RBDSOLVE_LATEX")
    if chosen:
        return shutil.which(chosen)
    return next((found for name in ENGINES if (found := shutil.which(name))), None)


def compile_pdf(tex: str, folder: Path, name: str = "key") -> Path:
    """Write ``name.tex`` in ``folder`` (where its pictures are), compile it twice
    (the second run settles page breaks around the pictures) and return the PDF."""
    program = engine()
    if program is None:
        raise InputError("a PDF needs a LaTeX engine (pdflatex, lualatex or xelatex) and none is "
                         "installed; install TeX Live (Debian/Ubuntu: apt install texlive-latex-recommended) "
                         "or write the key as .tex, .md or .html")
    (folder / f"{name}.tex").write_text(tex, encoding="utf-8")
    command = [program, "-interaction=nonstopmode", "-halt-on-error", "-no-shell-escape", f"{name}.tex"]
    for _ in range(2):
        try:
            done = subprocess.run(command, cwd=folder, capture_output=True, timeout=SECONDS,
                                  stdin=subprocess.DEVNULL)
        except subprocess.TimeoutExpired:
            raise InternalError(f"{Path(program).name} did not finish in {SECONDS} s") from None
        if done.returncode != 0:
            raise InternalError(f"{Path(program).name} could not compile the key: {_first_error(folder / f'{name}.log')}")
    return folder / f"{name}.pdf"


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
