"""Issue 8, case 6: an exact route that would run long is stopped at its budget, in a
whole process. A 64-link chain of rods with symbolic m, l, g: the exact route's model
section and its modes each take seconds of processor time, twenty times a budget of
0.1 s, so the budget runs out on any machine, quiet or loaded (the budget counts
processor time). That auto then answers on the numeric route, with the budget again,
is tested with a fake route (tests/solvers/routes/test_routes.py): no budget separates
the two real routes by a wide enough margin on every machine.
"""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

from rbdsolve.solvers.routes.budget import available

pytestmark = pytest.mark.skipif(not available(), reason="no SIGPROF on this platform")

N = 64


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


def _run(path, *args: str) -> subprocess.CompletedProcess:
    # the 300 s timeout guards against a hang, far from the work
    return subprocess.run([sys.executable, "-m", "rbdsolve", "solve", str(path), "--format", "json", *args],
                          capture_output=True, text=True, timeout=300)


def test_the_budget_is_honoured_in_a_whole_process(tmp_path) -> None:
    path = tmp_path / "chain.yaml"
    path.write_text(chain(N))
    exact = _run(path, "--route", "exact", "--budget", "0.1")
    assert exact.returncode == 1, exact.stderr
    assert "ran out of its 0.1 s budget" in json.loads(exact.stdout)["error"]["message"]
    assert "Traceback" not in exact.stderr
