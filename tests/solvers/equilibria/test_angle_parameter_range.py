"""An angle parameter (an incline's α) is studied over (0, π): a condition or a Hessian
that keeps one sign there decides, though sin α alone has no sign (a new user's disk on
a spring on an incline: the tilted equilibria were said to exist always, "True", and the
top's stability undetermined).

By hand: the disk of radius r is pinned at a point O of its rim, its centre at
r (sin θ, −cos θ); the rim point B opposite O is at 2r (sin θ, −cos θ), tied by a spring
(k, natural length 2r) to A = (0, −3r). Gravity's part in the plane is g sin α along −y,
w = m g sin α. The spring's length is r √(13 − 12 cos θ), so

    ∂V/∂θ = r sin θ (w + 6 k r (1 − 2/√(13 − 12 cos θ))).

Tilted equilibria: √(13 − 12 cos θ) = 12 k r/(w + 6 k r), which lies in [1, 5] (cos θ in
[−1, 1]) exactly when 12 k r ≥ w + 6 k r, k ≥ k_c = w/(6 r). At θ = π, √25 = 5 and
K = −r (w + 18 k r/5) < 0 for every α in (0, π): unstable."""

from __future__ import annotations

import json
import math

from click.testing import CliRunner

from rbdsolve.cli import main

from conftest import ROD_ON_INCLINE, same

DISK = """title: a pinned disk on an incline, on a spring
parameters: [m, r, g, k, alpha]
coordinates: [theta]
gravity: [0, -g*sin(alpha), -g*cos(alpha)]
points:
  A: [0, -3*r]
bodies:
  disk: {shape: disk, mass: m, radius: r, at: "r*[sin(theta), -cos(theta)]", angle: theta,
         points: {B: [0, -r]}}
springs:
  s: {stiffness: k, between: [B, A], natural_length: 2*r}
questions:
  - equilibria
"""


def _equilibria(tmp_path) -> list[dict]:
    path = tmp_path / "p.yaml"
    path.write_text(DISK, encoding="utf-8")
    out = CliRunner().invoke(main, ["solve", str(path), "--format", "json"])
    assert out.exit_code == 0, out.output
    (result,) = json.loads(out.stdout)["results"]
    return result["answers"]["equilibria"]


def _tilted_cosine(m: float, r: float, g: float, k: float, alpha: float) -> float:
    """cos θ of the tilted pair, from √(13 − 12 cos θ) = 12 k r/(w + 6 k r)."""
    w = m * g * math.sin(alpha)
    return (13 - (12 * k * r / (w + 6 * k * r)) ** 2) / 12


def test_the_tilted_pair_exists_above_the_critical_stiffness(tmp_path) -> None:
    found = _equilibria(tmp_path)
    tilted = [e for e in found if e["at"]["theta"] not in ("0", "pi")]
    assert len(tilted) == 2
    for e in tilted:
        assert same(e["exists_when"], "k >= g*m*sin(alpha)/(6*r)")
        assert e["stability"] == "stable"
    # the printed condition, sampled on each side of k_c (m = 2, r = 0.1, g = 9.81, α = 30°)
    m, r, g, alpha = 2.0, 0.1, 9.81, math.radians(30)
    k_c = m * g * math.sin(alpha) / (6 * r)
    assert -1 <= _tilted_cosine(m, r, g, 1.01 * k_c, alpha) <= 1
    assert _tilted_cosine(m, r, g, 0.99 * k_c, alpha) > 1


def test_the_top_is_unstable_for_every_incline(tmp_path) -> None:
    (top,) = [e for e in _equilibria(tmp_path) if e["at"]["theta"] == "pi"]
    assert top["stability"] == "unstable"
    assert same(top["hessian"][0][0], "-r*(g*m*sin(alpha) + 18*k*r/5)")


# A bead on a hoop of radius R turning at Ω about the vertical, the hoop's plane tilted α
# from the vertical (a second new user's). By hand, in the turning frame, the bead at
# R (sin θ, −cos θ sin α, −cos θ cos α): V' = −m g R cos θ cos α − ½ m Ω² R² (sin²θ +
# cos²θ sin²α), so ∂V'/∂θ = m R sin θ (g cos α − Ω² R cos θ cos²α) and
#   θ = π: K = −m R cos α (g + Ω² R cos α)   (> 0 for α past π/2 and Ω² R |cos α| < g),
#   cos θ₀ = g/(Ω² R cos α): it exists only where Ω⁴ R² cos²α ≥ g², and there
#   K = m R² cos²α Ω² sin²θ₀ = m (Ω⁴ R² cos²α − g²)/Ω² ≥ 0.
TILTED_HOOP = """title: a bead on a tilted hoop turning about the vertical
parameters: {m: mass, R: radius, g: gravity, Omega: rate, alpha: tilt}
coordinates: [theta]
gravity: [0, 0, -g]
frames:
  shaft: {axis: z, rate: Omega}
points:
  P: "R*[sin(theta)*cos(Omega*t) + cos(theta)*sin(alpha)*sin(Omega*t), sin(theta)*sin(Omega*t) - cos(theta)*sin(alpha)*cos(Omega*t), -cos(theta)*cos(alpha)]"
bodies:
  bead: {shape: particle, mass: m, at: P}
questions:
  - equilibria: {frame: shaft}
"""


def _hoop(tmp_path, text: str) -> list[dict]:
    path = tmp_path / "hoop.yaml"
    path.write_text(text, encoding="utf-8")
    out = CliRunner().invoke(main, ["solve", str(path), "--format", "json"])
    assert out.exit_code == 0, out.output
    return json.loads(out.stdout)["results"][0]["answers"]["equilibria"]


def test_a_sign_that_turns_past_a_right_angle_is_not_called_unstable(tmp_path) -> None:
    """K = −m R cos α (g + Ω² R cos α) at θ = π is negative for α < π/2 but positive for
    α = 2.4, Ω = 1, R = 1, g = 9.81 (+6.69 m): no verdict "for every value" (a check by
    samples called it unstable)."""
    (top,) = [e for e in _hoop(tmp_path, TILTED_HOOP) if e["at"]["theta"] == "pi"]
    assert top["stability"] != "unstable"
    alpha, omega, R, g = 2.4, 1.0, 1.0, 9.81
    assert -R * math.cos(alpha) * (g + omega**2 * R * math.cos(alpha)) > 0


def test_an_existence_no_parameter_splits_is_said_as_it_is(tmp_path) -> None:
    """The tilted pair exists only where Ω⁴ R² cos²α − g² ≥ 0, a condition no one
    parameter splits: exists_when says that condition, not "True", and since K is that
    condition over Ω² it is stable wherever it exists."""
    tilted = [e for e in _hoop(tmp_path, TILTED_HOOP) if e["at"]["theta"] not in ("0", "pi")]
    assert len(tilted) == 2
    for e in tilted:
        assert same(e["exists_when"], "Omega**4*R**2*cos(alpha)**2 - g**2 >= 0")
        assert e["stability"] == "stable"
    # sampled on each side: cos θ₀ = g/(Ω² R cos α) is a cosine only past the boundary
    R, g, alpha = 1.0, 9.81, 0.7
    omega_c = math.sqrt(g / (R * math.cos(alpha)))
    assert abs(g / ((1.01 * omega_c) ** 2 * R * math.cos(alpha))) <= 1
    assert abs(g / ((0.99 * omega_c) ** 2 * R * math.cos(alpha))) > 1


def test_an_assumption_on_the_angle_s_side_decides_the_cosine(tmp_path) -> None:
    """Under [alpha < pi/2] the top θ = π is unstable for every Ω (cos α > 0, K < 0);
    under [alpha > pi/2] its stability depends on Ω."""
    below = _hoop(tmp_path, TILTED_HOOP.replace("coordinates:", "assumptions: [alpha < pi/2]\ncoordinates:"))
    (top,) = [e for e in below if e["at"]["theta"] == "pi"]
    assert top["stability"] == "unstable"
    above = _hoop(tmp_path, TILTED_HOOP.replace("coordinates:", "assumptions: [alpha > pi/2]\ncoordinates:"))
    (top,) = [e for e in above if e["at"]["theta"] == "pi"]
    assert top["stability"] == "depends"
    # and the modes about it: λ = −(Ω² R cos α + g) cos α/R < 0 under [alpha < pi/2] (refused before)
    text = TILTED_HOOP.replace("coordinates:", "assumptions: [alpha < pi/2]\ncoordinates:").replace(
        "  - equilibria: {frame: shaft}", "  - modes: {frame: shaft, about: {theta: pi}}")
    path = tmp_path / "modes.yaml"
    path.write_text(text, encoding="utf-8")
    out = CliRunner().invoke(main, ["solve", str(path), "--format", "json"])
    assert out.exit_code == 0, out.output
    assert json.loads(out.stdout)["results"][0]["answers"]["motions"] == ["growth"]


def test_the_modes_about_a_top_held_for_every_incline(tmp_path) -> None:
    """A rod OA (m, L) pinned at O on a plane inclined at α, θ from up the slope, its end
    held by a horizontal spring (k, zero length) of stretch L sin θ. By hand
    V = m g sin α (L/2) cos θ + ½ k L² sin²θ; at θ = π, K = k L² + m g L sin α/2 and
    M = m L²/3, so λ = 3 (2 L k + g m sin α)/(2 L m) > 0 for every α in (0, π): an
    oscillation (it was refused: "the sign … depends on the parameters")."""
    text = ROD_ON_INCLINE + "questions:\n  - modes: {about: {theta: pi}}\n"
    path = tmp_path / "rod.yaml"
    path.write_text(text, encoding="utf-8")
    out = CliRunner().invoke(main, ["solve", str(path), "--format", "json"])
    assert out.exit_code == 0, out.output
    answers = json.loads(out.stdout)["results"][0]["answers"]
    (lam,) = answers["eigenvalues"]
    assert same(lam, "3*(2*L*k + g*m*sin(alpha))/(2*L*m)")
    assert answers["motions"] == ["oscillation"]
