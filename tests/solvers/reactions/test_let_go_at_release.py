"""A support that does not hold at the state asked, with every value given: a disk
released inside a circular track above the level of the track's centre (a new user's
trial) printed the friction it needs there and the forces where it gets to, as if it
rolled; the track cannot pull, so the disk leaves it at once.

By hand, the disk (radius r) rolling inside the track (radius R), θ from the downward
vertical: T = ¾ m (R − r)² θ̇², and along the line of centres
N = m (R − r) θ̇² + m g cos θ, F = −(1/3) m g sin θ; released from rest at θ₀,
N = m g cos θ₀ there: negative past 90°, and then μ ≥ |F|/N means nothing."""

from __future__ import annotations

import math

import pytest

import rbdsolve
from conftest import DISK_IN_TRACK

DISK = DISK_IN_TRACK + """\
values: {m: 1 kg, r: 8 cm, R: 50 cm, g: 9.81 m/s^2}
questions:
  - reactions: {forces: [C], from_rest: {theta: THETA0 deg}, to: {theta: 0}}
"""


def _solved(tmp_path, degrees: int):
    path = tmp_path / "disk.yaml"
    path.write_text(DISK.replace("THETA0", str(degrees)))
    (solution,) = rbdsolve.solve(path, budget=1200.0)  # a budget far from the work
    return solution


def test_released_above_the_centre_the_disk_leaves_the_track_and_that_is_said(tmp_path) -> None:
    solution = _solved(tmp_path, 100)
    push = 9.81 * math.cos(math.radians(100))
    assert push < 0
    assert solution.values["at"]["C"]["components"]["N_C"] == pytest.approx(push, rel=1e-12)
    (said,) = [w for w in solution.warnings if "at the state asked" in w]
    assert said.startswith(f"N_C = {push:.6g} < 0") and "leaves it at once" in said and "not the motion's" in said
    assert not (solution.answers.least_friction_at or {}).get("C")
    assert not (solution.answers.least_friction_over or {}).get("C")


def test_released_below_the_centre_it_rolls_and_nothing_is_said(tmp_path) -> None:
    """N = m g cos 40° > 0: μ ≥ tan(40°)/3 at the release, by hand."""
    solution = _solved(tmp_path, 40)
    assert not [w for w in solution.warnings if "at the state asked" in w]
    assert solution.values["least_friction_at"]["C"] == pytest.approx(math.tan(math.radians(40)) / 3, rel=1e-12)
