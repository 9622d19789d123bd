"""A zero of a push along the motion is a loss only where the push held before it. A disk
released inside a circular track had its N = 0 at cos θ = 4/7 cos θ₀ printed as "the
contact is lost … only when θ₀ ≥ π/2" (a new user's trial); released past 90°, N < 0 at
the release and the disk leaves at once, so that zero is where N rises back through zero.

By hand, the disk (radius r) rolling inside the track (radius R), θ from the downward
vertical: T = ¾ m (R − r)² θ̇², V = −m g (R − r) cos θ, so released from rest at θ₀,
θ̇² = 4 g (cos θ − cos θ₀)/(3 (R − r)); along the line of centres
N = m (R − r) θ̇² + m g cos θ = (1/3) m g (7 cos θ − 4 cos θ₀). On the way, cos θ ≥ cos θ₀:
for θ₀ < π/2, N ≥ m g cos θ₀ > 0 throughout; for θ₀ > π/2, N(θ₀) = m g cos θ₀ < 0.

The control, where the loss is real: the same disk rolling on the outside of a fixed drum
(radius R), θ from the upward vertical: θ̇² = 4 g (cos θ₀ − cos θ)/(3 (R + r)) and
N = m g cos θ − m (R + r) θ̇² = (1/3) m g (7 cos θ − 4 cos θ₀), zero at cos θ = 4/7 cos θ₀,
which the disk reaches rolling down from any θ₀ in (0, π/2), where N(θ₀) = m g cos θ₀ > 0."""

from __future__ import annotations

import math

import pytest
import sympy as sp

import rbdsolve
from conftest import DISK_IN_TRACK

OPEN_RELEASE = DISK_IN_TRACK.replace("[m, r, R, g]", "[m, r, R, g, theta0]") + """\
questions:
  - reactions: {forces: [C], from_rest: {theta: theta0}}
"""

ON_TOP = OPEN_RELEASE.replace("side: inside", "side: outside")


def _solved(tmp_path, text: str):
    path = tmp_path / "scene.yaml"
    path.write_text(text)
    (solution,) = rbdsolve.solve(path, budget=1200.0)  # a budget far from the work
    return solution


def _hand_disk_push(theta: float, theta0: float) -> float:
    return (7 * math.cos(theta) - 4 * math.cos(theta0)) / 3  # N/(m g)


def test_the_disk_inside_a_track_is_never_said_to_lose_contact(tmp_path) -> None:
    solution = _solved(tmp_path, OPEN_RELEASE)
    assert not solution.answers.contact_lost.get("N_C")
    text = "\n".join(str(step) for step in solution.steps)
    assert "so the contact is lost" not in text
    assert "does not reach zero along the motion: the contact holds throughout, where it holds at the release" in text
    # the hand derivation it rests on: no zero on the way below 90°, a pull at the release above it
    for theta0 in (0.2, 0.8, 1.3, 1.55):
        assert min(_hand_disk_push(theta0 * k / 50, theta0) for k in range(51)) > 0
    for theta0 in (1.6, 2.0, 3.0):
        assert _hand_disk_push(theta0, theta0) < 0


def test_its_push_along_the_motion_is_the_hand_one(tmp_path) -> None:
    push = _solved(tmp_path, OPEN_RELEASE).answers.along["C"]["N_C"]
    names = {str(s): s for s in push.free_symbols}
    (theta,) = [f for f in push.atoms(sp.Function) if str(f.func) == "theta"]
    for value, start in ((0.3, 0.7), (-0.5, 1.2), (2.0, 2.5)):
        at = push.subs(theta, value).subs(names["theta0"], start) / (names["m"] * names["g"])
        assert float(at) == pytest.approx(_hand_disk_push(value, start), rel=1e-12, abs=1e-12)


def test_a_disk_on_top_of_a_drum_still_leaves_it(tmp_path) -> None:
    """The control: N = (1/3) m g (7 cos θ − 4 cos θ₀) = 0 at cos θ = 4/7 cos θ₀, reached."""
    solution = _solved(tmp_path, ON_TOP)
    (where,) = solution.answers.contact_lost["N_C"]
    (theta0,) = [s for s in where.rhs.free_symbols if str(s) == "theta0"]
    assert sp.simplify(where.rhs - sp.Rational(4, 7) * sp.cos(theta0)) == 0
    assert "so the contact is lost" in "\n".join(str(step) for step in solution.steps)
