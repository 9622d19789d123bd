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

from conftest import same

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
