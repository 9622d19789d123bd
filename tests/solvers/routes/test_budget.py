"""The time budget: a slow question ends with exit code 1 and a message, the timer's
ring gets through sympy's ``except Exception`` blocks, and nothing is left armed.

The budget counts processor time, so no test here reads a clock: each asserts what
happened (the work stopped, the next question ran), with budgets far from the work
(a tenth of a second against minutes), and loops that spend processor time where the
work must be endless."""

from __future__ import annotations

import json
import re
import resource
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest
from click.testing import CliRunner

from rbdsolve import solvers
from rbdsolve.cli import main
from rbdsolve.errors import UnsolvedError
from rbdsolve.problem import load_text
from rbdsolve.solvers import Options, solve_file
from rbdsolve.solvers.routes import budget
from rbdsolve.solvers.routes.budget import OutOfTime, available, within

from conftest import ROOT, spin

pytestmark = pytest.mark.skipif(not available(), reason="no SIGPROF on this platform")

# Three rods and a spring, small oscillations with every parameter symbolic: det(K − λM)
# is a cubic over the parameters (M and K have no common scale), and its roots, their
# signs and the mode shapes run for minutes on the exact route (measured: past 30 s of
# processor time). Not a structure the route choice can send elsewhere: without values
# there is no numeric route, so the budget is what ends it. The inertia is quick.
SLOW = """\
title: slow modes
parameters: [m, l, g, k]
coordinates: [a, b, c]
gravity: [0, -g]
points:
  A: l * [sin(a), -cos(a)]
  B: A + l * [sin(b), -cos(b)]
  C: B + l * [sin(c), -cos(c)]
bodies:
  r1: {shape: rod, mass: m, length: l, at: A/2, angle: a}
  r2: {shape: rod, mass: m, length: l, at: (A + B)/2, angle: b}
  r3: {shape: rod, mass: m, length: l, at: (B + C)/2, angle: c}
springs:
  s: {stiffness: k, between: [B, [0, -4*l]]}
questions:
  - modes: {about: {a: 0, b: 0, c: 0}}
  - inertia: {body: r1}
"""


def busy_swallowing(swallow_first: bool) -> None:
    """Work in a loop that catches Exception, as sympy does; the first ring may even be
    swallowed by a bare except."""
    swallowed = False
    while True:
        try:
            sum(range(1000))
        except Exception:  # noqa: BLE001 - what sympy does; OutOfTime must get through
            pass
        except BaseException:
            if not swallow_first or swallowed:
                raise
            swallowed = True


def assert_disarmed(previous) -> None:
    """The timer is off and the handler is the previous one; in place of the default
    action, the quiet handler (budget._disarm: a ring already on its way must not kill
    the process), whichever test happened to run first."""
    assert signal.getitimer(budget.TIMER) == (0.0, 0.0)
    restored = budget._stray if previous in (signal.SIG_DFL, None) else previous
    assert signal.getsignal(budget.SIGNAL) is restored


@pytest.mark.parametrize("swallow_first", [False, True])
def test_the_alarm_gets_through_except_exception(swallow_first: bool) -> None:
    previous = signal.getsignal(budget.SIGNAL)
    with pytest.raises(OutOfTime, match="'work' ran out of its 0.1 s budget"):
        with within(0.1, "'work'"):
            busy_swallowing(swallow_first)  # it ended: the loop alone never would
    assert_disarmed(previous)


def test_nothing_is_left_armed_after_work_that_ends_in_time() -> None:
    previous = signal.getsignal(budget.SIGNAL)
    with within(5, "'work'"):
        pass
    assert_disarmed(previous)
    spin(0.1)  # a stray ring would kill the test process here


def test_no_budget_and_other_threads_arm_nothing() -> None:
    with within(None, "'work'"):
        assert signal.getitimer(budget.TIMER) == (0.0, 0.0)
    seen = []
    thread = threading.Thread(target=lambda: seen.append(_armed_in_a_thread()))
    thread.start()
    thread.join(5)
    assert seen == [False]


def _armed_in_a_thread() -> bool:
    with within(0.01, "'work'"):
        return signal.getitimer(budget.TIMER) != (0.0, 0.0)


def test_a_slow_question_is_left_unanswered_and_the_next_one_runs() -> None:
    report = solve_file(load_text(SLOW, "slow.yaml"), Options(budget=4.0))
    first, second = report.solutions
    # one budget for the run: the first of two questions gets half of what the model left
    assert re.fullmatch(r"'modes' ran out of its share \(1\.\d+ s\) of the 4 s budget \(--budget to change "
                        r"it\)", first.error), first.error
    assert second.error is None and second.answers  # inertia: well under what is left
    assert signal.getitimer(budget.TIMER) == (0.0, 0.0)


def test_a_model_past_its_budget_fails_the_file_in_one_line(monkeypatch, tmp_path: Path) -> None:
    def endless(problem):
        spin(float("inf"))

    monkeypatch.setattr(solvers, "build_model", endless)
    with pytest.raises(UnsolvedError, match=r"slow.yaml: the model \(T and V\) ran out of its 0.2 s budget"):
        solve_file(load_text(SLOW, "slow.yaml"), Options(budget=0.2))
    path = tmp_path / "slow.yaml"
    path.write_text(SLOW, encoding="utf-8")
    result = CliRunner().invoke(main, ["solve", str(path), "--budget", "0.2"])
    assert result.exit_code == 1
    assert result.stderr.splitlines() == [
        f"{path}: the model (T and V) ran out of its 0.2 s budget (--budget to change it)"]


def test_budget_must_be_positive() -> None:
    result = CliRunner().invoke(main, ["solve", "x.yaml", "--budget", "0"])
    assert result.exit_code == 2 and "--budget" in result.output


def test_the_whole_process_ends_within_its_budget(tmp_path: Path) -> None:
    path = tmp_path / "slow.yaml"
    path.write_text(SLOW.replace("  - inertia: {body: r1}\n", ""), encoding="utf-8")
    # it ends: the 300 s timeout is a guard against a hang, far from the work
    done = subprocess.run([sys.executable, "-m", "rbdsolve", "solve", str(path), "--budget", "0.5", "-f", "json"],
                          capture_output=True, text=True, timeout=300, cwd=ROOT)
    assert done.returncode == 1, done.stderr
    # which stage the half second ends in depends on the machine's speed, not on rbdsolve: the
    # model (T and V) takes 0.3–0.6 s of processor time on a 2-core machine of 2026, the
    # modes question the rest (a run where the model alone spent it failed here once)
    line = json.loads(done.stdout)
    message = line["results"][0]["error"] if "results" in line else line["error"]["message"]
    assert re.search(r"(^'modes'|the model \(T and V\)) ran out of its (share \([\d.]+ s\) of the )?0\.5 s "
                     r"budget \(--budget to change it\)$", message), message
    assert "Traceback" not in done.stderr


def test_one_budget_caps_the_whole_run(monkeypatch) -> None:
    """Three questions that never end, after a model that spins 0.3 s: the run spends
    its 2 s of processor time and no more (each stage had the whole budget before: 2 s
    for the model and 2 s for each question, 8 s); each question gets a share of what
    is left, the first a third, the last all that remains."""
    def endless(question, model, options):
        spin(float("inf"))

    monkeypatch.setitem(solvers.FAMILIES, solvers.QuestionKind.EQUILIBRIA, solvers.Family(endless, endless))
    build = solvers.build_model
    monkeypatch.setattr(solvers, "build_model", lambda problem: (spin(0.3), build(problem))[1])
    text = SLOW.split("questions:")[0] + "questions:\n" + "  - equilibria\n" * 3
    start = time.process_time()
    report = solve_file(load_text(text, "slow.yaml"), Options(budget=2.0))
    spent = time.process_time() - start
    # below one more stage's whole 2 s (4 s and more), and far from the work after the
    # budget (the rings' latency, the report: 0.1–0.3 s quiet, 0.64 s once with both cores
    # busy with two other test runs, where processor time stretches too)
    assert 1.9 <= spent < 2.0 + 1.5, spent
    assert [s.error.split(" of the ")[-1] for s in report.solutions] == ["2 s budget (--budget to change it)"] * 3


def test_the_assumption_of_a_huge_ratio_is_bounded_by_the_budget(tmp_path: Path) -> None:
    """Issue 39: 'assumptions: [R > 1e300*r]' makes sympy factor with 300-digit
    coefficients, for minutes; each stage had the whole budget, so the default 60 s let
    it run past 90 s. Now the process spends its --budget of processor time, start-up
    and printing aside (measured as the child's processor time, not the clock)."""
    text = (ROOT / "problems" / "conditions" / "cylinder-in-cylinder.yaml").read_text(encoding="utf-8")
    path = tmp_path / "huge.yaml"
    path.write_text(text.replace("assumptions: [R > r]", "assumptions: [R > 1e300*r]"), encoding="utf-8")
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    done = subprocess.run([sys.executable, "-m", "rbdsolve", "solve", str(path), "--budget", "3"],
                          capture_output=True, text=True, timeout=600, cwd=ROOT)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    spent = (after.ru_utime + after.ru_stime) - (before.ru_utime + before.ru_stime)
    assert done.returncode == 1, done.stderr
    assert "ran out of its 3 s budget" in done.stderr
    assert spent < 3 + 3, spent  # start-up (~1 s) and the rings; each question had its own 3 s before: 12 s


def test_once_stopping_a_ring_raises_the_interrupt_not_out_of_time(monkeypatch) -> None:
    """Ctrl-C landing as a budget runs out: the ring that comes while the interrupt is on
    its way out must not replace it with OutOfTime (caught as a budget run out, the run
    would go on as if never interrupted; seen once on a loaded machine)."""
    monkeypatch.setattr(budget, "_stopping", [])
    budget.stop(KeyboardInterrupt)
    with pytest.raises(KeyboardInterrupt):
        with within(0.05, "'work'"):
            spin(float("inf"))


def test_the_whole_budget_is_said_whole_after_a_blink() -> None:
    """The model's share is the budget less what reading the file spent: 30 ms of a 0.2 s
    budget (a cold or loaded process) still reads "its 0.2 s budget" (past 1 %, 2 ms, it
    read "its share (0.17 s) of the 0.2 s budget", and a test of the message failed on a
    busy machine); half of it is a share."""
    from rbdsolve.solvers.routes.budget import OutOfTime

    assert "ran out of its 0.2 s budget" in str(OutOfTime(0.17, "the model (T and V)", total=0.2))
    assert "its share (0.1 s) of the 0.2 s budget" in str(OutOfTime(0.1, "the model (T and V)", total=0.2))
    assert "its share (30 s) of the 60 s budget" in str(OutOfTime(30, "'equilibria'", total=60))
