"""Writing an output file so that a failed or interrupted run leaves the previous file
or nothing, never half of one: the text goes to a temporary name beside the file and
is renamed onto it once whole (a rename within a folder is atomic on POSIX). Outputs
that belong together (draw's scene and its mode shapes, a key and its pictures) are
made in a staging folder beside them and published together (``staging``,
``publish``): all of them appear, or none, and the previous ones stay.

A target that is not a regular file is never replaced by one. A device (``/dev/full``,
``/dev/null``, a terminal) is written in place. A FIFO (``/dev/stdout`` on a pipe too)
gets the whole output once it is made, under a deadline: no reader within
WRITE_SECONDS, or a reader that takes nothing for that long, is refused rather than
waited for (exit code 2). A socket is refused. Every failure is one line, ``cannot
write PATH: reason`` (exit code 2).
"""

from __future__ import annotations

import errno
import os
import secrets
import select
import shutil
import stat
import tempfile
import time
from contextlib import contextmanager
from pathlib import Path
from typing import Iterator, Sequence

from rbdsolve.errors import InputError

WRITE_SECONDS = 30.0  # a FIFO that no one reads by then is refused, as a problem file no one writes


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
    kind = _kind(path)
    if kind == "socket":
        raise InputError(f"cannot write {path}: it is a socket, not a file")
    if kind == "fifo":
        with _through_fifo(path) as temporary:
            yield temporary
        return
    if kind == "device":
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


def _kind(path: Path) -> str:
    """'file' (a regular file, or none yet), 'fifo', 'socket' or 'device' (anything
    else that is not a folder), as the path's target is (a link followed)."""
    try:
        mode = os.stat(path).st_mode
    except (OSError, ValueError):  # not there yet (or unreadable): a new regular file
        return "file"
    if stat.S_ISREG(mode) or stat.S_ISDIR(mode):  # a folder: the rename fails and says so
        return "file"
    return "fifo" if stat.S_ISFIFO(mode) else "socket" if stat.S_ISSOCK(mode) else "device"


@contextmanager
def _through_fifo(path: Path) -> Iterator[Path]:
    """A private temporary file for the body; its bytes then sent to the FIFO ``path``."""
    with _said(path):
        handle, name = tempfile.mkstemp(prefix="rbdsolve-", suffix=".part")
        os.close(handle)
    try:
        yield Path(name)
        send(Path(name).read_bytes(), path)
    finally:
        Path(name).unlink(missing_ok=True)


def send(data: bytes, path: Path, seconds: float | None = None) -> None:
    """``data`` written to the FIFO ``path``: opened without waiting for a reader (none
    within ``seconds``, WRITE_SECONDS, is refused) and written as the reader takes it (a
    reader that takes nothing for ``seconds`` is refused)."""
    seconds = WRITE_SECONDS if seconds is None else seconds
    fd = _open_for_a_reader(path, seconds)
    try:
        view = memoryview(data)
        while view:
            if not select.select([], [fd], [], seconds)[1]:
                raise InputError(f"cannot write {path}: its reader took nothing for {seconds:g} s")
            with _said(path):
                view = view[os.write(fd, view[: 64 * 1024]):]
    finally:
        os.close(fd)


def _open_for_a_reader(path: Path, seconds: float) -> int:
    deadline = time.monotonic() + seconds
    while True:
        try:
            return os.open(path, os.O_WRONLY | os.O_NONBLOCK)
        except OSError as exc:
            if exc.errno != errno.ENXIO:  # ENXIO: no reader yet
                raise InputError(f"cannot write {path}: {exc.strerror or exc}") from None
        if time.monotonic() >= deadline:
            raise InputError(f"cannot write {path}: no process opened it for reading within {seconds:g} s")
        time.sleep(0.02)


@contextmanager
def staging(beside: Path) -> Iterator[Path]:
    """A private folder beside ``beside`` (``.NAME.XXXX.part``, on the same file system
    so that what is made in it can be renamed into place), removed however the block
    ends; in the temporary folder when ``beside`` is a device or a FIFO (``-o
    /dev/stdout``: its bytes are sent, not renamed). Its name is chosen before it is
    made, so that a signal arriving just after it is made still finds it in the cleanup."""
    beside = Path(beside)
    home = beside.parent if _kind(beside) == "file" else Path(tempfile.gettempdir())
    folder = home / f".{beside.name}.{secrets.token_hex(6)}.part"
    try:
        with _said(beside):
            folder.mkdir(mode=0o700)
        yield folder
    finally:
        shutil.rmtree(folder, ignore_errors=True)


def publish(pairs: Sequence[tuple[Path, Path]]) -> None:
    """Each staged file renamed onto its target, all or none: should a rename fail or be
    interrupted (any exception, KeyboardInterrupt and SystemExit too), the targets
    renamed already are put back as they were — a previous file from a hard link kept
    aside, a new one removed. A target that is not a regular file gets the bytes
    instead (``replacing``'s rules)."""
    begun: list[tuple[Path, Path, Path | None]] = []  # (staged, target, its previous file kept aside)
    kept: list[Path] = []
    try:
        for staged, target in pairs:
            if _kind(target) != "file":
                write_file(target, Path(staged).read_bytes())
                continue
            begun.append((Path(staged), target, _aside(target, kept)))
            _moved(Path(staged), target)
    except BaseException:
        for staged, target, previous in reversed(begun):
            if staged.exists():  # not renamed: the target is as it was
                continue
            if previous is not None:
                os.replace(previous, target)
            else:
                target.unlink(missing_ok=True)
        raise
    finally:
        for previous in kept:
            previous.unlink(missing_ok=True)


def _moved(staged: Path, target: Path) -> None:
    """``staged`` renamed onto ``target``; from another file system (a staging folder in
    the temporary folder), written beside it and renamed, and ``staged`` removed."""
    with _said(target):
        os.chmod(staged, _mode(target))
        try:
            os.replace(staged, target)
        except OSError as exc:
            if exc.errno != errno.EXDEV:
                raise
            write_file(target, staged.read_bytes())
            staged.unlink()


def _aside(target: Path, kept: list[Path]) -> Path | None:
    """A second name for the file at ``target`` (a hard link, else a copy), from which
    ``publish`` can put it back, listed in ``kept`` before it is made (so that it is
    removed whatever happens next); None where there is no file yet."""
    if not target.is_file():
        return None
    previous = target.parent / f".{target.name}.{secrets.token_hex(6)}.previous.part"
    kept.append(previous)
    with _said(target):
        try:
            os.link(target, previous)
        except OSError:  # a file system without hard links
            shutil.copy2(target, previous)
    return previous


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
