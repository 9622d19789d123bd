"""The energy question's rate at ``to`` is the motion's only while every contact pushes
on the way there: past the place where a push reaches zero the body leaves the surface,
and the constrained energy integral is not its motion (solvers/reactions/on_the_way.py).
Each place is derived by hand in the test's docstring."""

from __future__ import annotations

import json
import math

import pytest
import sympy as sp
from click.testing import CliRunner

from rbdsolve.cli import main

from conftest import counted_calls

DISK_ON_DRUM = """title: a disk rolling off a drum
parameters: {m: mass, r: radius, R: drum radius, g: acceleration of gravity}
values: {m: 2, r: 0.1, R: 0.5, g: 9.81}
coordinates: [theta]
gravity: [0, -g]
bodies:
  disk: {shape: disk, mass: m, radius: r}
contacts:
  C: {body: disk, rolls_on: {circle: {centre: [0, 0], radius: R, side: outside}}, along: theta}
questions:
  - energy: {from_rest: {theta: pi/36}, to: {theta: TO}}
"""

RING_IN_LOOP = """title: a ring rolling round the inside of a loop
parameters: {m: mass, r: radius, R: track radius, g: acceleration of gravity, w0: rate at the bottom}
values: {m: 1, r: 0.1, R: 1.0, g: 9.81, w0: W0}
coordinates: [theta]
gravity: [0, -g]
bodies:
  ring: {shape: ring, mass: m, radius: r}
contacts:
  C: {body: ring, rolls_on: {circle: {centre: [0, 0], radius: R, side: inside}}, along: theta}
questions:
  - energy: {at: {theta: 0, dot(theta): w0}, to: {theta: 5*pi/6}}
"""


def _result(tmp_path, text: str, route: str = "exact") -> dict:
    path = tmp_path / "p.yaml"
    path.write_text(text, encoding="utf-8")
    out = CliRunner().invoke(main, ["solve", str(path), "--format", "json", "--route", route])
    assert out.exit_code == 0, out.output
    (result,) = json.loads(out.stdout)["results"]
    return result


def _place(warning: str) -> float:
    return float(warning.split("θ = ")[1].split(",")[0])


def test_a_disk_leaving_a_drum_on_the_way(tmp_path) -> None:
    """Rolling on the drum's outside, the centre on a circle of radius R + r: T = ¾ m
    (R + r)² θ̇², V = m g (R + r) cos θ, so θ̇² = 4 g (cos θ₀ − cos θ)/(3 (R + r)); the
    normal balance m (R + r) θ̇² = m g cos θ − N gives N = m g (7 cos θ − 4 cos θ₀)/3, zero
    at cos θ = 4 cos θ₀/7: θ = 0.965198 for θ₀ = 5°. Asked at 70° (past it) on both
    routes: a warning there; at 50° (before it): none."""
    lost = math.acos(4 / 7 * math.cos(math.pi / 36))
    for route in ("exact", "numeric"):
        (warning,) = _result(tmp_path, DISK_ON_DRUM.replace("TO", "7*pi/18"), route)["warnings"]
        assert abs(_place(warning) - lost) < 1e-5 and "N_C = 0" in warning
        assert "not the motion's" in warning
    assert _result(tmp_path, DISK_ON_DRUM.replace("TO", "5*pi/18"))["warnings"] == []


def test_the_disk_leaves_the_drum_whatever_its_mass_left_open(tmp_path) -> None:
    """The same disk with m left open (a new user's sheet: m cancels from every answer),
    exact route: N = m g (7 cos θ − 4 cos θ₀)/3 vanishes where it did, and the rate at 70°
    was printed with no warning, since a value was missing."""
    open_mass = DISK_ON_DRUM.replace("values: {m: 2, ", "values: {")
    (warning,) = _result(tmp_path, open_mass.replace("TO", "7*pi/18"))["warnings"]
    assert abs(_place(warning) - math.acos(4 / 7 * math.cos(math.pi / 36))) < 1e-5 and "N_C = 0" in warning
    assert _result(tmp_path, open_mass.replace("TO", "5*pi/18"))["warnings"] == []


def test_a_ring_falling_off_the_top_of_a_loop(tmp_path) -> None:
    """Inside the track, ρ = R − r: T = m ρ² θ̇² (a ring: ½ m v² + ½ m r² ω², v = r ω),
    V = −m g ρ cos θ, so ρ θ̇² = ρ w₀² − g (1 − cos θ); along the radius N − m g cos θ =
    m ρ θ̇², N = m (ρ w₀² − g + 2 g cos θ): zero at cos θ = (g − ρ w₀²)/(2 g). With
    ρ w₀² = 2 g (w₀ = 4.669047) that is cos θ = −1/2, θ = 2π/3, before 5π/6; with w₀ = 6,
    ρ w₀² = 32.4 > 3 g, N > 0 all round: no warning."""
    (warning,) = _result(tmp_path, RING_IN_LOOP.replace("W0", "4.669047"))["warnings"]
    assert abs(_place(warning) - 2 * math.pi / 3) < 1e-4
    assert _result(tmp_path, RING_IN_LOOP.replace("W0", "6"))["warnings"] == []


def test_reactions_and_the_energy_on_the_way_solve_the_balances_once(tmp_path, monkeypatch) -> None:
    """Asked together, the reactions from rest and the energy's check on the way follow
    one push: N = m g (7 cos θ − 4 cos θ₀)/3 by hand (above), which the reactions give
    along the motion, and the balances for N and F are solved once, the general q̈ found
    once (a rocking cylinder segment spent 2 s of its energy question doing both again)."""
    from rbdsolve.solvers.lagrange import accelerations as accelerations_module
    from rbdsolve.solvers.reactions import balances

    rows = counted_calls(monkeypatch, balances, "_independent_rows")
    solved = counted_calls(monkeypatch, accelerations_module, "_det")
    text = DISK_ON_DRUM.replace("  - energy: {from_rest: {theta: pi/36}, to: {theta: TO}}",
                                "  - reactions: {forces: [C], from_rest: {theta: pi/36}}\n"
                                "  - energy: {from_rest: {theta: pi/36}, to: {theta: 5*pi/18}}")
    path = tmp_path / "p.yaml"
    path.write_text(text, encoding="utf-8")
    out = CliRunner().invoke(main, ["solve", str(path), "--format", "json"])
    assert out.exit_code == 0, out.output
    reactions, energy = json.loads(out.stdout)["results"]
    assert len(rows) == 1
    assert len(solved) == 2  # det M and Cramer's numerator det M₁ (M with −h), for q̈ = −M⁻¹ h
    theta0 = math.pi / 36
    assert reactions["values"]["first_zero"]["N_C"]["lost_at"]["theta"] == pytest.approx(
        math.acos(4 * math.cos(theta0) / 7), rel=1e-9)
    g, m, t = sp.symbols("g m t", positive=True)
    N = sp.sympify(reactions["answers"]["along"]["C"]["N_C"], locals={"g": g, "m": m, "t": t})
    theta = sp.Function("theta")(t)
    assert sp.simplify(N - g * m * (7 * sp.cos(theta) - 4 * sp.cos(sp.pi / 36)) / 3) == 0
    assert not energy["warnings"]  # 50° is before the place where N = 0 (θ = 0.965198)
