"""With every value given, eigenvalues whose closed form in the parameters runs past
READABLE_OPS are solved at the values, exactly (a new user's rod and disk pendulums
coupled by a spring: 40 lines of radicals per eigenvalue, 8 s). Expected values by hand.

By hand: the rod (m, l) hangs from O₁, its point P at depth h; the disk (M, R) hangs
from O₂ = (D, 0) by its rim, its centre C at R below; the spring k joins P and C with
its natural length L₀ = √(D² + (h − R)²), the distance at rest. About θ₁ = θ₂ = 0,
M = diag(m l²/3, 3/2 M R²), and the spring adds k (D/L₀)² [[h², −h R], [−h R, R²]]
(its stretch to first order is (D/L₀)(h θ₁ − R θ₂)) to gravity's diag(m g l/2, M g R).
"""

from __future__ import annotations

import json

import sympy as sp
from click.testing import CliRunner

from rbdsolve.cli import main

COUPLED = """title: a rod and a disk pendulum coupled by a spring
parameters: {m: rod, l: length, M: disk, R: radius, D: pins apart, h: depth, k: stiffness, g: gravity}
values: {m: 1 kg, l: 80 cm, M: 2 kg, R: 20 cm, D: 60 cm, h: 50 cm, k: 30 N/m, g: 9.81 m/s^2}
coordinates: [theta1, theta2]
gravity: [0, -g]
points:
  O2: [D, 0]
  G1: l/2*[sin(theta1), -cos(theta1)]
  P: h*[sin(theta1), -cos(theta1)]
  C: O2 + R*[sin(theta2), -cos(theta2)]
bodies:
  rod: {shape: rod, mass: m, length: l, at: G1, angle: theta1, axis: y}
  disk: {shape: disk, mass: M, radius: R, at: C, angle: theta2}
springs:
  s: {stiffness: k, between: [P, C], natural_length: sqrt(D**2 + (h - R)**2)}
questions:
  - modes: {about: {theta1: 0, theta2: 0}}
"""


def test_long_eigenvalues_are_solved_at_the_values(tmp_path) -> None:
    m, l, M, R, D, h, k, g = (sp.Rational(x) for x in ("1", "4/5", "2", "1/5", "3/5", "1/2", "30", "981/100"))
    c = k * D**2 / (D**2 + (h - R) ** 2)
    K = sp.Matrix([[m * g * l / 2 + c * h**2, -c * h * R], [-c * h * R, M * g * R + c * R**2]])
    Mq = sp.diag(m * l**2 / 3, sp.Rational(3, 2) * M * R**2)
    lam = sp.Symbol("lam")
    want = sorted(sp.solve((K - lam * Mq).det(), lam), key=lambda x: float(x))
    path = tmp_path / "p.yaml"
    path.write_text(COUPLED, encoding="utf-8")
    out = CliRunner().invoke(main, ["solve", str(path), "--format", "json"])
    assert out.exit_code == 0, out.output
    result = json.loads(out.stdout)["results"][0]
    got = [sp.sympify(x) for x in result["answers"]["eigenvalues"]]
    assert [sp.simplify(a - b) for a, b in zip(got, want)] == [0, 0]
    assert any("solved at the values" in step["text"] for step in result["steps"])
