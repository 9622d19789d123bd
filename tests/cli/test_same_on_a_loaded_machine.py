"""Issue 37, item 3: a file gives the same answer, the same route and the same exit code
on a quiet machine and on one whose cores are busy with other work.

The scenes are ones that sat at the old budget's edge: their exact route ran sympy's
solve for 18 to 60 s and the numeric route started only when that ran out, so a busy
machine changed the route and the exit code. Now the route is chosen from the
equations' structure (solvers/routes/routes.py) and the budget counts processor time
(solvers/routes/budget.py). Each is solved as a whole process once on the machine as it
is, then again while two busy-loop processes keep both cores loaded; the JSON, without
its ``seconds``, is the same. No clock is read: the 600 s timeouts guard against a hang.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import PROBLEMS, ROOT

SCENES = [PROBLEMS / "edges" / "inverted-rod-two-springs.yaml",  # exact: the whole 60 s, then numeric
          PROBLEMS / "contacts" / "half-disk-on-drum.yaml"]  # 18–44 s to say "transcendental"
BUSY = "while True:\n    pass\n"


def _solve(path: Path) -> tuple[int, dict]:
    done = subprocess.run([sys.executable, "-m", "rbdsolve", "solve", str(path), "-f", "json"], cwd=ROOT,
                          env={**os.environ, "PYTHONPATH": str(ROOT)}, capture_output=True, text=True, timeout=600)
    return done.returncode, _timeless(json.loads(done.stdout))


def _timeless(value):
    """The JSON without its ``seconds`` (the one thing a loaded machine may change)."""
    if isinstance(value, dict):
        return {k: _timeless(v) for k, v in value.items() if k != "seconds"}
    if isinstance(value, list):
        return [_timeless(v) for v in value]
    return value


@pytest.mark.parametrize("path", SCENES, ids=lambda p: p.name)
def test_the_same_answer_quiet_and_loaded(path: Path) -> None:
    quiet = _solve(path)
    busy = [subprocess.Popen([sys.executable, "-c", BUSY]) for _ in range(2)]
    try:
        loaded = _solve(path)
    finally:
        for process in busy:
            process.kill()
            process.wait()
    assert quiet[0] == 0 and loaded[0] == quiet[0]
    assert loaded[1] == quiet[1]
