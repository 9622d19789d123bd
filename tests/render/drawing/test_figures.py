"""Pictures: save_figures (the answer key's contract) and ``rbdsolve draw``."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

from click.testing import CliRunner

from rbdsolve.cli import main
from rbdsolve.model.build import build_model
from rbdsolve.problem import load_file
from rbdsolve.render.drawing.figures import Figure, save_figures

from conftest import PROBLEMS, ROOT

P1 = str(PROBLEMS / "sg2150-2015-10-29" / "p1-two-rods.yaml")
P3 = str(PROBLEMS / "sg2150-2015-10-29" / "p3-rolling-ring.yaml")
PNG = b"\x89PNG\r\n\x1a\n"


def run(*args: str):
    return CliRunner().invoke(main, list(args))


def test_save_figures_scene_and_modes(tmp_path: Path) -> None:
    figures = save_figures(build_model(load_file(P1)), tmp_path, "p1")
    assert [f.path.name for f in figures] == ["p1.png", "p1-modes.png"]
    assert all(isinstance(f, Figure) and f.path.read_bytes().startswith(PNG) for f in figures)
    assert figures[0].caption == ("Two rods in a circle: the scene to scale at θ = 0, φ = 0 "
                                  "(m = r = g = 1: no values given).")
    assert "mode shapes about θ = 0, φ = 0" in figures[1].caption


def test_save_figures_skips_a_3d_scene(tmp_path: Path) -> None:
    assert save_figures(build_model(load_file(P3)), tmp_path, "p3", ".svg") == ()
    assert list(tmp_path.iterdir()) == []


def test_cli_png_and_svg(tmp_path: Path) -> None:
    png, svg = tmp_path / "scene.png", tmp_path / "scene.svg"
    result = run("draw", P1, "-o", str(png), "--at", "theta=0.3", "--at", "phi=-pi/6")
    assert result.exit_code == 0, result.output
    assert result.output.splitlines() == [str(png), str(tmp_path / "scene-modes.png")]
    assert png.read_bytes().startswith(PNG)
    result = run("draw", P1, "-o", str(svg), "--no-modes", "--set", "r=2")
    assert result.exit_code == 0, result.output
    assert result.output.splitlines() == [str(svg)] and b"<svg" in svg.read_bytes()[:500]


def test_cli_3d_scene_is_one_located_line(tmp_path: Path) -> None:
    result = run("draw", P3, "-o", str(tmp_path / "p3.png"))
    assert result.exit_code == 2
    lines = result.output.strip().splitlines()
    assert len(lines) == 1 and "p3-rolling-ring.yaml:" in lines[0] and "cannot be drawn" in lines[0]
    assert not (tmp_path / "p3.png").exists()


def test_cli_bad_at_and_suffix(tmp_path: Path) -> None:
    result = run("draw", P1, "-o", str(tmp_path / "x.png"), "--at", "psi=1")
    assert result.exit_code == 2 and "no coordinate 'psi' (did you mean 'phi'?)" in result.output
    result = run("draw", P1, "-o", str(tmp_path / "x.pdf"))
    assert result.exit_code == 2 and ".png or .svg" in result.output


def test_help_and_check_do_not_import_matplotlib() -> None:
    code = ("import sys; from click.testing import CliRunner; from rbdsolve.cli import main; "
            f"CliRunner().invoke(main, ['--help']); CliRunner().invoke(main, ['check', {P1!r}]); "
            "CliRunner().invoke(main, ['draw', '--help']); print('matplotlib' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT,
                         env={"PYTHONPATH": str(ROOT), "PATH": "/usr/bin:/bin"}, check=True)
    assert out.stdout.strip() == "False"
