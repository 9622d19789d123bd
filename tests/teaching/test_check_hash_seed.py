"""teaching/check.py: a student's check does not depend on the hash seed of the run.

The sampler draws the answer's symbols, then those only the assumptions hold. The latter
were once drawn in a set's iteration order, so with assumptions a > b + c, b > c (none of
them in the answer) the first admissible point, and so the point a wrong answer is
shown "different at", changed with PYTHONHASHSEED (0 gave g = 8, 2 gave g = 3)."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

SCENE = """
parameters: {m: mass, l: length, g: acceleration, a: length, b: length, c: length}
coordinates: [theta]
gravity: [0, -g]
assumptions: [a > b + c, b > c]
points:
  P: l * [sin(theta), -cos(theta)]
bodies:
  bob: {shape: particle, mass: m, at: P}
questions: [modes]
"""

# no condition for equality can be solved for: the verdict names a sampled point
ANSWER = "modes.M[1][1] = m*l**2 + exp(m*l) + exp(g*l)"


def _checked_with_seed(path: Path, seed: int) -> str:
    env = {**os.environ, "PYTHONHASHSEED": str(seed)}
    run = subprocess.run([sys.executable, "-m", "rbdsolve", "grade", str(path), "-a", ANSWER],
                         env=env, capture_output=True, text=True)
    assert run.returncode == 1, run.stderr  # the answer is wrong
    return run.stdout


def test_the_point_shown_is_the_same_whatever_the_hash_seed(tmp_path: Path) -> None:
    path = tmp_path / "p.yaml"
    path.write_text(SCENE)
    first = _checked_with_seed(path, 0)
    assert "different at" in first
    assert first == _checked_with_seed(path, 2)
