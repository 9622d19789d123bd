"""The least coefficient of friction over a whole motion released from rest, with every
value given (solvers/reactions/largest.py): a new user's hoop on an incline held by a
spring printed only the μ needed at the release (0.233), where rolling through the
motion needs 1.528.

The hoop, by hand (x up the slope, e_t = (cos α, sin α), e_n = (−sin α, cos α); its
centre at x e_t + r e_n, W = r e_n + (0, l₀), so the spring's length is
ℓ = √(l₀² − 2 l₀ x sin α + x²) and its pull on the hoop k (ℓ − l₀)(W − P)/ℓ):

    rolling, J = m r²:         F = −m ẍ
    along the slope:           2 m ẍ = −m g sin α + k (ℓ − l₀)(l₀ sin α − x)/ℓ
    across it:                 N = m g cos α − k (ℓ − l₀) l₀ cos α/ℓ
    energy from rest at x = 0: V(x) = m g x sin α + ½ k (ℓ − l₀)² = V(0) = 0 where it turns

so μ(x) = m |ẍ|/N, at its largest over [x_t, 0], x_t the turning point (ẍ(0) < 0: it
sets off down the slope). Found here with scipy's brentq and a dense sample, apart from
rbdsolve.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import sympy as sp
from scipy.optimize import brentq, minimize_scalar

import rbdsolve
from conftest import DISK_IN_TRACK, HOOP_ON_INCLINE
from rbdsolve.solvers.reactions.first_zero import FirstZero
from rbdsolve.solvers.reactions.largest import largest_friction

HOOP = HOOP_ON_INCLINE + "values: {m: 2 kg, r: 0.3 m, k: K N/m, l0: 0.5 m, alpha: 25 deg, g: 9.81 m/s^2}\n"


def _hoop_by_hand(k: float, slant: float) -> tuple[float, float, float]:
    """The largest μ over the motion, where, and the turning point (module docstring),
    the spring anchored at W = r e_n + l₀ (cos(α + s), sin(α + s)): s = π/2 − α is
    (0, l₀), straight above; d = W − P = l₀ (cos(α + s), sin(α + s)) − x e_t, so
    d·e_t = l₀ cos s − x and d·e_n = l₀ sin s."""
    m, l0, a, g = 2.0, 0.5, math.radians(25), 9.81

    def length(x):
        return np.sqrt(l0**2 - 2 * l0 * x * np.cos(slant) + x**2)

    def mu(x):
        pull = k * (length(x) - l0) / length(x)
        xdd = (-m * g * np.sin(a) + pull * (l0 * np.cos(slant) - x)) / (2 * m)
        return m * np.abs(xdd) / (m * g * np.cos(a) - pull * l0 * np.sin(slant))

    turn = brentq(lambda x: m * g * x * math.sin(a) + 0.5 * k * (length(x) - l0) ** 2, -2.0, -1e-7)
    xs = np.linspace(turn, 0.0, 20001)
    i = int(np.argmax(mu(xs)))
    best = minimize_scalar(lambda x: -mu(x), bounds=(xs[max(i - 1, 0)], xs[min(i + 1, len(xs) - 1)]),
                           method="bounded", options={"xatol": 1e-12})
    return max((-best.fun, best.x), (mu(xs[i]), xs[i])) + (turn,)  # an end's sample may be the largest


ABOVE, SLANTED = "[0, l0]", "l0*[cos(alpha + 1/2), sin(alpha + 1/2)]"


@pytest.mark.parametrize("k, anchor", [(80.0, ABOVE), (8000.0, SLANTED)])
def test_a_hoop_held_by_a_spring_needs_the_friction_of_its_turning_point(tmp_path, k, anchor) -> None:
    """k = 80 N/m straight above, the new user's; 8000 N/m slanted half a radian above
    the slope turns the hoop back 2.7 mm down it, inside the first of the steps along x
    (4.4 mm), where the search for the turning point returned the release itself (q̇² = 0
    there) and μ was taken over no span: 0.233 for 0.474 (a review's)."""
    path = tmp_path / "hoop.yaml"
    path.write_text(HOOP.replace("k: K N/m", f"k: {k:g} N/m").replace("+ [0, l0]", f"+ {anchor}"))
    (solution,) = rbdsolve.solve(path, budget=1200.0)  # a budget far from the work
    slant = math.pi / 2 - math.radians(25) if anchor == ABOVE else 0.5
    largest, at, turn = _hoop_by_hand(k, slant)
    found = solution.answers.least_friction_over["C"]
    if k == 80:
        assert largest == pytest.approx(1.52807, abs=5e-6)  # the new user's own check, check_p5.py
    assert found.mu == pytest.approx(largest, rel=1e-9)
    assert found.at["x"] == pytest.approx(at, abs=1e-6)
    assert found.until["x"] == pytest.approx(turn, abs=1e-9) and found.lost is None
    assert solution.values["least_friction_at"]["C"] == pytest.approx(math.tan(math.radians(25)) / 2, rel=1e-12)
    assert solution.answers.first_zero["N_C"].turns_at["x"] == pytest.approx(turn, abs=1e-9)  # a length steps too


q = sp.Symbol("q")
TURNS = {"N": FirstZero(None, {"q": 2.0})}


def test_an_interior_peak_is_found_between_samples() -> None:
    """μ = |sin 3q|/(2 + cos 3q) on [0, 2]: d/du sin u/(2 + cos u) = (2 cos u + 1)/(…)²,
    zero at cos 3q = −½, where μ = (√3/2)/(3/2) = 1/√3 (q = 2π/9 and 4π/9)."""
    found = largest_friction(2 + sp.cos(3 * q), sp.sin(3 * q), "N", TURNS, q * (2 - q), q, 0.0, "q")
    assert found.mu == pytest.approx(1 / math.sqrt(3), rel=1e-12)
    assert min(abs(found.at["q"] - 2 * math.pi / 9), abs(found.at["q"] - 4 * math.pi / 9)) < 1e-5
    assert found.until == {"q": 2.0} and found.lost is None


def test_the_span_ends_where_another_push_is_lost_first() -> None:
    """μ = q/1 grows along the way: its largest is where the motion as modelled ends."""
    first = {"N": FirstZero(None, {"q": 2.0}), "T": FirstZero({"q": 0.5}, None)}
    found = largest_friction(sp.Integer(1), q, "N", first, q * (2 - q), q, 0.0, "q")
    assert found.mu == pytest.approx(0.5, rel=1e-12) and found.until == {"q": 0.5} and found.lost == "T"


def test_no_number_where_its_own_push_is_lost_on_the_way() -> None:
    """N → 0 on the way: the friction needed grows without bound towards that place."""
    first = {"N": FirstZero({"q": 1.0}, None)}
    assert largest_friction(1 - q, q, "N", first, q * (2 - q), q, 0.0, "q") is None


def test_a_motion_that_goes_round_is_taken_over_one_turn() -> None:
    """q̇² = 2 sin q grows from 0 at q = 0 (first_zero found the push positive all round):
    the span is one whole turn, where |sin q|/(2 + cos q) is largest at cos q = −½, 1/√3
    (q = 2π/3 and 4π/3)."""
    first = {"N": FirstZero(None, None)}
    found = largest_friction(2 + sp.cos(q), sp.sin(q), "N", first, 2 * sp.sin(q), q, 0.0, "q")
    assert found.mu == pytest.approx(1 / math.sqrt(3), rel=1e-12) and found.until is None
    assert min(abs(found.at["q"] - 2 * math.pi / 3), abs(found.at["q"] - 4 * math.pi / 3)) < 1e-5


def test_released_at_an_equilibrium_it_stays() -> None:
    first = {"N": FirstZero(None, None)}
    assert largest_friction(sp.Integer(1), sp.sin(q), "N", first, sp.cos(q) - 1, q, 0.0, "q") is None


DISK_ON_DRUM = """\
parameters: [m, r, R, theta0, g]
values: {m: 1.2 kg, r: 6 cm, R: 40 cm, theta0: 12 deg, g: 9.81 m/s^2}
coordinates: [theta]
gravity: [0, -g]
bodies:
  disk: {shape: disk, mass: m, radius: r}
contacts:
  C: {body: disk, rolls_on: {circle: {centre: [0, 0], radius: R, side: outside}}, along: theta}
questions:
  - reactions: {forces: [C], from_rest: {theta: theta0}}
"""


def test_where_the_contact_is_lost_on_the_way_no_largest_friction_is_given_and_that_is_said(tmp_path) -> None:
    """A disk rolling off a drum (a new user's): by hand, with ρ = R + r, T = ¾ m ρ² θ̇²
    (its spin ρ θ̇/r) and V = m g ρ cos θ, so ρ θ̇² = (4/3) g (cos θ₀ − cos θ), and along
    the line of centres N = m g cos θ − m ρ θ̇² = m g (7 cos θ − 4 cos θ₀)/3, zero at
    cos θ = 4 cos θ₀/7; F = m g sin θ/3 stays finite there, so |F|/N grows without bound."""
    path = tmp_path / "disk.yaml"
    path.write_text(DISK_ON_DRUM)
    (solution,) = rbdsolve.solve(path, budget=1200.0)  # a budget far from the work
    lost = math.acos(4 * math.cos(math.radians(12)) / 7)
    assert solution.answers.first_zero["N_C"].lost_at["theta"] == pytest.approx(lost, abs=1e-9)
    assert solution.answers.least_friction_over is None
    (said,) = [w for w in solution.warnings if "grows without bound" in w]
    assert f"θ = {lost:.6g}" in said


MASS_OPEN = DISK_IN_TRACK + """\
values: {r: 8 cm, R: 50 cm, g: 9.81 m/s^2}
questions:
  - reactions: {forces: [C], from_rest: {theta: 40 deg}}
"""


def test_a_mass_left_open_does_not_keep_the_largest_friction_back(tmp_path) -> None:
    """A disk rolling inside a track, its mass m open (a new user's trial): by hand,
    N = m g (7 cos θ − 4 cos θ₀)/3 and F = −m g sin θ/3 along the motion, so
    μ(θ) = |sin θ|/(7 cos θ − 4 cos θ₀) whatever m; d/dθ of sin θ/(7 cos θ − 4 cos θ₀)
    is (7 − 4 cos θ₀ cos θ)/(…)² > 0, so over [−θ₀, θ₀] it is largest at the ends:
    tan θ₀/3 at θ₀ = 40° (and −θ₀, where it turns back)."""
    path = tmp_path / "disk.yaml"
    path.write_text(MASS_OPEN)
    (solution,) = rbdsolve.solve(path, budget=1200.0)  # a budget far from the work
    found = solution.answers.least_friction_over["C"]
    theta0 = math.radians(40)
    assert found.mu == pytest.approx(math.tan(theta0) / 3, rel=1e-9)
    assert abs(found.at["theta"]) == pytest.approx(theta0, abs=1e-6)
    assert found.until["theta"] == pytest.approx(-theta0, abs=1e-9)
