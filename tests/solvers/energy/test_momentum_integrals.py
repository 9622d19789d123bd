"""The energy question with cyclic coordinates: their momenta constant, with the energy
integral they fix the one rate left (solvers/lagrange/momentum_integrals.py). Expected
values are derived by hand in the docstrings, or by integrating Lagrange's equations
(written here from T and V by hand) with scipy."""

from __future__ import annotations

import json
import math

import numpy as np
from click.testing import CliRunner
from scipy.integrate import solve_ivp

from rbdsolve.cli import main

from conftest import PROBLEMS, same

CART = (PROBLEMS / "forces" / "pendulum-on-sliding-cart.yaml").read_text(encoding="utf-8").split("questions:")[0]

TURNTABLE = """title: a bead slides out along a rod on a turntable free to turn
parameters: {M: mass of the table, R: radius of the table, m: mass of the bead, a: start, omega0: start rate}
coordinates: [r, phi]
bodies:
  table: {shape: disk, mass: M, radius: R, angle: phi, at: [0, 0]}
  bead: {shape: particle, mass: m, at: [r*cos(phi), r*sin(phi)]}
questions:
  - energy: {at: {r: a, phi: 0, dot(r): 0, dot(phi): omega0}, to: {r: 2*a, phi: 0}, points: [bead]}
"""

TRACK = """title: a cylinder rolls in the track of a cart on a smooth floor
parameters: {M: mass of the cart, R: track, m: mass of the cylinder, r: radius, theta0: start, g: gravity}
values: {M: 3, R: 0.5, m: 2, r: 0.1, theta0: pi/3, g: 9.81}
coordinates: [x, theta]
gravity: [0, -g]
points:
  O: [x, R]
bodies:
  cart: {mass: M, inertia: M*R**2, at: O}
  cylinder: {shape: cylinder, mass: m, radius: r, height: r}
contacts:
  C: {body: cylinder, rolls_on: {body: cart, radius: R, side: inside}, along: theta}
questions:
  - energy: {from_rest: {x: 0, theta: theta0}, to: {x: 0, theta: 0}, points: [cylinder, cart]}
"""


def _result(tmp_path, text: str, *more: str) -> dict:
    path = tmp_path / "p.yaml"
    path.write_text(text, encoding="utf-8")
    out = CliRunner().invoke(main, ["solve", str(path), "--format", "json", *more])
    assert out.exit_code == 0, out.output
    (result,) = json.loads(out.stdout)["results"]
    return result


def _cart_at_the_bottom(v0: float) -> tuple[float, float]:
    """ẋ and θ̇ of the cart (M = 2) and bob (m = 1, l = 0.5) as θ first reaches 0, released
    at θ₀ = 40° with ẋ = v0: Lagrange's equations by hand, T = ½ (M + m) ẋ² + m l cos θ ẋ θ̇
    + ½ m l² θ̇², V = −m g l cos θ, so (M + m) ẍ + m l (cos θ θ̈ − sin θ θ̇²) = 0 and
    l θ̈ + cos θ ẍ + g sin θ = 0, integrated by solve_ivp to the event θ = 0."""
    M, m, l, g = 2.0, 1.0, 0.5, 9.81

    def rates(_, y):
        _, th, xd, thd = y
        A = np.array([[M + m, m * l * math.cos(th)], [math.cos(th), l]])
        b = np.array([m * l * math.sin(th) * thd**2, -g * math.sin(th)])
        xdd, thdd = np.linalg.solve(A, b)
        return [xd, thd, xdd, thdd]

    bottom = lambda _, y: y[1]  # noqa: E731
    bottom.terminal = True
    run = solve_ivp(rates, (0, 5), [0, math.radians(40), v0, 0], events=bottom, rtol=1e-12, atol=1e-12)
    _, _, xd, thd = run.y_events[0][0]
    return xd, thd


def test_a_turntable_keeps_its_angular_momentum(tmp_path) -> None:
    """J = M R²/2, T = ½ (J + m r²) φ̇² + ½ m ṙ²: φ is cyclic, p_φ = (J + m r²) φ̇ =
    (J + m a²) ω₀ (not 0: the rates at 'to' hold it as well as the energy's root).
    T constant: m ṙ² = (J + m a²) ω₀² − (J + m a²)² ω₀²/(J + m r²), so at r = 2a
    ṙ² = 3 a² ω₀² (J + m a²)/(J + 4 m a²), φ̇ = ω₀ (J + m a²)/(J + 4 m a²), and the bead's
    v² = ṙ² + 4 a² φ̇²."""
    got = _result(tmp_path, TURNTABLE)["answers"]
    J = "(M*R**2/2)"
    assert same(got["momenta"]["phi"], f"omega0*({J} + m*a**2)")
    rr = f"3*a**2*omega0**2*({J} + m*a**2)/({J} + 4*m*a**2)"
    phid = f"omega0*({J} + m*a**2)/({J} + 4*m*a**2)"
    assert same(got["there"]["rate_squared"]["r"], rr)
    assert same(got["there"]["rate"]["phi"], phid)
    assert same(got["there"]["speed"]["bead"], f"sqrt({rr} + 4*a**2*({phid})**2)")


def test_a_pendulum_on_a_cart_against_a_simulation(tmp_path) -> None:
    """Lagrange's equations of the cart and bob by hand, T = ½ (M + m) ẋ² + m l cos θ ẋ θ̇
    + ½ m l² θ̇², V = −m g l cos θ:
        (M + m) ẍ + m l (cos θ θ̈ − sin θ θ̇²) = 0,   l θ̈ + cos θ ẍ + g sin θ = 0,
    integrated from rest at θ₀ = 40° until θ = 0: the rates there agree with the
    numeric route's to 1e-8."""
    l = 0.5
    xd, thd = _cart_at_the_bottom(0.0)
    got = _result(tmp_path, CART + "questions:\n  - energy: {from_rest: {x: 0, theta: theta0}, to: {x: 0, theta: 0}, "
                                   "points: [B]}\n", "--route", "numeric")["answers"]
    assert abs(got["rate"]["theta"] - abs(thd)) < 1e-8
    # |θ̇| is given; ẋ is the motion's own there, θ falling from θ₀ to 0 (θ̇ < 0, ẋ > 0)
    assert thd < 0 < xd and abs(got["rate"]["x"] - xd) < 1e-8
    assert abs(got["speed"]["B"] - abs(xd + l * thd)) < 1e-8  # at θ = 0 the bob moves along x only


def test_a_contact_with_several_coordinates_is_said_unfollowed(tmp_path) -> None:
    """The cylinder in the sliding cart's track: the rates come (θ̇ at the bottom,
    4 g (M + m)(1 − cos θ₀)/((3 M + m)(R − r)) by the same reduction), with a warning
    that its push on the way was not followed."""
    result = _result(tmp_path, TRACK)
    assert same(result["answers"]["there"]["rate_squared"]["theta"], "4*g*(M + m)*(1 - cos(theta0))/((3*M + m)*(R - r))")
    assert any("not followed" in w for w in result["warnings"])


def test_two_coordinates_neither_cyclic_are_still_refused(tmp_path) -> None:
    """A cart on a spring to a wall holds x in V: nothing is cyclic, no rate is fixed."""
    text = CART.replace("parameters:", "parameters:\n  k: stiffness").replace(
        "bodies:", "springs:\n  wall: {between: [[0, 0], A], stiffness: k}\nbodies:")
    path = tmp_path / "p.yaml"
    path.write_text(text + "questions:\n  - energy: {from_rest: {x: 0, theta: theta0}, to: {x: 0, theta: 0}}\n",
                    encoding="utf-8")
    out = CliRunner().invoke(main, ["solve", str(path), "--format", "json"])
    assert out.exit_code == 1 and "no coordinate is cyclic (L holds each of x, theta)" in out.output


def test_a_cart_pushed_as_its_pendulum_is_released_against_a_simulation(tmp_path) -> None:
    """The same cart given ẋ = v₀ = 1.5 m/s at release: p_x = (M + m) v₀ ≠ 0, so the way
    θ passes 0 matters. Swinging down from θ₀ = 40°, θ̇ < 0 there and ẋ = v₀ + m l |θ̇|/(M
    + m); the bob's speed is |ẋ + l θ̇|. Against the simulation to 1e-8 (they were those
    of θ̇ > 0: ẋ = 0.88152, v_B = 2.73696, where the motion gives 2.11848 and 0.26304)."""
    l = 0.5
    xd, thd = _cart_at_the_bottom(1.5)
    text = CART.replace("parameters:", "parameters:\n  v0: push").replace("values: {", "values: {v0: 1.5 m/s, ")
    got = _result(tmp_path, text + "questions:\n  - energy: {at: {x: 0, theta: theta0, dot(x): v0, dot(theta): 0}, "
                                    "to: {x: 0, theta: 0}, points: [A, B]}\n")["values"]["there"]
    assert abs(got["rate"]["x"] - xd) < 1e-8
    assert abs(got["speed"]["A"] - abs(xd)) < 1e-8 and abs(got["speed"]["B"] - abs(xd + l * thd)) < 1e-8
