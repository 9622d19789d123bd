"""Writing outputs (render/files.py): a FIFO is written under a deadline, never waited
for without end; outputs that belong together are published all or none, the
previous ones restored when the publishing is interrupted (issue 39, items 4 and 6)."""

from __future__ import annotations

import os
import threading
from pathlib import Path

import pytest

from rbdsolve.errors import InputError
from rbdsolve.render import files
from rbdsolve.render.files import publish, staging, write_file

fifos = pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="no FIFOs here")


@fifos
def test_a_fifo_no_one_reads_is_refused_after_the_deadline(tmp_path, monkeypatch) -> None:
    monkeypatch.setattr(files, "WRITE_SECONDS", 0.3)
    fifo = tmp_path / "out.fifo"
    os.mkfifo(fifo)
    with pytest.raises(InputError, match=r"^cannot write .*out.fifo: no process opened it for reading within 0.3 s$"):
        write_file(fifo, "text")
    assert [p.name for p in tmp_path.iterdir()] == ["out.fifo"]  # still the FIFO, nothing beside it


@fifos
def test_a_fifo_with_a_reader_gets_the_whole_output(tmp_path) -> None:
    fifo = tmp_path / "out.fifo"
    os.mkfifo(fifo)
    got: list[bytes] = []
    reader = threading.Thread(target=lambda: got.append(fifo.read_bytes()))
    reader.start()
    data = os.urandom(300_000)  # more than a pipe holds: written as the reader takes it
    write_file(fifo, data)
    reader.join(timeout=60)
    assert got == [data]


@fifos
def test_a_fifo_whose_reader_takes_nothing_is_refused(tmp_path, monkeypatch) -> None:
    monkeypatch.setattr(files, "WRITE_SECONDS", 0.3)
    fifo = tmp_path / "out.fifo"
    os.mkfifo(fifo)
    reader = os.open(fifo, os.O_RDONLY | os.O_NONBLOCK)  # opened, never read
    try:
        with pytest.raises(InputError, match="its reader took nothing for 0.3 s"):
            write_file(fifo, b"x" * 1_000_000)
    finally:
        os.close(reader)


def test_a_socket_is_refused(tmp_path) -> None:
    import socket

    path = tmp_path / "s"
    with socket.socket(socket.AF_UNIX) as server:
        server.bind(str(path))
        with pytest.raises(InputError, match="it is a socket, not a file"):
            write_file(path, "text")


def test_outputs_published_together_appear_together(tmp_path) -> None:
    a, b = tmp_path / "a.png", tmp_path / "a-modes.png"
    a.write_text("old a")
    with staging(a) as stage:
        (stage / "a.png").write_text("new a")
        (stage / "a-modes.png").write_text("new b")
        publish([(stage / "a.png", a), (stage / "a-modes.png", b)])
    assert (a.read_text(), b.read_text()) == ("new a", "new b")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a-modes.png", "a.png"]  # no staging, no kept copy


@pytest.mark.parametrize("interrupt", [KeyboardInterrupt, SystemExit, OSError])
def test_an_interrupted_publish_puts_everything_back(tmp_path, monkeypatch, interrupt) -> None:
    """The second rename interrupted: the first target is put back as it was (the old
    file from its hard link), the new second one never appears, nothing is left over."""
    a, b = tmp_path / "a.png", tmp_path / "a-modes.png"
    a.write_text("old a")
    os.chmod(a, 0o640)
    real = os.replace
    calls = []

    def replace(src, dst):
        calls.append(dst)
        if len(calls) == 2 and Path(dst) == b:
            raise interrupt()
        return real(src, dst)

    with staging(a) as stage:
        (stage / "a.png").write_text("new a")
        (stage / "a-modes.png").write_text("new b")
        monkeypatch.setattr(files.os, "replace", replace)
        with pytest.raises((interrupt, InputError)):
            publish([(stage / "a.png", a), (stage / "a-modes.png", b)])
        monkeypatch.setattr(files.os, "replace", real)
    assert a.read_text() == "old a" and oct(a.stat().st_mode & 0o777) == oct(0o640)
    assert not b.exists()
    assert [p.name for p in tmp_path.iterdir()] == ["a.png"]


def test_a_staging_folder_is_removed_however_the_block_ends(tmp_path) -> None:
    with pytest.raises(KeyboardInterrupt):
        with staging(tmp_path / "k.md") as stage:
            (stage / "x.png").write_text("half")
            raise KeyboardInterrupt
    assert list(tmp_path.iterdir()) == []
