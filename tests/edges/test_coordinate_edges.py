"""Failure edges found on unseen problems (issue 26): singular coordinates, rounded
roots, nulls where numbers exist, a body that should turn, a silent choice, a false
"no solution", a route blocked by a parameter that does not matter.

Every expected value is derived here by hand (the derivation is in each comment) or
by an independent computation (numpy/mpmath on the formula written out by hand).
"""

from __future__ import annotations

import json

import pytest
import sympy as sp

from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.solvers import solve_problem
from rbdsolve.solvers.routes.options import Options, RouteChoice


def _report(text: str, route: RouteChoice = RouteChoice.AUTO):
    return solve_problem(build_model(load_text(text, "scene.yaml")), Options(route=route))


# --- 7. a route blocked by a parameter that does not matter ----------------------------

# A yo-yo: a disk (m, R) and an axle (m/10, radius r, length b) on one string of
# radius r, falling by y and turning by y/r. In a planar motion only J_zz counts, and
# a cylinder's J_zz about its own axis (z) is m r²/2 whatever its length b:
#   T = ½ (11m/10) ẏ² + ½ (m R²/2)(ẏ/r)² + ½ (m r²/20)(ẏ/r)² = m (10 R²/r² + 23) ẏ²/40,
# so M = m (10 R²/r² + 23)/20 = 0.2 (250 + 23)/20 = 2.73 and the force 11 m g/10 = 2.1582.
YOYO = """\
parameters: {m: mass, r: axle radius, R: disk radius, b: axle length, g: gravity}
values: {m: 0.2, r: 0.01, R: 0.05, g: 9.81}
coordinates: [y]
gravity: [0, -g]
bodies:
  disk: {shape: disk, mass: m, radius: R, at: [0, -y], angle: y/r}
  axle: {shape: cylinder, mass: m/10, radius: r, height: b, axis: z, at: [0, -y], angle: y/r}
questions: [eom]
"""


def test_a_parameter_the_answer_does_not_depend_on_is_not_asked_for() -> None:
    (solution,) = _report(YOYO, RouteChoice.NUMERIC).solutions
    assert solution.solved, solution.error
    (equation,) = solution.answers.equations
    (ydd,) = [d for d in equation.atoms(sp.Derivative) if d.derivative_count == 2]
    assert float(equation.coeff(ydd)) == pytest.approx(2.73, rel=1e-12)
    assert float(equation.subs(ydd, 0)) == pytest.approx(-2.1582, rel=1e-12)


def test_a_parameter_the_answer_depends_on_is_still_asked_for() -> None:
    (solution,) = _report(YOYO.replace("R: 0.05, ", ""), RouteChoice.NUMERIC).solutions
    assert not solution.solved
    assert "give R " in solution.error and "b" not in solution.error.split("give ")[1].split("(")[0]


# --- 4. a swinging body without `angle` ------------------------------------------------

# A rod (m, l) hung from O by its centre G = l/2 (sin θ, −cos θ), written without
# `angle`: it translates, T = ½ m (l/2)² θ̇² = m l² θ̇²/8 instead of the rod's
# m l² θ̇²/6. The answer stays what the scene says; every question on T warns.
SWING = """\
parameters: {m: mass, l: length, g: gravity}
coordinates: [theta]
gravity: [0, -g]
points:
  O: [0, 0]
  G: O + l/2*[sin(theta), -cos(theta)]
bodies:
  rod: {shape: rod, mass: m, length: l, at: G}
questions: [eom, equilibria, modes]
"""

# A slider driven by a crank: its centre moves along x with θ but not on a circle
# about any named point, so it may well just slide: the plain note, no warning.
SLIDER = """\
parameters: {m: mass, a: crank, g: gravity}
coordinates: [theta]
gravity: [0, -g]
points:
  O: [0, 0]
  A: a*[cos(theta), sin(theta)]
  B: [a*cos(theta) + 2*a, 0]
bodies:
  slider: {shape: box, mass: m, width: a, height: a, depth: a, at: B}
questions: [eom]
"""


def test_a_body_that_swings_without_an_angle_is_warned_about_on_every_question_using_T() -> None:
    report = _report(SWING)
    eom, equilibria, modes = report.solutions
    for solution in (eom, modes):
        (warning,) = solution.warnings
        assert "'rod' has no angle" in warning and "add `angle: theta`" in warning and "about O" in warning
    assert equilibria.warnings == ()  # V alone: no rotational energy involved
    l, m = sp.symbols("l m", positive=True)
    (equation,) = eom.answers.equations
    (thdd,) = [d for d in equation.atoms(sp.Derivative) if d.derivative_count == 2]
    assert sp.simplify(equation.coeff(thdd) - m * l**2 / 4) == 0  # 2 × m l²/8: the answer is unchanged


def test_a_body_that_may_just_slide_keeps_the_plain_note() -> None:
    report = _report(SLIDER)
    assert report.solutions[0].warnings == ()
    assert any("slider has no 'angle'" in str(step) for step in report.model.steps)


# --- 3. numbers wherever an entry has a value -------------------------------------------

# A cube (m, edge a) hanging from a ball joint O by G = −a e3, turned by α, β, γ about
# x, then the new y, then the new z. About G a cube is isotropic, J_G = m a²/6 · 1, in
# every orientation: R J Rᵀ = J. About O (Steiner, d_b = (0, 0, −a) in body axes)
# J_O = Q diag(7/6, 7/6, 1/6) m a² Qᵀ: moments m a²/6 once and 7 m a²/6 twice, the
# axis of the smallest along OG, (sin β, −sin α cos β, cos α cos β) — defined everywhere.
CUBE = """\
parameters: {m: mass, a: edge, g: gravity}
values: {m: 2, a: 3/10, g: 9.81}
coordinates: [alpha, beta, gamma]
gravity: [0, 0, -g]
triads:
  B: {turns: [[x, alpha], [y, beta], [z, gamma]], vectors: [e1, e2, e3]}
points:
  O: [0, 0, 0]
  G: -a*e3
bodies:
  cube: {shape: box, mass: m, width: a, height: a, depth: a, at: G, orientation: [B]}
questions:
"""


def _plain(value):
    """Coordinates, which answers write as functions of time, as plain symbols."""
    from sympy.core.function import AppliedUndef

    return value.xreplace({f: sp.Symbol(f.func.__name__) for f in value.atoms(AppliedUndef)})


def _cli(*args: str, input: str):
    from click.testing import CliRunner

    from rbdsolve.cli import main

    return CliRunner().invoke(main, list(args), input=input)


def test_a_turned_cube_has_numbers_in_json_equal_to_the_terminal() -> None:
    text = CUBE + "  - inertia: {body: cube}\n"
    (answer,) = json.loads(_cli("solve", "-", "--format", "json", input=text).stdout)["results"]
    J = m_a2 = 2 * 0.09 / 6  # m a²/6 = 0.03
    assert sum(answer["values"]["J_G"], []) == pytest.approx([J, 0, 0, 0, J, 0, 0, 0, J], abs=1e-15)
    assert answer["values"]["principal_moments"] == pytest.approx([m_a2] * 3, abs=1e-15)
    terminal = _cli("solve", "-", input=text).output
    assert "J_G = a² m [[1/6, 0, 0], [0, 1/6, 0], [0, 0, 1/6]]" in terminal
    assert "J_G = [[0.03, 0, 0], [0, 0.03, 0], [0, 0, 0.03]] kg·m²" in terminal and "—" not in terminal


def test_principal_axes_of_a_turning_tensor_are_defined_at_every_configuration() -> None:
    (solution,) = _report(CUBE + "  - inertia: {body: cube, about: O}\n").solutions
    a, m = sp.symbols("a m", positive=True)
    moments = [sp.simplify(x.subs({sp.Symbol("a", positive=True): a})) for x in solution.answers.principal_moments]
    assert [sp.simplify(x / (m * a**2)) for x in moments] == [sp.Rational(1, 6), sp.Rational(7, 6), sp.Rational(7, 6)]
    axis = _plain(sp.Matrix(solution.answers.principal_axes[0]))
    al, be = sp.symbols("alpha beta")
    assert sp.simplify(axis - sp.Matrix([sp.sin(be), -sp.sin(al) * sp.cos(be), sp.cos(al) * sp.cos(be)])) == sp.zeros(3, 1)
    for e in solution.answers.principal_axes:  # no denominators: defined where sin β = 0 or cos α = 0
        assert all(sp.fraction(sp.together(x))[1] == 1 for x in e)
    assert solution.warnings == ()


# A disk (m, R) whose centre circles O at distance e, G = e (cos θ, sin θ), while it
# turns by 2θ. About O: J = m [[R²/4 + e² sin²θ, −e² sin θ cos θ, 0], [·, R²/4 + e² cos²θ,
# 0], [0, 0, R²/2 + e²]]; its in-plane eigenvectors are along OG, (cos θ, sin θ, 0), with
# R²/4 m, and across it, (sin θ, −cos θ, 0), with (R²/4 + e²) m — at every θ, where the
# cofactor formula (1, tan θ, 0) fails at θ = π/2.
DISK = """\
parameters: {m: mass, R: radius, e: offset}
coordinates: [theta]
points:
  O: [0, 0]
bodies:
  disk: {shape: disk, mass: m, radius: R, at: "e*[cos(theta), sin(theta)]", angle: 2*theta}
questions:
  - inertia: {body: disk, about: O}
"""


def test_principal_axes_that_turn_have_no_denominator() -> None:
    (solution,) = _report(DISK).solutions
    th = sp.Symbol("theta")
    axes = [_plain(sp.Matrix(e)) for e in solution.answers.principal_axes]
    assert axes[0] == sp.Matrix([sp.cos(th), sp.sin(th), 0])
    assert axes[1] == sp.Matrix([sp.sin(th), -sp.cos(th), 0])
    assert axes[2] == sp.Matrix([0, 0, 1])


# --- 1. singular points of the coordinates; one configuration written twice ------------

# The cube on its ball joint: V = −m g·r_G = m g a cos α cos β (G = −a e3, e3 =
# (sin β, −sin α cos β, cos α cos β)). Physically an equilibrium has G straight below
# O (hanging) or above it (upside down); γ, a turn about OG, is free. ∂V/∂q = 0 also
# holds at (α, β) = (±π/2, ±π/2), where e3 is horizontal: there the turns are in
# gimbal lock (β = ±π/2 makes the x and z turns one axis), and the cube is not in
# equilibrium (gravity has a moment about O). (π, π, γ) is R_x(π) R_y(π) R_z(γ) =
# R_z(π + γ): the hanging cube again; (π, 0, γ) = R_z(π) · (0, π, γ): upside down again.
EQUILIBRIA = CUBE + "  - equilibria\n"


def _values(at) -> tuple:
    return tuple(round(float(sp.sympify(v)), 9) for v in at.values())


@pytest.mark.parametrize("route", [RouteChoice.EXACT, RouteChoice.NUMERIC])
def test_the_cube_on_a_ball_joint_lists_its_physical_equilibria_once(route) -> None:
    (solution,) = _report(EQUILIBRIA, route).solutions
    pi = round(float(sp.pi), 9)
    listed = {_values(eq.at): (eq.stability.value, {_values(e) for e in eq.equivalent})
              for eq in solution.answers.equilibria}
    assert listed == {(0.0, 0.0, 0.0): ("neutral", {(pi, pi, 0.0)}),
                      (0.0, pi, 0.0): ("unstable", {(pi, 0.0, 0.0)})}
    singular = {_values(p.at) for p in solution.answers.singular_points}
    h = round(float(sp.pi / 2), 9)
    assert singular == {(s * h, t * h, 0.0) for s in (-1, 1) for t in (-1, 1)}
    assert all(p.verdict == "not an equilibrium" for p in solution.answers.singular_points)
    assert any("singular points of the coordinates" in w for w in solution.warnings)


# A spherical pendulum, P = l (sin θ cos φ, sin θ sin φ, −cos θ): the poles θ = 0, π
# are singular points of the angles (φ does not move P there) and real equilibria
# (P straight below or above O): they stay listed, the bottom stable, the top not.
SPHERICAL = """\
parameters: {m: mass, l: length, g: gravity}
coordinates: [theta, phi]
gravity: [0, 0, -g]
points:
  P: l*[sin(theta)*cos(phi), sin(theta)*sin(phi), -cos(theta)]
bodies:
  bob: {shape: particle, mass: m, at: P}
questions: [equilibria]
"""


def test_singular_points_that_are_equilibria_stay_listed() -> None:
    (solution,) = _report(SPHERICAL, RouteChoice.EXACT).solutions
    listed = [(_values(eq.at), eq.stability.value, eq.equivalent) for eq in solution.answers.equilibria]
    assert listed == [((0.0, 0.0), "stable", ()), ((round(float(sp.pi), 9), 0.0), "unstable", ())]
    assert solution.answers.singular_points == ()


# --- 2. a rounded root; an equilibrium by its number ------------------------------------

# An inverted rod (m = 1, l = 2, g = 1) on a pivot with a torsional spring c = 3/10:
# V = ½ c θ² + m g (l/2) cos θ, equilibria θ = k sin θ with k = m g l/(2 c) = 10/3,
# V'' = c (1 − k cos θ), M = m l²/3 = 4/3 about the pivot. The nonzero roots ±θ* are
# stable; mpmath gives θ* below, and the single mode λ = V''(θ*)/M.
ROD = """\
parameters: {m: mass, l: length, g: gravity, c: stiffness}
values: {m: 1, l: 2, g: 1, c: 3/10}
coordinates: [theta]
gravity: [0, -g]
points:
  G: l/2 * [sin(theta), cos(theta)]
bodies:
  rod: {shape: rod, mass: m, length: l, at: G, angle: theta, axis: y}
springs:
  s: {stiffness: c, angle: theta}
questions:
"""


def _rod_root() -> tuple[float, float]:
    import mpmath as mp

    k, c = mp.mpf(10) / 3, mp.mpf(3) / 10
    root = mp.findroot(lambda x: x - k * mp.sin(x), 2.5)
    return float(root), float(c * (1 - k * mp.cos(root)) / (mp.mpf(4) / 3))


def test_a_root_rounded_to_six_digits_is_refined_and_said() -> None:
    root, lam = _rod_root()
    (solution,) = _report(ROD + f"  - modes: {{about: {{theta: {root:.6g}}}}}\n").solutions
    assert solution.solved, solution.error
    assert solution.answers.about["theta"] == pytest.approx(root, abs=1e-12)
    assert solution.answers.eigenvalues[0] == pytest.approx(lam, rel=1e-9)
    assert any("refined by Newton's method" in w for w in solution.warnings)


def test_a_point_far_from_every_equilibrium_is_refused_with_a_number() -> None:
    (solution,) = _report(ROD + "  - modes: {about: {theta: 2.3}}\n").solutions
    # ∂V/∂θ = c θ − (m g l/2) sin θ = 0.3 · 2.3 − sin 2.3
    expected = 0.3 * 2.3 - __import__("math").sin(2.3)
    assert not solution.solved and f"∂V/∂θ = {expected:.6g} there" in solution.error
    import re

    assert re.findall(r"∂V/∂θ = (\S+)", solution.error) == [f"{expected:.6g}"] * 2  # both routes: a number


def test_an_equilibrium_named_by_its_number() -> None:
    root, lam = _rod_root()
    equilibria, modes = _report(ROD + "  - equilibria\n  - modes: {about: {equilibrium: 3}}\n").solutions
    assert equilibria.answers.equilibria[2].at["theta"] == pytest.approx(root, abs=1e-9)  # −θ*, 0, θ*
    assert modes.answers.about["theta"] == pytest.approx(root, abs=1e-12)
    (missing,) = _report(ROD + "  - modes: {about: {equilibrium: 4}}\n").solutions
    assert "there is no equilibrium 4" in missing.error and "finds 3" in missing.error


# The hoop turning at Ω (R = 1, g = 9.81, Ω = 5): equilibria 0, ±acos(g/(R Ω²)), π
# (by hand: ∂V'/∂θ = m R sin θ (g − R Ω² cos θ)); the rounded root is taken as the
# exact one, acos(9.81/25), on the exact route.
def test_a_rounded_root_is_taken_as_the_exact_equilibrium_on_the_exact_route() -> None:
    from conftest import PROBLEMS

    text = (PROBLEMS / "frames" / "rotating-hoop-fast.yaml").read_text()
    text = text.replace("about: {theta: acos(g/(R*Omega**2))}", "about: {theta: 1.16756}")
    modes = _report(text).solutions[-1]
    assert modes.route.value == "exact"
    R, g, Om = sp.symbols("R g Omega", positive=True)
    assert _plain(sp.sympify(modes.answers.about["theta"])) == sp.acos(g / (R * Om**2))
    assert any("from equilibrium 3" in w for w in modes.warnings)


# --- 5. a choice among stable equilibria is said ----------------------------------------

def test_modes_without_about_names_the_other_stable_equilibria() -> None:
    root, _ = _rod_root()
    (modes,) = _report(ROD + "  - modes\n").solutions
    assert modes.answers.about["theta"] == pytest.approx(-root, abs=1e-12)  # the first stable one
    (note,) = [w for w in modes.warnings if "are stable" in w]
    assert "equilibrium 1" in note and f"equilibrium 3: theta = {root:.9g}" in note


# --- 6. a false "no solution"; copies of one motion --------------------------------------

# A thrown coin (a disk: J1 = m r²/4 across, J3 = m r²/2 along its axis e3), torque
# free, so L is constant (along z). Its angular velocity has magnitude ω₀ at α from
# e3. The axis precesses about L at φ̇ at the tilt β: ω = φ̇ ẑ + ψ̇ e3 has φ̇ sin β =
# ω₀ sin α across the axis and ω₀ cos α along it. L ∥ ẑ means J1 ω⊥ cos β = J3 ω₃ sin β,
# tan β = (J1/J3) tan α = tan α/2 (by hand; e.g. Goldstein ch. 5.6), and then
# φ̇ = ω₀ sin α/sin β = ω₀ √(4 − 3 sin²α).
COIN = """\
parameters: {m: mass, r: radius, omega0: angular speed, alpha: angle of omega from the axis}
unknowns: [beta]
triads:
  T: {turns: [["z", "omega0*sin(alpha)/sin(beta)*t"], [x, beta]], vectors: [e1, e2, e3]}
points:
  O: [0, 0, 0]
bodies:
  coin: {shape: disk, mass: m, radius: r, at: O, orientation: [T, [z, "(omega0*cos(alpha) - omega0*sin(alpha)*cos(beta)/sin(beta))*t"]]}
questions:
  - steady_motion: {about: O, solve_for: beta}
"""


def test_the_coin_s_precession_is_solved_exactly_once() -> None:
    (solution,) = _report(COIN, RouteChoice.EXACT).solutions
    assert solution.solved, solution.error
    (beta,) = solution.answers.solved.values()
    alpha = sp.Symbol("alpha", positive=True)
    beta = beta.xreplace({s: alpha for s in beta.free_symbols if s.name == "alpha"})
    for a in (0.2, 0.5, 1.0, 1.4):  # tan β = tan α/2, with the axis on L's side (cos β > 0)
        b = float(beta.subs(alpha, a))
        assert b == pytest.approx(__import__("math").atan(__import__("math").tan(a) / 2), abs=1e-14)
    # φ̇ = ω₀ sin α / sin β = ω₀ √(4 − 3 sin²α)
    phidot = sp.sin(alpha) / sp.sin(beta)
    assert float(phidot.subs(alpha, 0.5)) == pytest.approx(__import__("math").sqrt(4 - 3 * __import__("math").sin(0.5) ** 2))


def test_the_numeric_route_lists_the_coin_s_motion_once_in_one_turn() -> None:
    import math

    (solution,) = _report(COIN + "values: {m: 1, r: 1, omega0: 3, alpha: 1/2}\n", RouteChoice.NUMERIC).solutions
    assert solution.solved, solution.error
    (only,) = solution.answers.solutions
    assert only.unknowns["beta"] == pytest.approx(math.atan(math.tan(0.5) / 2), abs=1e-12)


def test_an_open_quantity_is_not_called_no_solution() -> None:
    # φ̇ and β both unknown but only L ∥ ẑ to hold them: a family, not "no solution"
    text = COIN.replace("unknowns: [beta]", "unknowns: [phidot, beta]").replace(
        '"omega0*sin(alpha)/sin(beta)*t"', "phidot*t").replace(
        '"(omega0*cos(alpha) - omega0*sin(alpha)*cos(beta)/sin(beta))*t"', '"(omega0*cos(alpha) - phidot*cos(beta))*t"'
    ).replace("solve_for: beta", "solve_for: [phidot, beta]")
    (solution,) = _report(text, RouteChoice.EXACT).solutions
    assert "leave some of them open" in solution.error and "no real solution" not in solution.error
