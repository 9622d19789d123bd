"""Output paths from outside (issue 39, items 4 and 6): echoed escaped, never a
terminal's control; a FIFO with no reader refused after a deadline, not waited for; an
empty -o refused; a key's pictures folder that is a symbolic link not followed; outputs
that belong together (draw's two pictures, a key and its pictures folder) appearing
whole or not at all."""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from click.testing import CliRunner

from rbdsolve.cli import main
from rbdsolve.render import files
from rbdsolve.render.drawing import figures

from conftest import PROBLEMS, SEED

PENDULUM = PROBLEMS / "examples" / "pendulum.yaml"
P1 = SEED / "p1-two-rods.yaml"
HOSTILE = "x\x1b]0;PWN\x07\x1b[2J"  # sets the terminal's title, clears it


def run(*args):
    return CliRunner().invoke(main, [str(a) for a in args])


@pytest.mark.parametrize(("command", "suffix", "extra"), [
    ("variants", ".csv", ("--count", "2", "--verify", "0")),
    ("key", ".md", ("--no-figures",)),
    ("draw", ".png", ("--no-modes",)),
    ("new", ".yaml", ()),
])
def test_an_output_path_is_echoed_escaped(tmp_path, command: str, suffix: str, extra) -> None:
    output = tmp_path / f"{HOSTILE}{suffix}"
    source = "modes" if command == "new" else (P1 if command == "variants" else PENDULUM)
    result = run(command, source, "-o", output, *extra)
    assert result.exit_code == 0, result.output
    assert "\x1b" not in result.output and "\x07" not in result.output
    assert "x\\x1b]0;PWN\\x07\\x1b[2J" + suffix in result.output
    assert output.exists()  # the file itself has the name asked for


@pytest.mark.parametrize("command", ["solve", "key", "variants", "draw", "grade", "new"])
def test_an_empty_output_path_is_refused(tmp_path, command: str) -> None:
    source = {"new": "modes", "variants": P1}.get(command, PENDULUM)
    extra = ("-a", "omega1 = 1") if command == "grade" else ()
    result = run(command, source, "-o", "", *extra)
    assert result.exit_code == 2
    assert "Invalid value for '-o' / '--output': an empty path names no file" in result.output


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="no FIFOs here")
@pytest.mark.parametrize(("command", "name", "extra"), [
    ("solve", "out.fifo", ()),
    ("variants", "out.csv", ("--count", "2", "--verify", "0")),
    ("key", "out.md", ("--no-figures",)),
    ("draw", "out.png", ("--no-modes",)),
])
def test_a_fifo_output_with_no_reader_is_refused(tmp_path, monkeypatch, command: str, name: str, extra) -> None:
    monkeypatch.setattr(files, "WRITE_SECONDS", 0.3)
    fifo = tmp_path / name
    os.mkfifo(fifo)
    result = run(command, P1 if command == "variants" else PENDULUM, "-o", fifo, *extra)
    assert result.exit_code == 2, result.output
    assert f"cannot write {fifo}: no process opened it for reading within 0.3 s" in result.output
    assert sorted(p.name for p in tmp_path.iterdir()) == [name]


def test_a_key_does_not_follow_a_planted_link_for_its_pictures(tmp_path) -> None:
    outside = tmp_path / "outside"
    outside.mkdir()
    work = tmp_path / "work"
    work.mkdir()
    (work / "k-figures").symlink_to("../outside")
    result = run("key", PENDULUM, "-o", work / "k.md")
    assert result.exit_code == 2
    assert result.output == (f"{work / 'k-figures'}: the key's pictures folder is a symbolic link (to ../outside); "
                             "rbdsolve does not write through one: remove it, or choose another -o\n")
    assert list(outside.iterdir()) == [] and sorted(p.name for p in work.iterdir()) == ["k-figures"]
    assert run("key", PENDULUM, "-o", work / "k.md", "--no-figures").exit_code == 0  # no pictures, no folder


def test_a_key_and_its_pictures_appear_together(tmp_path) -> None:
    result = run("key", PENDULUM, "-o", tmp_path / "k.md")
    assert result.exit_code == 0, result.output
    assert sorted(p.name for p in tmp_path.iterdir()) == ["k-figures", "k.md"]
    pictures = sorted(p.name for p in (tmp_path / "k-figures").iterdir())
    assert pictures == ["01-pendulum-modes.png", "01-pendulum.png"]
    assert oct((tmp_path / "k-figures").stat().st_mode & 0o777) == oct(0o777 & ~_umask())


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def test_a_key_interrupted_while_drawing_leaves_no_pictures_folder(tmp_path, monkeypatch) -> None:
    """The second picture interrupted: the first was drawn, yet no k-figures/ (empty or
    half full) is left, nor a staging folder, and no key."""

    def interrupted(*args, **kwargs):
        raise KeyboardInterrupt

    monkeypatch.setattr(figures, "save_modes", interrupted)
    result = run("key", PENDULUM, "-o", tmp_path / "k.md")
    assert result.exit_code == 130, result.output
    assert list(tmp_path.iterdir()) == []


def test_a_key_interrupted_after_its_pictures_folder_appeared_removes_it(tmp_path, monkeypatch) -> None:
    """The pictures folder renamed into place, then the key's own publishing interrupted:
    the folder it made is removed again."""
    from rbdsolve.teaching import key

    def interrupted(pairs):
        raise KeyboardInterrupt

    monkeypatch.setattr(key, "publish", interrupted)
    result = run("key", PENDULUM, "-o", tmp_path / "k.md")
    assert result.exit_code == 130, result.output
    assert list(tmp_path.iterdir()) == []


def test_draw_interrupted_between_its_two_pictures_leaves_the_previous_pair(tmp_path, monkeypatch) -> None:
    scene, modes = tmp_path / "p.png", tmp_path / "p-modes.png"
    scene.write_bytes(b"previous scene")
    modes.write_bytes(b"previous modes")

    def interrupted(*args, **kwargs):
        raise KeyboardInterrupt

    monkeypatch.setattr(figures, "save_modes", interrupted)
    result = run("draw", PENDULUM, "-o", scene)
    assert result.exit_code == 130, result.output
    assert (scene.read_bytes(), modes.read_bytes()) == (b"previous scene", b"previous modes")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["p-modes.png", "p.png"]
