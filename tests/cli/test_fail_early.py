"""Fail early (issue 24): ``key -o key.pdf`` without a TeX engine is refused before any
solving, in one line that says what to install and which output needs no engine."""

from __future__ import annotations

import subprocess
import sys

import pytest
from click.testing import CliRunner

import rbdsolve.cli.key as key_command
from rbdsolve.cli import main

from conftest import ROOT, SEED


def _no_solving(*args, **kwargs):
    raise AssertionError("the key was solved before the engine was checked")


@pytest.fixture
def no_engine_on_path(tmp_path, monkeypatch):
    """An empty PATH and no RBDSOLVE_LATEX: shutil.which finds no engine."""
    monkeypatch.delenv("RBDSOLVE_LATEX", raising=False)
    monkeypatch.setenv("PATH", str(tmp_path / "empty"))
    monkeypatch.setattr(key_command, "solve_all", _no_solving)


def test_no_engine_on_path_is_one_line_before_solving(tmp_path, no_engine_on_path) -> None:
    result = CliRunner().invoke(main, ["key", str(SEED), "-o", str(tmp_path / "key.pdf")])
    assert result.exit_code == 2, result.output
    lines = result.output.strip().splitlines()
    assert len(lines) == 1, result.output
    assert "needs a LaTeX engine" in lines[0] and "apt install texlive" in lines[0] and "-o key.html" in lines[0]
    assert not (tmp_path / "key.pdf").exists()


def test_an_engine_named_but_absent_is_named(tmp_path, monkeypatch) -> None:
    monkeypatch.setenv("RBDSOLVE_LATEX", "no-such-tex-engine")
    monkeypatch.setattr(key_command, "solve_all", _no_solving)
    result = CliRunner().invoke(main, ["key", str(SEED), "-o", str(tmp_path / "key.pdf")])
    assert result.exit_code == 2, result.output
    assert "RBDSOLVE_LATEX=no-such-tex-engine names none" in result.output and "-o key.html" in result.output


def test_other_formats_need_no_engine(tmp_path, no_engine_on_path, monkeypatch) -> None:
    """The check is for .pdf only: a .md key goes on to solve (here, to the stub)."""
    result = CliRunner().invoke(main, ["key", str(SEED), "-o", str(tmp_path / "key.md")])
    assert "solved before the engine was checked" in result.output  # the stub, reported as a bug


def test_the_refusal_loads_no_sympy(tmp_path) -> None:
    """Fast because nothing heavy is imported (no timing asserted: the imports tell)."""
    code = ("import sys\nfrom rbdsolve.cli import main\n"
            f"try: main(['key', {str(SEED)!r}, '-o', {str(tmp_path / 'key.pdf')!r}])\n"
            "except SystemExit as exc: print(exc.code, 'sympy' in sys.modules)")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, timeout=60,
                          env={"PYTHONPATH": str(ROOT), "PATH": str(tmp_path), "RBDSOLVE_LATEX": ""})
    assert done.stdout.split() == ["2", "False"], done.stdout + done.stderr
    assert "needs a LaTeX engine" in done.stderr
