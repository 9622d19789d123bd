"""An exam's answer key: each problem's statement, its pictures and its worked
solution, as one document (PDF, LaTeX, Markdown or HTML).

    write_key(output, title, problems, figures, values) -> notes

The problems come solved (the CLI solves them, in processes with ``--jobs``); this
draws each planar scene and its mode shapes at the values the solution used, lays the
key out (report.key.AnswerKey, rendered by render/) and writes it. A .tex or .md key
keeps its pictures in a folder beside it (``key-figures/``); a .pdf or .html key is one
file. A picture that cannot be drawn is left out with a note: the key keeps the
solution.
"""

from __future__ import annotations

import os
import re
import secrets
import shutil
import tempfile
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import Callable, Mapping, Sequence

from rbdsolve.errors import InputError
from rbdsolve.problem.schema import Problem
from rbdsolve.problem.quantities.quantity import Value
from rbdsolve.report.key import AnswerKey, KeyEntry, Picture, default_title
from rbdsolve.report.steps import ProblemReport
from rbdsolve.render.files import publish, require_folder, staging, write_file

KINDS = (".pdf", ".tex", ".md", ".html")


@dataclass(frozen=True)
class Solved:
    """One problem of the exam as solved: its report, or why it has none (a bad file),
    and how to load it again for its pictures."""

    name: str
    load: Callable[[], Problem]
    report: ProblemReport | None
    failure: str | None = None
    spent: float = 0.0  # processor seconds its solve spent: its pictures get what is left of the budget


def check_output(output: Path, figures: bool = True) -> None:
    """Before any solving: a key's format, a folder to write it in, and, for a key whose
    pictures go beside it, a pictures folder that is a folder (not a link to elsewhere)."""
    if output.suffix not in KINDS:
        raise InputError(f"-o {output}: the key is written as {', '.join(KINDS)}; found '{output.suffix or output.name}'")
    require_folder(output, "the key")
    if figures and output.suffix not in SINGLE_FILE:
        _check_figures_folder(figures_folder(output))


SINGLE_FILE = (".pdf", ".html")  # the pictures inside the key, not in a folder beside it


def figures_folder(output: Path) -> Path:
    """Where a .tex or .md key's pictures go: ``key-figures/`` beside ``key.md``."""
    return output.parent / f"{safe_name(output.stem)}-figures"


def _check_figures_folder(folder: Path) -> None:
    """A pictures folder that is there already must be a folder of its own: a symbolic
    link (``key-figures -> ../outside``, planted or forgotten) would send the pictures
    wherever it points, and is refused, as is a file of that name."""
    if folder.is_symlink():
        raise InputError(f"{folder}: the key's pictures folder is a symbolic link (to {os.readlink(folder)}); "
                         "rbdsolve does not write through one: remove it, or choose another -o")
    if folder.exists() and not folder.is_dir():
        raise InputError(f"{folder}: the key's pictures go in a folder of this name, and this is a file: "
                         "remove it, or choose another -o")


def key_title(paths: Sequence[str], problems: Sequence[Solved]) -> str:
    """The problems' common source, else the folder's name (report.key.default_title)."""
    return default_title(list(paths), [p.report.source if p.report else "" for p in problems])


def write_key(output: Path, title: str, problems: Sequence[Solved], figures: bool,
              values: Mapping[str, Value], budget: float | None = None) -> tuple[str, ...]:
    """Write the key to ``output`` (its suffix picks the format); return notes about
    pictures left out. A .tex or .md key and its pictures appear together or not at all:
    the pictures are drawn in a staging folder beside the key (render/files.py) and
    published with it, so an interrupt leaves no pictures folder it made."""
    check_output(output, figures)
    notes: list[str] = []
    single_file = output.suffix in SINGLE_FILE
    with _scratch_folder() as scratch, staging(output) as stage:
        home = Path(scratch) if single_file else stage
        folder = home / figures_folder(output).name
        suffix = ".svg" if output.suffix == ".html" else ".png"
        entries = []
        for n, problem in enumerate(problems, start=1):
            stem = f"{n:02d}-{safe_name(Path(problem.name).stem)}"
            pictures = (_pictures(problem, folder, home, stem, suffix, values, notes, budget)
                        if figures and problem.report is not None else ())
            entries.append(KeyEntry(problem.name, problem.report, problem.failure, pictures))
        document = _document(AnswerKey(title, tuple(entries)), output, home, Path(scratch))
        if single_file or not folder.is_dir():
            write_file(output, document)
        else:
            _publish_with_pictures(document, output, folder, stage)
    return tuple(notes)


def _publish_with_pictures(document: bytes, output: Path, drawn: Path, stage: Path) -> None:
    """The key and its pictures folder, together: a new folder is the staged one renamed
    into place (and removed again should the key then fail or be interrupted); in a
    folder there already, the pictures are published file by file with the key."""
    target = figures_folder(output)
    _check_figures_folder(target)
    staged = stage / output.name
    staged.write_bytes(document)
    if target.exists():
        publish([*((p, target / p.name) for p in sorted(drawn.iterdir())), (staged, output)])
        return
    created = target  # named before the rename: a signal just after it still finds the folder to remove
    try:
        os.chmod(drawn, 0o777 & ~_umask())
        shutil.move(drawn, target)  # a rename, but for a key sent to a FIFO (its staging in the temporary folder)
        publish([(staged, output)])
    except BaseException:
        shutil.rmtree(created, ignore_errors=True)
        raise


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


@contextmanager
def _scratch_folder():
    """A private temporary folder, removed however the block ends. Its name is chosen
    before it is made, so a signal arriving just after it is made still finds it in
    the cleanup (tempfile's TemporaryDirectory leaves a gap between the two)."""
    scratch = Path(tempfile.gettempdir()) / f"rbdsolve-key-{secrets.token_hex(6)}"
    try:
        scratch.mkdir(mode=0o700)
        yield str(scratch)
    finally:
        shutil.rmtree(scratch, ignore_errors=True)


def safe_name(name: str) -> str:
    """A file name TeX, Markdown and HTML all read as it is: letters, digits, . _ -."""
    return re.sub(r"[^A-Za-z0-9._-]+", "-", name).strip("-") or "key"


def _document(answer_key: AnswerKey, output: Path, home: Path, scratch: Path) -> bytes:
    """The key as the bytes of its file (output's suffix picks the format)."""
    if output.suffix == ".md":
        from rbdsolve.render.markdown import render_key

        return render_key(answer_key).encode("utf-8")
    if output.suffix == ".html":
        from rbdsolve.render.html import render_key

        return render_key(answer_key, home).encode("utf-8")
    from rbdsolve.render.latex import render_key

    tex = render_key(answer_key)
    if output.suffix == ".tex":
        return tex.encode("utf-8")
    from rbdsolve.render.pdf import compile_pdf

    return compile_pdf(tex, scratch).read_bytes()


def _pictures(problem: Solved, folder: Path, home: Path, stem: str, suffix: str,
              values: Mapping[str, Value], notes: list[str], budget: float | None) -> tuple[Picture, ...]:
    """The scene and its mode shapes, drawn at the values the solution used, within what
    is left of the file's budget after its solve (one budget for the file); none for a
    scene that is not planar. A picture that fails is noted and left out."""
    from rbdsolve.model.build import build_model
    from rbdsolve.render.drawing.figures import save_figures
    from rbdsolve.solvers.routes.budget import MIN_SHARE, OutOfTime, within

    try:
        with within(None if budget is None else max(budget - problem.spent, MIN_SHARE), "the pictures", budget):
            model = build_model(problem.load())
            if values:
                model = model.with_values(dict(values))
            folder.mkdir(parents=True, exist_ok=True)
            drawn = save_figures(model, folder, stem, suffix)
    except (Exception, OutOfTime) as exc:  # noqa: BLE001 - a picture must not lose the key
        notes.append(f"{problem.name}: no picture in the key: {type(exc).__name__}: {exc}")
        return ()
    return tuple(Picture(f.path.relative_to(home), f.caption) for f in drawn)
