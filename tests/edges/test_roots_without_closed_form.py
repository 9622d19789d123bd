"""A polynomial system whose roots sympy cannot write in radicals (found in issue 19's
work): a double pendulum (two particles m on light rods l) in a vertical plane turning
at Ω about the vertical through its pivot. Its equilibrium equations reduce to an
irreducible sextic in cos θ₂, and sympy's ``solve`` silently returned the four
"hanging or upside-down" configurations only. The exact route must refuse rather than
list four of twelve; the modes about the hanging position name both critical rates.

By hand (seen from the plane, the Coriolis force is normal to it and taken by it):
V' = −m g l (2 cos θ₁ + cos θ₂) − ½ m Ω² l² (sin² θ₁ + (sin θ₁ + sin θ₂)²),
∂V'/∂θ₁ = m l (2 g sin θ₁ − Ω² l cos θ₁ (2 sin θ₁ + sin θ₂)),
∂V'/∂θ₂ = m l (g sin θ₂ − Ω² l cos θ₂ (sin θ₁ + sin θ₂)).
At θ = 0: K = m l [[2(g − lΩ²), −lΩ²], [−lΩ², g − lΩ²]], M = m l² [[2, 1], [1, 1]];
det(K − λM) = 0 gives λ = (2 ∓ √2) g/l − Ω², so the modes turn into growths at
Ω² = (2 − √2) g/l and (2 + √2) g/l.
"""

from __future__ import annotations

import math
import random

import pytest
import scipy.optimize as so
import sympy as sp

from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.solvers import solve_file, solve_problem
from rbdsolve.solvers.routes.options import Options, RouteChoice

SCENE = """\
parameters: {m: mass, l: length, g: gravity, Omega: rate of turning}
coordinates: [theta1, theta2]
gravity: [0, -g, 0]
frames:
  plane: {axis: y, rate: Omega}
points:
  A: l * [sin(theta1)*cos(Omega*t), -cos(theta1), -sin(theta1)*sin(Omega*t)]
  B: A + l * [sin(theta2)*cos(Omega*t), -cos(theta2), -sin(theta2)*sin(Omega*t)]
bodies:
  a: {shape: particle, mass: m, at: A}
  b: {shape: particle, mass: m, at: B}
questions:
"""


def _gradient(x, W, g=1.0, l=1.0):
    t1, t2 = x
    return [2 * g * math.sin(t1) - W**2 * l * math.cos(t1) * (2 * math.sin(t1) + math.sin(t2)),
            g * math.sin(t2) - W**2 * l * math.cos(t2) * (math.sin(t1) + math.sin(t2))]


def test_there_are_equilibria_off_the_axis() -> None:
    """The premise, by hand: at Ω = 2 (g = l = 1) the pendulum has an equilibrium with
    both particles out of the axis, so four is not the list."""
    root = so.fsolve(_gradient, [1.4, 1.4], args=(2.0,), xtol=1e-12)
    assert max(abs(v) for v in _gradient(root, 2.0)) < 1e-12
    assert abs(math.sin(root[0])) > 0.5 and abs(math.sin(root[1])) > 0.5


@pytest.mark.parametrize("values", ["", "values: {m: 1, l: 1, g: 1, Omega: 2}\n"])
def test_the_exact_route_never_gives_its_part_as_the_list(values) -> None:
    """The system couples both angles with degree 2 in each equation (Bézout number 16):
    the exact route does not start the Gröbner basis; it lists the evident roots, where
    sin θ₁ = sin θ₂ = 0 makes every term vanish (by hand, the four hanging or upside-down
    configurations), and says that other equilibria may exist."""
    text = SCENE + "  - equilibria: {frame: plane}\n" + values
    (solution,) = solve_file(load_text(text, "double.yaml"), Options(route=RouteChoice.EXACT)).solutions
    assert solution.solved, solution.error
    found = {(sp.sympify(e.at["theta1"]), sp.sympify(e.at["theta2"])) for e in solution.answers.equilibria}
    assert found == {(a, b) for a in (0, sp.pi) for b in (0, sp.pi)}
    assert any("Bézout number of 16" in w and "other equilibria may exist" in w.lower() for w in solution.warnings)


def test_auto_gives_every_equilibrium_numerically() -> None:
    text = SCENE + "  - equilibria: {frame: plane}\nvalues: {m: 1, l: 1, g: 1, Omega: 2}\n"
    (solution,) = solve_problem(build_model(load_text(text, "double.yaml"))).solutions
    assert solution.solved and solution.route.value == "numeric", solution.error
    found = solution.answers.equilibria
    want = _every_root(2.0)
    assert len(want) == 12  # the premise: 4 on the axis, 8 off it
    assert len(found) == len(want)
    for eq in found:
        x = [eq.at["theta1"], eq.at["theta2"]]
        assert max(abs(v) for v in _gradient(x, 2.0)) < 1e-9
        (match,) = [r for r in want if max(abs(_wrap(a - b)) for a, b in zip(x, r)) < 1e-7]
        assert eq.stability.value == _stability(match, 2.0), (x, eq.stability)


def _wrap(x: float) -> float:
    return (x + math.pi) % (2 * math.pi) - math.pi


def _every_root(W: float) -> list[list[float]]:
    """Every zero of the gradient in one turn of each angle: fsolve from a 25 × 25 grid
    (finer than needed: the basins are wide), each root polished, kept once mod 2π."""
    roots: list[list[float]] = []
    for a in range(25):
        for b in range(25):
            start = [-math.pi + 2 * math.pi * a / 25, -math.pi + 2 * math.pi * b / 25]
            r, _, ier, _ = so.fsolve(_gradient, start, args=(W,), xtol=1e-13, full_output=True)
            if ier != 1 or max(abs(v) for v in _gradient(r, W)) > 1e-10:
                continue
            r = [_wrap(r[0]), _wrap(r[1])]
            if not any(max(abs(_wrap(x - y)) for x, y in zip(r, s)) < 1e-7 for s in roots):
                roots.append(r)
    return roots


def _stability(x: list[float], W: float, h: float = 1e-6) -> str:
    """From the Hessian of V'/(m l) by central differences of the gradient by hand."""
    import numpy as np

    H = np.array([[(_gradient([x[0] + h * (j == 0), x[1] + h * (j == 1)], W)[i]
                    - _gradient([x[0] - h * (j == 0), x[1] - h * (j == 1)], W)[i]) / (2 * h) for j in range(2)]
                  for i in range(2)])
    eig = np.linalg.eigvalsh((H + H.T) / 2)
    assert min(abs(eig)) > 1e-4  # no root of this scene is degenerate
    return "stable" if min(eig) > 0 else "unstable"


def test_the_modes_name_both_critical_rates_in_order() -> None:
    text = SCENE + "  - modes: {frame: plane, about: {theta1: 0, theta2: 0}}\n"
    (solution,) = solve_problem(build_model(load_text(text, "double.yaml"))).solutions
    assert solution.solved, solution.error
    g, l = sp.symbols("g l", positive=True)
    got = sorted((sp.sympify(c.value) ** 2 for c in solution.answers.critical), key=lambda v: float(v.subs({g: 1, l: 1})))
    want = [(2 - sp.sqrt(2)) * g / l, (2 + sp.sqrt(2)) * g / l]
    assert all(sp.simplify(a - b) == 0 for a, b in zip(got, want)) and len(got) == 2
    text_steps = " ".join(str(r) for step in solution.steps for r in step.math)
    assert "Omega_c1" in text_steps and "Omega_c2" in text_steps
    # each mode's printed case holds at sampled rates on each side (λ by hand above)
    rng = random.Random(5)
    for k, cases in enumerate(solution.answers.cases):
        for _ in range(20):
            v = {g: rng.uniform(1, 20), l: rng.uniform(0.1, 3)}
            W = sp.Symbol("Omega", positive=True)
            v[W] = rng.uniform(0.01, 3) * math.sqrt(v[g] / v[l])
            lams = sorted([(2 - math.sqrt(2)) * v[g] / v[l] - v[W] ** 2, (2 + math.sqrt(2)) * v[g] / v[l] - v[W] ** 2])
            (case,) = [c for c in cases if bool(c.when.subs(v))]
            assert case.kind.value == ("oscillation" if lams[k] > 0 else "growth")
