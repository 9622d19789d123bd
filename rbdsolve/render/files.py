"""Writing an output file so that a failed or interrupted run leaves the previous file
or nothing, never half of one: the text goes to a temporary name beside the file and
is renamed onto it once whole (a rename within a folder is atomic on POSIX).

A target that is not a regular file (``/dev/full``, a FIFO, ``/dev/stdout``) is written
in place: renaming onto it would replace the device with a file. Every failure is one
located line, ``cannot write PATH: reason`` (exit code 2).
"""

from __future__ import annotations

import os
import stat
import tempfile
from contextlib import contextmanager
from pathlib import Path
from typing import Iterator

from rbdsolve.errors import InputError


def require_folder(output: Path, what: str) -> None:
    """Before any work: the folder ``output`` is to be written in exists (exit code 2
    otherwise, naming ``what`` is written)."""
    if not output.parent.is_dir():
        raise InputError(f"-o {output}: there is no folder {output.parent}/ to write {what} in")


def write_file(path: str | Path, data: str | bytes) -> None:
    """``data`` (text as UTF-8) to ``path``, whole or not at all."""
    raw = data.encode("utf-8") if isinstance(data, str) else data
    with replacing(path) as temporary:
        with open(temporary, "wb") as handle:
            handle.write(raw)


@contextmanager
def replacing(path: str | Path) -> Iterator[Path]:
    """A temporary path for the body to write; renamed onto ``path`` when the body ends
    normally, removed when it fails or is interrupted (any exception, KeyboardInterrupt
    and SystemExit included)."""
    path = Path(path)
    if _special(path):
        with _said(path):
            yield path
        return
    with _said(path):
        handle, name = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".part", dir=path.parent or ".")
        os.close(handle)
    temporary = Path(name)
    try:
        with _said(path):
            yield temporary
            os.chmod(temporary, _mode(path))
            os.replace(temporary, path)
    finally:
        temporary.unlink(missing_ok=True)


def _special(path: Path) -> bool:
    try:
        return not stat.S_ISREG(os.stat(path).st_mode)
    except OSError:  # not there yet (or unreadable): a new regular file
        return False


def _mode(path: Path) -> int:
    """The replaced file's permissions, or a new file's (0666 less the umask): mkstemp
    makes its file private (0600)."""
    try:
        return stat.S_IMODE(os.stat(path).st_mode)
    except OSError:
        umask = os.umask(0)
        os.umask(umask)
        return 0o666 & ~umask


@contextmanager
def _said(path: Path) -> Iterator[None]:
    try:
        yield
    except OSError as exc:
        raise InputError(f"cannot write {path}: {exc.strerror or exc}") from None
