"""Issue 28, findings 4-5 and 12: options checked at the edge, budgets that stop the
work (never the process), output paths that are inputs, and writes that fail (a full
disk, a closed stream): one line and a documented exit code, never exit 3."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner

from rbdsolve.cli import main

from conftest import PROBLEMS, ROOT, SEED

PENDULUM = PROBLEMS / "examples" / "pendulum.yaml"
BAD = ROOT / "tests" / "problem" / "bad" / "001-yaml-unclosed-flow-mapping.yaml"
ENV = {**os.environ, "PYTHONPATH": str(ROOT)}


def run(*args):
    return CliRunner().invoke(main, [str(a) for a in args])


def process(*args: str, **kwargs) -> subprocess.CompletedProcess:
    """The real command in its own process: file descriptors, signals and exit codes
    as a shell sees them."""
    return subprocess.run([sys.executable, "-m", "rbdsolve", *map(str, args)], env=ENV, cwd=ROOT,
                          capture_output=True, text=True, timeout=120, **kwargs)


@pytest.mark.parametrize("command", ["solve", "key", "variants", "draw"])
@pytest.mark.parametrize("budget", ["nan", "inf", "-inf", "1e308", "1e-6", "0", "-1", "ten"])
def test_a_budget_out_of_range_is_a_usage_error(command: str, budget: str, tmp_path: Path) -> None:
    output = {"key": ["-o", tmp_path / "k.md"], "draw": ["-o", tmp_path / "d.png"]}.get(command, [])
    result = run(command, PENDULUM, *output, "--budget", budget)
    assert result.exit_code == 2, result.output
    assert "Invalid value for '--budget'" in result.output and budget in result.output
    assert "Traceback" not in result.output and "internal error" not in result.output


def test_a_budget_that_rings_at_once_stops_the_work_not_the_process() -> None:
    """A budget far shorter than its work, 300 times, then busy past the timer's repeat
    (the budget's clock is processor time): each ring stops the work (OutOfTime), and no
    ring is left to kill the process with SIGPROF's default action ("Profiling timer
    expired", exit code 155)."""
    code = ("import time, sympy as sp\n"
            "from rbdsolve.solvers.routes.budget import within, OutOfTime\n"
            "x = sp.Symbol('x')\n"
            "for i in range(300):\n"
            "    try:\n"
            "        with within(1e-6, 'x'):\n"
            "            sp.expand((x + i) ** 30)\n"
            "    except OutOfTime:\n"
            "        pass\n"
            "end = time.process_time() + 0.3\n"
            "while time.process_time() < end:\n"
            "    sum(range(1000))\n"
            "print('alive')\n")
    done = subprocess.run([sys.executable, "-c", code], env=ENV, capture_output=True, text=True, timeout=120)
    assert done.returncode == 0 and done.stdout == "alive\n", done.stderr


def test_the_smallest_budget_leaves_the_question_unanswered() -> None:
    done = process("solve", SEED / "p1-two-rods.yaml", "--budget", "0.001")
    assert done.returncode == 1, done.stderr
    assert "ran out of its 0.001 s budget" in done.stderr and "Traceback" not in done.stderr


def test_draw_takes_a_budget(tmp_path: Path) -> None:
    result = run("draw", SEED / "p1-two-rods.yaml", "-o", tmp_path / "p1.png", "--budget", "0.001")
    assert result.exit_code == 1 and "ran out of its 0.001 s budget" in result.output
    # the model or the mode shapes ran out (the processor timer's ticks may let the model's
    # few milliseconds through): the modes are not drawn either way
    assert not (tmp_path / "p1-modes.png").exists()
    drawn = run("draw", SEED / "p1-two-rods.yaml", "-o", tmp_path / "p1.png", "--budget", "30")
    assert drawn.exit_code == 0 and (tmp_path / "p1.png").exists() and (tmp_path / "p1-modes.png").exists()


@pytest.mark.parametrize("command", ["solve", "variants", "key"])
def test_an_output_that_is_an_input_is_refused(tmp_path: Path, command: str) -> None:
    name = "p.md" if command == "key" else "p.yaml"  # a key is .md, .tex...: a problem file so named
    problem = tmp_path / name
    problem.write_text(PENDULUM.read_text(encoding="utf-8"), encoding="utf-8")
    alias = tmp_path / "sub" / ".." / name
    (tmp_path / "sub").mkdir()
    extra = ["--format", "csv"] if command == "variants" else []
    result = run(command, problem, "-o", alias, *extra)
    assert result.exit_code == 2 and "this is one of the problem files" in result.output, result.output
    assert problem.read_text(encoding="utf-8") == PENDULUM.read_text(encoding="utf-8")


needs_dev_full = pytest.mark.skipif(not os.path.exists("/dev/full"), reason="no /dev/full here")


@needs_dev_full
@pytest.mark.parametrize("fmt", ["json", "terminal"])
def test_an_output_file_on_a_full_disk_is_one_line(fmt: str) -> None:
    done = process("solve", PENDULUM, "-f", fmt, "-o", "/dev/full")
    assert done.returncode == 2, done.stderr
    assert done.stderr == "cannot write /dev/full: No space left on device\n"


@needs_dev_full
def test_standard_output_on_a_full_disk_is_one_line() -> None:
    with open("/dev/full", "w") as full:
        done = subprocess.run([sys.executable, "-m", "rbdsolve", "solve", str(PENDULUM), "-f", "json"], env=ENV,
                              stdout=full, stderr=subprocess.PIPE, text=True, timeout=120)
    assert done.returncode == 2, done.stderr
    assert done.stderr == "cannot write to standard output: No space left on device\n"


@needs_dev_full
def test_standard_error_full_or_closed_costs_nothing(tmp_path: Path) -> None:
    """The answers are written and the exit code is the worst file's (2: one is bad),
    whether standard error takes the messages or not."""
    for stderr in (open("/dev/full", "w"), subprocess.DEVNULL, None):
        with open(tmp_path / "out.jsonl", "w") as out:
            closed = {"stderr": stderr} if stderr is not None else {"stderr": subprocess.DEVNULL,
                                                                      "preexec_fn": lambda: os.close(2)}
            done = subprocess.run([sys.executable, "-m", "rbdsolve", "solve", str(PENDULUM), str(BAD), "-f", "json"],
                                  env=ENV, stdout=out, timeout=120, **closed)
        assert done.returncode == 2
        assert (tmp_path / "out.jsonl").read_text().count("\n") == 2
