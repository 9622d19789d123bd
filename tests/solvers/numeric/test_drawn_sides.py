"""The numeric route on a V compiled from the symbolic model keeps a spring on the side
it is drawn on, as the exact route does (model/energies/spring_length.py
``held_sides``). Found by the oracle (seed 2033, scene 36): a bead on a rod turning at
Ω, held by a spring of natural length a from the axis, its length |a + x| written a + x.
In the rod's frame V' = ½ k x² − ½ m Ω² (a + x)², so ∂V'/∂x = 0 at
x* = m Ω² a/(k − m Ω²), where a + x* = k a/(k − m Ω²) (by hand). With m Ω² > k that is
negative: the bead past the axis, where V' is not the spring's; on the other side,
|a + x| = −(a + x), ∂V/∂x = k (x + 2a) − m Ω² (a + x) = 0 gives x = (m Ω² − 2k) a/
(k − m Ω²), where a + x = −k a/(k − m Ω²) > 0: no root there either. No equilibrium,
where the numeric route gave x* = −0.5 and an unstable mode about it."""

from __future__ import annotations

import pytest

from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.solvers import Options, RouteChoice, solve_problem

BEAD = """
parameters: {m: mass, k: stiffness, a: natural length, Omega: rate}
values: {m: 5 kg, k: 50, a: 30 cm, Omega: OMEGA}
coordinates: [x]
frames:
  rod: {axis: z, rate: Omega}
points:
  P: (a + x)*[cos(Omega*t), sin(Omega*t), 0]
bodies:
  bead: {shape: particle, mass: m, at: P}
springs:
  s: {stiffness: k, between: [P, "[0, 0, 0]"], natural_length: a}
questions:
  - equilibria: {frame: rod}
  - modes: {frame: rod, about: each}
"""


def _solved(omega: str, route: RouteChoice):
    model = build_model(load_text(BEAD.replace("OMEGA", omega), "bead.yaml"))
    return solve_problem(model, Options(route=route)).solutions


@pytest.mark.parametrize("route", [RouteChoice.AUTO, RouteChoice.NUMERIC])
def test_past_the_critical_rate_no_equilibrium_is_given(route) -> None:
    """m Ω² = 125 > k = 50: neither route lists one, and the modes refuse."""
    equilibria, modes = _solved("5 rad/s", route)
    assert modes.error is not None and "no equilibrium" in modes.error
    if route is RouteChoice.NUMERIC:
        assert equilibria.error is not None
        assert "x = -0.5 solves ∂V/∂q = 0 only with spring 's' past zero length" in equilibria.error
    else:
        assert equilibria.error is None and not equilibria.answers.equilibria


def test_below_it_the_numeric_route_finds_the_hand_equilibrium() -> None:
    """m Ω² = 20 < k = 50: x* = 20 · 0.3/30 = 0.2, λ = (k − m Ω²)/m = 6 (by hand)."""
    equilibria, modes = _solved("2 rad/s", RouteChoice.NUMERIC)
    (found,) = equilibria.answers.equilibria
    assert found.at["x"] == pytest.approx(0.2, abs=1e-12)
    (about,) = modes.answers.modes
    assert about.eigenvalues[0] == pytest.approx(6.0, rel=1e-12)
