"""The process's way out (cli.app.run): the command's exit code, every byte of its
output and the exit handlers, also where it skips the interpreter's teardown."""

from __future__ import annotations

import json
import subprocess
import sys

from click.testing import CliRunner

from conftest import ROOT, SEED
from rbdsolve.cli import main


def process(*args: str, code: str | None = None) -> subprocess.CompletedProcess:
    command = [sys.executable, "-c", code] if code else [sys.executable, "-m", "rbdsolve", *args]
    return subprocess.run(command, capture_output=True, text=True, cwd=ROOT,
                          env={"PYTHONPATH": str(ROOT)}, timeout=120, check=False)


def without_seconds(line: str) -> dict:
    """A JSON report without its timings, which differ from run to run."""
    report = json.loads(line)
    for result in report["results"]:
        result.pop("seconds")
    return report


def test_a_solve_prints_all_it_would_print_in_process() -> None:
    p1 = str(SEED / "p1-two-rods.yaml")
    done = process("solve", p1, "--format", "json")
    inside = CliRunner().invoke(main, ["solve", p1, "--format", "json"])
    assert done.returncode == inside.exit_code == 0, done.stderr
    assert without_seconds(done.stdout) == without_seconds(inside.output)


def test_a_failure_keeps_its_exit_code_and_message() -> None:
    done = process("check", "no-such-file.yaml")
    assert done.returncode == 2
    assert "no such file" in done.stderr


def test_exit_handlers_still_run() -> None:
    """A handler registered before the command (as a library's would be) runs, after
    the command's output."""
    code = ("import atexit, sys\n"
            "atexit.register(lambda: print('handler ran', flush=True))\n"
            "sys.argv = ['rbdsolve', '--version']\n"
            "from rbdsolve.cli import run\n"
            "run()\n")
    done = process(code=code)
    assert done.returncode == 0
    assert done.stdout.endswith("handler ran\n") and "version" in done.stdout


def test_a_profiler_still_writes_its_results(tmp_path) -> None:
    """python -m cProfile -o FILE -m rbdsolve …: the profile is written when the
    interpreter ends, so a profiled process leaves by Python's own exit."""
    out = tmp_path / "check.prof"
    done = subprocess.run([sys.executable, "-m", "cProfile", "-o", str(out), "-m", "rbdsolve", "--version"],
                          capture_output=True, text=True, cwd=ROOT, env={"PYTHONPATH": str(ROOT)}, timeout=120)
    assert done.returncode == 0, done.stderr
    assert out.stat().st_size > 0
