"""render/pdf.py: which TeX engine runs and how (a stand-in engine records its command)."""

from __future__ import annotations

import os
import stat
import sys

import pytest

from rbdsolve.errors import InputError
from rbdsolve.render.pdf import ENGINES, compile_pdf, engine

FAKE = """#!{python}
import sys, pathlib
pathlib.Path("calls.txt").open("a").write(" ".join(sys.argv[1:]) + "\\n")
pathlib.Path(sys.argv[-1]).with_suffix(".pdf").write_bytes(b"%PDF-1.5 fake")
"""


def fake_engine(folder, name: str):
    path = folder / name
    path.write_text(FAKE.format(python=sys.executable))
    path.chmod(path.stat().st_mode | stat.S_IEXEC)
    return path


@pytest.fixture
def only(tmp_path, monkeypatch):
    """PATH holding nothing but the stand-in engines this test makes."""
    bin_folder = tmp_path / "bin"
    bin_folder.mkdir()
    monkeypatch.setenv("PATH", str(bin_folder))
    monkeypatch.delenv("RBDSOLVE_LATEX", raising=False)
    return bin_folder


def test_tectonic_is_one_of_the_engines_and_runs_once_untrusted(only, tmp_path) -> None:
    assert "tectonic" in ENGINES
    fake_engine(only, "tectonic")
    work = tmp_path / "work"
    work.mkdir()
    pdf = compile_pdf("\\documentclass{article}", work)
    assert pdf.read_bytes().startswith(b"%PDF")
    assert (work / "calls.txt").read_text().splitlines() == ["--untrusted --keep-logs key.tex"]


def test_pdflatex_comes_first_and_runs_twice_without_shell_escape(only, tmp_path) -> None:
    fake_engine(only, "tectonic")
    fake_engine(only, "pdflatex")
    assert os.path.basename(engine()) == "pdflatex"
    work = tmp_path / "work"
    work.mkdir()
    compile_pdf("\\documentclass{article}", work)
    assert (work / "calls.txt").read_text().splitlines() == [
        "-interaction=nonstopmode -halt-on-error -no-shell-escape key.tex"] * 2


def test_rbdsolve_latex_chooses_the_engine(only, tmp_path, monkeypatch) -> None:
    fake_engine(only, "pdflatex")
    chosen = fake_engine(tmp_path, "my-tectonic")
    monkeypatch.setenv("RBDSOLVE_LATEX", str(chosen))
    assert engine() == str(chosen)


def test_no_engine_is_said_with_the_way_out(only, tmp_path, monkeypatch) -> None:
    with pytest.raises(InputError, match="pdflatex, lualatex, xelatex or tectonic.*TeX Live"):
        compile_pdf("", tmp_path)
    monkeypatch.setenv("RBDSOLVE_LATEX", "no-such-engine")
    with pytest.raises(InputError, match="RBDSOLVE_LATEX=no-such-engine names none on PATH"):
        compile_pdf("", tmp_path)
