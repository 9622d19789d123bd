"""Issue 8, case 6: an exact route that would run long is stopped at its budget, and
with values the numeric route answers (auto). A 64-link chain of rods with symbolic
m, l, g: the exact route's model section and its modes each take well over 1 s (issue 23
made the 32-link chain's exact modes, the case before, finish within 1 s with values);
with --budget 1 the command must end within the budget(s) plus the start-up of a
trivial solve (import of sympy, measured in the same test) and a 1.5 s margin. Three
CLI runs in subprocesses: about 8 s in all.
"""

from __future__ import annotations

import json
import subprocess
import sys
import time

import pytest

from rbdsolve.solvers.shared.budget import available

pytestmark = pytest.mark.skipif(not available(), reason="no SIGALRM on this platform")

N = 64
MARGIN = 1.5  # seconds over the budgets and the start-up


def chain(n: int) -> str:
    points = ["  P0: [0, 0]"]
    bodies = []
    for i in range(1, n + 1):
        points += [f"  P{i}: P{i - 1} + l * [sin(th{i}), -cos(th{i})]",
                   f"  G{i}: P{i - 1} + l/2 * [sin(th{i}), -cos(th{i})]"]
        bodies.append(f"  rod{i}: {{shape: rod, mass: m, length: l, at: G{i}, angle: th{i}, axis: y}}")
    at_rest = ", ".join(f"th{i}: 0" for i in range(1, n + 1))
    return ("parameters: {m: mass, l: length, g: gravity}\n"
            f"coordinates: [{', '.join(f'th{i}' for i in range(1, n + 1))}]\n"
            "gravity: [0, -g]\npoints:\n" + "\n".join(points) + "\nbodies:\n" + "\n".join(bodies)
            + f"\nquestions:\n  - modes: {{about: {{{at_rest}}}}}\n")


def _run(path, *args: str) -> tuple[subprocess.CompletedProcess, float]:
    start = time.perf_counter()
    run = subprocess.run([sys.executable, "-m", "rbdsolve", "solve", str(path), "--format", "json", *args],
                         capture_output=True, text=True, timeout=60)
    return run, time.perf_counter() - start


def test_the_budget_is_honoured_and_auto_answers_with_values(tmp_path) -> None:
    trivial = tmp_path / "pendulum.yaml"
    trivial.write_text(chain(1))
    _, startup = _run(trivial, "--route", "exact")
    path = tmp_path / "chain.yaml"
    path.write_text(chain(N))

    exact, elapsed = _run(path, "--route", "exact", "--budget", "1")
    assert exact.returncode == 1
    assert "ran out of its 1 s budget" in json.loads(exact.stdout)["error"]["message"]
    assert elapsed <= startup + 1 + MARGIN, (elapsed, startup)

    # auto with values: the model's budget (then the coordinates only), the exact modes'
    # budget (they need about 2 s), then the numeric route's (about 0.35 s)
    auto, elapsed = _run(path, "--budget", "1", "--set", "m=1", "--set", "l=1", "--set", "g=9.81")
    assert elapsed <= startup + 3 * 1 + MARGIN, (elapsed, startup)
    assert auto.returncode == 0, auto.stderr
    result = json.loads(auto.stdout)["results"][0]
    assert result["ok"] and result["route"] == "numeric"
    assert "ran out of its 1 s budget" in result["warnings"][0]
    # K = g l m diag(n − i + 1/2) and M are positive definite: every λ an oscillation
    assert len(result["answers"]["eigenvalues"]) == N
    assert all(m == "oscillation" for m in result["answers"]["motions"])
