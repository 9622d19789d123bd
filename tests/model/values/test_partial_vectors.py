"""A vector answer with one parameter left open is written with the numbers in, as a
scalar one is: a new user's hanging rod struck by a ball at a depth b left open printed
θ̇_f and the energies as functions of b, but not the ball's velocity after, the struck
point's, nor the pivot's impulse.

By hand (impulse–momentum, the rod M, l pivoted at O, the ball m at v₀ (cos 30°,
−sin 30°) striking B at depth b along x, restitution e): J_O ω = P b, m (u_x − v₀ cos
30°) = −P, b ω − u_x = e v₀ cos 30°, with J_O = M l²/3; the pivot's impulse is M (l/2) ω
− P along x. At M = 1.5 kg, l = 0.9 m, m = 0.2 kg, v₀ = 4 m/s, e = 0.6, each entry is
checked at b = 0.3 m and 0.6 m against that solution (solved here by numpy)."""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp

from conftest import solved_scene

ROD = """\
parameters: [M, l, m, v0, e, b]
values: {M: 1.5 kg, l: 90 cm, m: 0.2 kg, v0: 4 m/s, e: 0.6}
coordinates: [theta]
points:
  O: [0, 0]
  G: l/2*[sin(theta), -cos(theta)]
  B: b*[sin(theta), -cos(theta)]
bodies:
  rod: {shape: rod, mass: M, length: l, at: G, angle: theta, axis: y}
questions:
  - impact:
      at: {theta: 0}
      collisions:
        B: {normal: x, restitution: e, particle: {mass: m, velocity: "v0*[cos(pi/6), -sin(pi/6)]"}}
"""


def _by_hand(b: float) -> dict[str, tuple[float, float, float]]:
    M, length, m, v0, e = 1.5, 0.9, 0.2, 4.0, 0.6
    U = v0 * np.cos(np.pi / 6)
    # unknowns ω, u_x, P
    A = np.array([[M * length**2 / 3, 0.0, -b], [0.0, m, 1.0], [b, -1.0, 0.0]])
    w, ux, P = np.linalg.solve(A, [0.0, m * U, e * U])
    return {"u_B": (ux, -v0 / 2, 0.0), "v_B": (b * w, 0.0, 0.0), "P_supports": (M * length / 2 * w - P, 0.0, 0.0)}


def _line(solution, name: str):
    (line,) = [x for x in solution.solution.numbers if str(x.relation.lhs) == name]
    return line


@pytest.fixture(scope="module")
def solution(tmp_path_factory):
    return solved_scene(tmp_path_factory.mktemp("rod"), ROD, "rod.yaml")


@pytest.mark.parametrize("name", ["u_B", "v_B", "P_supports"])
@pytest.mark.parametrize("depth", [0.3, 0.6])
def test_each_entry_is_the_hand_value_at_sampled_depths(solution, name: str, depth: float) -> None:
    line = _line(solution, name)
    (b,) = set().union(*(x.free_symbols for x in line.relation.rhs))
    found = [float(x.subs(b, depth)) for x in line.relation.rhs]
    assert found == pytest.approx(_by_hand(depth)[name], abs=1e-9)
    assert line.unit == ("N·s" if name == "P_supports" else "m/s")
    assert isinstance(line.relation.rhs, sp.MatrixBase)
