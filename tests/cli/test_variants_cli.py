"""``rbdsolve variants``: it says which file it wrote, and a bar follows the stages of a
large table on a terminal only."""

from __future__ import annotations

import pytest
from click.testing import CliRunner

from rbdsolve.cli import main
from rbdsolve.cli import variants as command

from conftest import SIMPLE_PENDULUM

PENDULUM = "title: Pendulum\n" + SIMPLE_PENDULUM + """\
values: {m: 2, l: {range: [0.5, 2], step: 0.25}, g: 10}
questions:
  - modes: {about: {theta: 0}}
"""


@pytest.fixture
def scene(tmp_path):
    path = tmp_path / "pendulum.yaml"
    path.write_text(PENDULUM, encoding="utf-8")
    return path


class Recorder:
    """A stand-in for the bar: whether it was shown, and each stage it was told."""

    made: list = []

    def __init__(self, shown: bool):
        self.shown, self.stages = shown, []
        Recorder.made.append(self)

    def __enter__(self):
        return lambda what, done, total: self.stages.append((what, done, total))

    def __exit__(self, *exc):
        pass


def run(*args):
    return CliRunner().invoke(main, ["variants", *map(str, args), "--verify", "1"])


def test_the_file_written_is_named_on_standard_error(scene, tmp_path) -> None:
    out = tmp_path / "sheet.json"
    result = run(scene, "-n", "4", "-o", out)
    assert result.exit_code == 0, result.output
    assert f"{scene}: wrote 4 variants to {out} (json)" in result.stderr.splitlines()
    assert out.exists() and result.stdout == ""


def test_a_table_on_standard_output_names_no_file(scene) -> None:
    result = run(scene, "-n", "1")
    assert result.exit_code == 0 and "wrote" not in result.stderr
    assert len(result.stdout.splitlines()) == 2  # the header and one variant


def test_a_large_table_on_a_terminal_shows_each_stage(scene, tmp_path, monkeypatch) -> None:
    Recorder.made = []
    monkeypatch.setattr(command, "_progress", Recorder)
    monkeypatch.setattr(command, "stderr_is_terminal", lambda: True)
    monkeypatch.setattr(command, "PROGRESS_FROM", 3)
    assert run(scene, "-n", "3", "-o", tmp_path / "a.csv").exit_code == 0
    assert run(scene, "-n", "2", "-o", tmp_path / "b.csv").exit_code == 0
    big, small = Recorder.made
    assert big.shown and not small.shown
    names = [what for what, _, _ in big.stages]
    assert names[:3] == ["drawing the values", "solving the problem exactly", "evaluating the answers"]
    assert ("each variant's stability and motions", 3, 3) in big.stages
    assert ("checking variants by a full solve", 0, 1) in big.stages and names[-1] == "writing the table"


def test_no_bar_when_standard_error_is_not_a_terminal(scene, tmp_path, monkeypatch) -> None:
    Recorder.made = []
    monkeypatch.setattr(command, "_progress", Recorder)
    monkeypatch.setattr(command, "PROGRESS_FROM", 1)
    assert run(scene, "-n", "3", "-o", tmp_path / "a.csv").exit_code == 0
    assert not Recorder.made[0].shown
