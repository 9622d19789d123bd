"""Progress where a solve is long (issue 24): the stages a solve goes through, the
display on a terminal (drawn at once here: the delay is a parameter, no sleeping), and
none with --format json or in a pipe."""

from __future__ import annotations

import io

from click.testing import CliRunner
from rich.console import Console

import rbdsolve.cli.progress as progress_module
import rbdsolve.cli.solve as solve_command
from rbdsolve.cli import main
from rbdsolve.cli.app import Source
from rbdsolve.cli.batch import Outcome, Settings, solve_source
from rbdsolve.cli.progress import Progress

from conftest import PROBLEMS

PENDULUM = PROBLEMS / "examples" / "pendulum.yaml"


def test_a_solve_says_each_stage_as_it_starts() -> None:
    stages: list[str] = []
    outcome = solve_source(Source(str(PENDULUM)), Settings(), stages.append)
    assert outcome.report is not None
    assert stages == ["the model (T and V)", "question 1 of 3: eom", "question 2 of 3: equilibria",
                      "question 3 of 3: modes"]


def _terminal() -> Console:
    return Console(file=io.StringIO(), width=100, force_terminal=True, color_system=None)


def test_the_display_shows_the_file_and_its_stage() -> None:
    console = _terminal()
    with Progress(2, True, delay=0, console=console) as shown:
        shown.started("exam/p1.yaml")
        shown.stage("question 2 of 3: modes")
        shown.display.refresh()
        shown.advance(Outcome("exam/p1.yaml", None, None, 1.0))
        shown.display.refresh()
    out = console.file.getvalue()
    assert "solving" in out and "exam/p1.yaml: question 2 of 3: modes" in out and "1/2" in out


def test_nothing_is_drawn_when_not_shown_or_before_the_delay() -> None:
    for progress in (Progress(1, False, delay=0, console=_terminal()), Progress(1, True, delay=60, console=_terminal())):
        with progress as shown:
            shown.started("p1.yaml")
            shown.stage("question 1 of 1: modes")
        assert shown.display is None and shown.console.file.getvalue() == ""


def test_no_progress_with_format_json(monkeypatch) -> None:
    """On a terminal (as the command sees it), with no delay: drawn for the text
    format, not for JSON, whose standard error stays clean for scripts too."""
    monkeypatch.setattr(solve_command, "stderr_is_terminal", lambda: True)
    monkeypatch.setattr(progress_module, "DELAY", 0.0)
    drawn: list[bool] = []
    real_start = Progress._start

    def start(self):
        drawn.append(True)
        real_start(self)

    monkeypatch.setattr(Progress, "_start", start)
    json_run = CliRunner().invoke(main, ["solve", str(PENDULUM), "--format", "json"])
    assert json_run.exit_code == 0 and drawn == []
    text_run = CliRunner().invoke(main, ["solve", str(PENDULUM)])
    assert text_run.exit_code == 0 and drawn == [True]
