"""How the numeric route writes one configuration its search met at several coordinate
values: a double pendulum whose hinge spring holds θ₂ − θ₁ has the same configuration at
(θ₁, θ₂) + 2πk (1, 1) for every k. The search over ±10π meets them from (−10π, −10π)
up; the solution writes the one at (0, 0) and says the rest in one line."""

from __future__ import annotations

import math
from types import SimpleNamespace

from rbdsolve.solvers.configuration.placement import _nearest_zero_first
from rbdsolve.solvers.equilibria.steps import _written_also


def _root(*at: float) -> SimpleNamespace:
    return SimpleNamespace(at=at)


def test_the_root_nearest_zero_is_written_and_the_others_follow_by_distance() -> None:
    turns = [_root(2 * math.pi * k, 2 * math.pi * k) for k in (-5, -4, 0, 1, -1)]
    first, others = _nearest_zero_first(turns[0], turns[1:])
    assert first.at == (0, 0)
    assert [r.at[0] / (2 * math.pi) for r in others] == [1, -1, -4, -5]


def test_between_two_at_the_same_distance_the_positive_one_is_written() -> None:
    first, others = _nearest_zero_first(_root(-math.pi, -math.pi), [_root(math.pi, math.pi)])
    assert first.at == (math.pi, math.pi) and others[0].at == (-math.pi, -math.pi)


def test_whole_turns_of_every_angle_together_are_said_in_one_line() -> None:
    eq = SimpleNamespace(at={"theta1": 0.0, "theta2": 0.0},
                         equivalent=[{"theta1": 2 * math.pi * k, "theta2": 2 * math.pi * k} for k in (1, -1, 2, -2, 3)])
    step = _written_also(eq, model=None)
    assert "(θ₁, θ₂) + 2πk for k = −2, …, 3 (k ≠ 0; 5 more roots in the search box)" in " ".join(step.text.split())
