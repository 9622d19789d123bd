"""``rbdsolve watch`` (issue 24): the poll loop with its clock and files injected (no
sleeping), the command through CliRunner with saves made between polls, and the live
display's layout."""

from __future__ import annotations

import io
import os
from pathlib import Path

import pytest
from click.testing import CliRunner
from rich.console import Console
from rich.text import Text

import rbdsolve.cli.watching as watch_module
from rbdsolve.cli import main
from rbdsolve.cli.batch import Failure, Outcome
from rbdsolve.cli.watching import Loop, State, Watched, status_line
from rbdsolve.cli.watch_view import Screen, View
from rbdsolve.errors import ExitCode

from conftest import PROBLEMS

PENDULUM = PROBLEMS / "examples" / "pendulum.yaml"


class Files:
    """Stamps and outcomes by script: what each file looks like at each poll."""

    def __init__(self, stamps: dict[str, list], outcomes: dict[str, list[Outcome]]):
        self.stamps, self.outcomes, self.solved = stamps, outcomes, []

    def stamp(self, name: str):
        return self.stamps[name][0]

    def solve(self, name: str) -> Outcome:
        self.solved.append(name)
        return self.outcomes[name].pop(0)

    def tick(self, seconds: float) -> None:
        for history in self.stamps.values():
            if len(history) > 1:
                history.pop(0)


def good(name: str, report: str) -> Outcome:
    return Outcome(name, report, None, 0.1)  # a stand-in report: the loop only keeps it


def bad(name: str, line: str) -> Outcome:
    return Outcome(name, None, Failure(line, None, ExitCode.BAD_INPUT, line), 0.1)


def test_the_loop_solves_on_a_save_keeps_the_last_good_report_and_skips_an_absent_file() -> None:
    files = Files({"a.yaml": [(1, 10), (1, 10), (2, 11), None, (3, 12), (3, 12)], "b.yaml": [(5, 5)]},
                  {"a.yaml": [good("a.yaml", "A1"), bad("a.yaml", "a.yaml:3:1: broken"), good("a.yaml", "A2")],
                   "b.yaml": [good("b.yaml", "B1")]})
    shown: list[State] = []
    loop = Loop(("a.yaml", "b.yaml"), files.solve, shown.append, sleep=files.tick, stamp=files.stamp, now=lambda: 0.0)
    final = loop.run(polls=5)
    assert files.solved == ["a.yaml", "b.yaml", "a.yaml", "a.yaml"]  # once each, then each save of a.yaml
    assert [(s.files[0].report, s.files[0].error) for s in shown] == [
        ("A1", None),  # the first solve
        ("A1", "a.yaml:3:1: broken"),  # invalid: the last good report stays, the error beneath
        ("A2", None),  # saved again (after a moment without the file): solved, the error gone
    ]
    assert final.latest == 0 and final.files[1].report == "B1" and final.rounds == 4


def test_ctrl_c_in_the_loop_leaves_it() -> None:
    def interrupted(seconds: float) -> None:
        raise KeyboardInterrupt

    files = Files({"a.yaml": [(1, 1)]}, {"a.yaml": [good("a.yaml", "A1")]})
    with pytest.raises(KeyboardInterrupt):
        Loop(("a.yaml",), files.solve, lambda state: None, sleep=interrupted, stamp=files.stamp).run()


def _saves(path: Path, texts: list[str]):
    """A sleep that saves the next text at each poll (with a newer mtime, as a save
    makes) and is Ctrl-C after the last."""
    pending = list(texts)
    mtime = [path.stat().st_mtime_ns]

    def sleep(seconds: float) -> None:
        if not pending:
            raise KeyboardInterrupt
        path.write_text(pending.pop(0), encoding="utf-8")
        mtime[0] += 10**9
        os.utime(path, ns=(mtime[0], mtime[0]))

    return sleep


def test_watch_resolves_on_save_survives_an_invalid_file_and_ctrl_c_exits_130(tmp_path, monkeypatch) -> None:
    """A rod pivoted at its end has T = ½ (M l²/3) θ̇²: 1/6 m l² θ̇² with M = m, then
    1/3 m l² θ̇² once the file says mass: 2*m; in between, a save that does not parse."""
    path = tmp_path / "p.yaml"
    text = PENDULUM.read_text(encoding="utf-8")
    path.write_text(text, encoding="utf-8")
    assert "mass: m," in text
    monkeypatch.setattr(watch_module, "pause", _saves(path, [text.replace("mass: m,", "mass: m +,"),
                                                             text.replace("mass: m,", "mass: 2*m,")]))
    result = CliRunner().invoke(main, ["watch", str(path)])
    assert result.exit_code == ExitCode.INTERRUPTED, result.output
    out = result.output
    first, error, second = out.index("T = 1/6 l² m θ̇²"), out.index("cannot read expression 'm +'"), out.index("T = 1/3 l² m θ̇²")
    assert first < error < second and out.rstrip().endswith("rbdsolve: interrupted")
    assert f"{path}:" in out[error - 200:error]  # the error is located in the file
    assert out.count("Compound pendulum") == 2  # the invalid save reprints no solution in a pipe


def test_watch_refuses_standard_input() -> None:
    result = CliRunner().invoke(main, ["watch", "-"])
    assert result.exit_code == 2 and "not standard input" in result.output


def test_the_screen_keeps_the_end_of_a_tall_solution_and_the_footer() -> None:
    console = Console(file=io.StringIO(), width=60, height=10, force_terminal=True, color_system=None)
    body = Text("\n".join(f"line {i}" for i in range(1, 31)))
    console.print(Screen(body, Text("status\nerror: broken")))
    lines = console.file.getvalue().rstrip("\n").split("\n")
    assert len(lines) == 10
    assert lines[0].startswith("… 23 lines above") and lines[1].strip() == "line 24" and lines[7].strip() == "line 30"
    assert [lines[8].strip(), lines[9].strip()] == ["status", "error: broken"]


def test_on_a_terminal_the_view_is_live() -> None:
    console = Console(file=io.StringIO(), width=80, height=20, force_terminal=True, color_system=None)
    state = State((Watched("p.yaml", None, "p.yaml:1:1: broken"),))
    with View(("p.yaml",), console) as view:
        assert view.live is not None
        view.show(state)
    out = console.file.getvalue()
    assert "p.yaml:1:1: broken" in out and status_line(state.files[0]) in out and "Ctrl-C" in out
