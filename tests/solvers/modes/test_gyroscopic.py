"""Small oscillations with gyroscopic terms (solvers/modes/gyroscopic.py, routh.py):
expected values by hand, conditions sampled on both sides, the numeric route against
the exact one, and the refusals that name the form that works."""

from __future__ import annotations

import math

import pytest
import sympy as sp

from rbdsolve.errors import InputError
from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.solvers import solve_problem
from rbdsolve.solvers.modes.gyroscopic import essential, squares_out
from rbdsolve.solvers.routes.options import Options, RouteChoice

m, h, A, C, g, s, k, r = sp.symbols("m h A C g s k r", positive=True)

# The sleeping top, its spin prescribed as a turn [z, s t] (a driven rotor): at the
# vertical the same linear equations as the free spin (C (ȧ sin b)² is of fourth order),
# A ä + C s ḃ − m g h a = 0, A b̈ − C s ȧ − m g h b = 0 (by hand).
DRIVEN_TOP = """
parameters: {m: mass, h: length, A: inertia about O, C: axial inertia, g: gravity, s: spin rate}
assumptions: [A > m*h**2]
coordinates: [a, b]
gravity: [0, 0, -g]
triads:
  T: {turns: [[x, a], [y, b], [z, s*t]], vectors: [e1, e2, e3]}
points:
  G: h*e3
bodies:
  top: {mass: m, inertia: [A - m*h**2, A - m*h**2, C], at: G, orientation: [T]}
questions:
  - modes: {about: {a: 0, b: 0}}
"""

FREE_TOP = DRIVEN_TOP.replace("coordinates: [a, b]", "coordinates: [a, b, phi]").replace(
    "[z, s*t]", "[z, phi]").replace("about: {a: 0, b: 0}", "about: {a: 0, b: 0, dot(phi): s}")


def solutions(text: str, **options):
    return solve_problem(build_model(load_text(text, "top.yaml")), Options(**options)).solutions


@pytest.mark.parametrize("text", [DRIVEN_TOP, FREE_TOP])
def test_sleeping_top_driven_or_free(text) -> None:
    (modes,) = solutions(text)
    assert modes.error is None, modes.error
    a = modes.answers
    assert sp.Matrix(a.M) == sp.Matrix([[A, 0], [0, A]])
    assert sp.Matrix(a.G) == sp.Matrix([[0, C * s], [-C * s, 0]])
    assert sp.Matrix(a.K) == sp.Matrix([[-m * g * h, 0], [0, -m * g * h]])
    D = C**2 * s**2 - 4 * A * m * g * h
    want = [(C * s - sp.sqrt(D)) / (2 * A), (C * s + sp.sqrt(D)) / (2 * A)]
    assert all(sp.simplify(x - y) == 0 for x, y in zip(a.frequencies, want))
    assert [c.parameter for c in a.critical] == ["s"]
    s_c = 2 * sp.sqrt(A * m * g * h) / C
    assert sp.simplify(a.critical[0].value - s_c) == 0
    # sampled on both sides of s_c, at parameter values a test picks
    point = {m: 1, h: sp.Rational(1, 10), A: sp.Rational(1, 50), C: sp.Rational(1, 100), g: sp.Rational(981, 100)}
    for factor, expected in ((sp.Rational(99, 100), "unstable"), (sp.Rational(101, 100), "stable")):
        at = {**point, s: s_c.xreplace(point) * factor}
        (case,) = [c for c in a.stability_cases if bool(c.when.xreplace(at))]
        assert case.stability.value == expected
        roots = sp.Poly(sp.Matrix([[-m * g * h - A * sp.Symbol("w") ** 2, sp.I * sp.Symbol("w") * C * s],
                                   [-sp.I * sp.Symbol("w") * C * s, -m * g * h - A * sp.Symbol("w") ** 2]])
                        .det().xreplace(at), sp.Symbol("w")).nroots()
        assert (max(abs(complex(z).imag) for z in roots) > 1e-9) == (expected == "unstable")


def test_the_free_top_shows_its_momentum_and_routhian() -> None:
    (modes,) = solutions(FREE_TOP)
    assert modes.answers.steady == {"phi": s}
    assert sp.simplify(modes.answers.momenta["phi"] - C * s) == 0
    texts = " ".join(step.text for step in modes.steps)
    assert "φ is cyclic" in texts and "Routh's function" in texts


def test_numeric_route_agrees_with_the_exact_one() -> None:
    values = "values: {m: 1, h: 0.1, A: 0.02, C: 0.01, g: 9.81, s: 40}\n"
    (exact,) = solutions(values + FREE_TOP)
    (numeric,) = solutions(values + FREE_TOP, route=RouteChoice.NUMERIC)
    assert numeric.error is None, numeric.error
    assert numeric.answers.stability.value == "stable"
    assert numeric.answers.frequencies == pytest.approx(exact.values["frequencies"], rel=1e-12)
    (below,) = solutions(values.replace("s: 40", "s: 10") + FREE_TOP, route=RouteChoice.NUMERIC)
    assert below.answers.stability.value == "unstable"
    # by hand: γ = √(4 A m g h − C² s²)/(2A) = √(0.07848 − 0.01)/0.04
    assert below.answers.growth_rates == pytest.approx([(0.07848 - 0.01) ** 0.5 / 0.04], rel=1e-12)


def test_a_rate_for_a_coordinate_that_is_not_cyclic_is_refused() -> None:
    (modes,) = solutions(FREE_TOP.replace("dot(phi): s", "phi: 0").replace("a: 0, b: 0,", "dot(a): 1, b: 0,"))
    assert "is for a cyclic coordinate" in modes.error and "give its value instead, a: VALUE" in modes.error


def test_euler_angles_at_the_vertical_name_the_form_that_works() -> None:
    text = FREE_TOP.replace("coordinates: [a, b, phi]", "coordinates: [psi, theta, phi]").replace(
        "[[x, a], [y, b], [z, phi]]", "[[z, psi], [x, theta], [z, phi]]").replace(
        "about: {a: 0, b: 0, dot(phi): s}", "about: {psi: 0, theta: 0, dot(phi): s}")
    (modes,) = solutions(text)
    assert "singular" in modes.error and "[[x, a], [y, b], [z, phi]]" in modes.error


def test_a_spin_angle_given_a_value_is_said_to_be_at_rest() -> None:
    (modes,) = solutions(FREE_TOP.replace("dot(phi): s", "phi: 0"))
    assert modes.error is None
    assert any("φ is cyclic" in w and "dot(phi): RATE" in w for w in modes.warnings)


def test_an_unknown_spin_is_refused_with_the_form_that_works() -> None:
    text = DRIVEN_TOP.replace("g: gravity, s: spin rate}", "g: gravity}\nunknowns: [s]")
    (modes,) = solutions(text)
    assert "'s' is an unknown" in modes.error and "declare 's' under 'parameters'" in modes.error


def test_equilibria_say_what_the_spin_may_change() -> None:
    text = DRIVEN_TOP.replace("  - modes: {about: {a: 0, b: 0}}", "  - equilibria")
    (equilibria,) = solutions(text)
    assert any("gyroscopic terms" in w and "'modes'" in w for w in equilibria.warnings)


@pytest.mark.parametrize("about, words", [
    ("{a: 0, dot(phi): s}", "give a value for every coordinate; missing b"),
])
def test_about_with_a_rate_is_read(about, words) -> None:
    with pytest.raises(InputError, match=words):
        load_text(FREE_TOP.replace("{a: 0, b: 0, dot(phi): s}", about), "top.yaml")


def test_check_amplitudes_is_refused_about_a_steady_spin() -> None:
    text = FREE_TOP.replace("dot(phi): s}}", "dot(phi): s}, check_amplitudes: [0.1]}")
    with pytest.raises(InputError, match="not available about a steady spin"):
        load_text(text, "top.yaml")


def test_essential_keeps_the_factor_that_carries_the_sign() -> None:
    assert essential(C**2 * s**2 * (C**2 * s**2 - 4 * A * m * g * h) / A**2) == C**2 * s**2 - 4 * A * m * g * h
    assert essential(-(k - m) / m) == m - k
    assert essential((k - m * s**2) ** 2 / m**2) == 1  # an even power: positive but at a root


def test_squares_out_of_a_root() -> None:
    value = sp.Pow(4 * A * g * h * m / C**2, sp.S.Half, evaluate=False)
    assert str(squares_out(value)) == "2*sqrt(A*g*h*m)/C"
    plain = sp.Pow(g / r, sp.S.Half, evaluate=False)
    assert squares_out(plain) is plain
    # nothing left over the line: √(A (g − k)/(3 m² r⁴)) is √(A (g − k)/3)/(m r²), no "1 √…"
    below = squares_out(sp.Pow(A * (g - k) / (3 * m**2 * r**4), sp.S.Half, evaluate=False))
    assert str(below) == "sqrt(A*(g - k)/3)/(m*r**2)"


GIMBALS = """
parameters: {m: mass, r: radius, s: spin rate}
coordinates: [psi, theta]
triads:
  ring: {turns: [[z, psi], [x, theta]], vectors: [e1, e2, e3]}
points:
  O: [0, 0, 0]
bodies:
  rotor: {shape: disk, mass: m, radius: r, at: O, axis: y, orientation: [ring, [y, s*t]]}
questions:
  - modes: {about: {psi: 0, theta: 0}}
"""


def test_gimbals_without_springs_have_a_neutral_direction() -> None:
    """A free gyroscope in gimbals (no springs): K = 0, det = A²ω⁴ − C²s²ω², so ω = 0
    (neutral: a steady turn of the gimbals) and the nutation ω = C s/A = 2 s (by hand,
    A = m r²/4, C = m r²/2)."""
    (modes,) = solutions(GIMBALS)
    assert modes.error is None, modes.error
    assert modes.answers.neutral == 1
    assert [sp.simplify(w - 2 * s) for w in modes.answers.frequencies] == [0]


def test_the_verdict_names_the_neutral_direction() -> None:
    """With K = 0 nothing restores a turn of the gimbals: the verdict says so, and does
    not credit the gyroscopic terms with holding what K alone would not (K has no
    negative eigenvalue; a new user's conical pendulum read "stable (the gyroscopic
    terms hold it …)" with a direction that drifts)."""
    (modes,) = solutions(GIMBALS)
    text = " ".join(step.text for step in modes.steps)
    assert "in every direction but the neutral one" in text
    assert "hold it where K alone would not" not in text


def test_both_routes_write_strict_json() -> None:
    import json

    from rbdsolve.render.json import report_object

    values = "values: {m: 1, h: 0.1, A: 0.02, C: 0.01, g: 9.81, s: 10}\n"
    for route in (RouteChoice.EXACT, RouteChoice.NUMERIC):
        report = solve_problem(build_model(load_text(values + FREE_TOP, "top.yaml")), Options(route=route))
        data = json.loads(json.dumps(report_object(report), allow_nan=False))
        answers = data["results"][0]["answers"]
        assert answers["stability"] == "unstable" and answers["steady"]["phi"] in ("s", 10.0)


def test_a_spin_about_an_axis_that_is_not_of_symmetry_is_named() -> None:
    """A box (three different moments) spun at s t about its own z: T changes with t."""
    text = DRIVEN_TOP.replace("inertia: [A - m*h**2, A - m*h**2, C]", "inertia: [A - m*h**2, 2*A, C]")
    (modes,) = solutions(text)
    assert "not one of symmetry of its inertia" in modes.error and "body 'top'" in modes.error


def test_without_about_the_first_equilibrium_stable_by_k_is_taken() -> None:
    """The hanging top, b = π: by hand M = A 1, K = m g h 1, G = −C s [[0, 1], [−1, 0]]
    (cos b = −1), ω = (√(C² s² + 4 A m g h) ∓ C s)/(2A), stable for every s."""
    (modes,) = solutions(DRIVEN_TOP.replace("  - modes: {about: {a: 0, b: 0}}", "  - modes"))
    a = modes.answers
    assert a.about == {"a": 0, "b": sp.pi} and a.stability.value == "stable"
    D = C**2 * s**2 + 4 * A * m * g * h
    assert all(sp.simplify(x - y) == 0 for x, y in zip(a.frequencies, [(sp.sqrt(D) - C * s) / (2 * A),
                                                                       (sp.sqrt(D) + C * s) / (2 * A)]))


def test_the_modes_of_a_gyroscopic_scene_are_not_drawn() -> None:
    from rbdsolve.errors import UnsolvedError
    from rbdsolve.render.drawing.mode_shapes import mode_shapes

    text = """
parameters: {m: mass, k: stiffness, Omega: rate}
values: {m: 1, k: 10, Omega: 1}
coordinates: [x, y]
frames:
  table: {axis: z, rate: Omega}
points:
  A: [0, 0]
  P: [x*cos(Omega*t) - y*sin(Omega*t), x*sin(Omega*t) + y*cos(Omega*t)]
bodies:
  bead: {shape: particle, mass: m, at: P}
springs:
  s: {between: [P, A], stiffness: k}
questions:
  - modes: {frame: table, about: {x: 0, y: 0}}
"""
    model = build_model(load_text(text, "slot.yaml"))
    with pytest.raises(UnsolvedError, match="whirls, not normal modes"):
        mode_shapes(model, model.problem.questions[0])


SPRUNG_ROTOR = """
parameters: {M: mass, L: length, m: mass, r: radius, k: stiffness, g: gravity, s: spin rate}
values: {M: 200 g, L: 30 cm, m: 1 kg, r: 10 cm, k: 2 N*m/rad, g: 9.81 m/s^2, s: 120}
coordinates: [a, b]
gravity: [0, 0, -g]
triads:
  T: {turns: [[x, a], [y, b]], vectors: [e1, e2, e3]}
points:
  G: L/2*e3
  D: L*e3
bodies:
  rod: {shape: rod, mass: M, length: L, at: G, axis: z, orientation: [T]}
  rotor: {shape: disk, mass: m, radius: r, at: D, orientation: [T, [z, s*t]]}
springs:
  tilt_a: {stiffness: k, angle: a}
  tilt_b: {stiffness: k, angle: b}
questions:
  - modes: {about: {a: 0, b: 0}}
"""


def test_the_growth_rate_below_the_critical_spin_is_a_number(tmp_path) -> None:
    """A rod upright on a sprung Cardan joint with a rotor on top (newuser21): A = M L²/3 +
    m L² + m r²/4 = 0.0985, C = m r²/2 = 0.005, K = k − (M/2 + m) g L = −1.2373, so
    A σ² ± i C s σ + K = 0 has Re σ = √(−4 A K − C² s²)/(2 A) = 1.81252 1/s at s = 120
    (below s_c = 2 √(−A K)/C = 139.642). The numeric block printed no γ, and warned that
    the frequencies were not real, which is what an unstable motion's are."""
    from click.testing import CliRunner

    from rbdsolve.cli import main

    path = tmp_path / "rotor.yaml"
    path.write_text("title: a rotor on a sprung joint" + SPRUNG_ROTOR, encoding="utf-8")
    out = CliRunner().invoke(main, ["solve", str(path)])
    assert out.exit_code == 0, out.output
    A, C, K = 0.0985, 0.005, 2 - (0.1 + 1) * 9.81 * 0.3
    gamma = math.sqrt(-4 * A * K - (C * 120) ** 2) / (2 * A)
    (line,) = [x for x in out.output.splitlines() if x.strip().startswith("γ = ") and "1/s" in x]
    assert abs(float(line.split("=")[1].split()[0]) - gamma) < 1e-5 * gamma
    assert "no numeric value for frequencies" not in out.output


ARM = """
parameters: {m: mass, l: length of the rod, a: length of the arm, g: gravity, Omega: rate of the shaft}
values: {m: 0.5, l: 0.4, a: 0.3, g: 9.81, Omega: 4}
coordinates: [alpha, beta]
gravity: [0, 0, -g]
frames:
  arm: {axis: z, rate: Omega}
triads:
  A: {turns: [[z, Omega*t]], vectors: [er, et, ez]}
points:
  P: (a + l*sin(beta))*er - l*sin(alpha)*cos(beta)*et - l*cos(alpha)*cos(beta)*ez
bodies:
  bob: {shape: particle, mass: m, at: P}
questions:
  - modes: {frame: arm, about: {equilibrium: 2}}
"""


def _arm_by_hand() -> list[float]:
    """A spherical pendulum hung from the end of an arm turning at Ω (a new user's): its
    position in fixed axes, turned by Ω t, T = ½ m |ṙ|², V = m g z, Lagrange's equations
    linearized by hand about α = 0 and the β₀ where the arm's plane holds it,
    g sin β₀ = Ω² cos β₀ (a + l sin β₀); M ü + G u̇ + K u = 0 solved as its first-order
    eigenproblem by numpy."""
    import numpy as np
    from scipy.optimize import brentq

    t = sp.Symbol("t")
    al, be = sp.Function("al")(t), sp.Function("be")(t)
    mm, ll, aa, gg, W = 0.5, 0.4, 0.3, 9.81, 4.0
    body = sp.Matrix([aa + ll * sp.sin(be), -ll * sp.sin(al) * sp.cos(be), -ll * sp.cos(al) * sp.cos(be)])
    turn = sp.Matrix([[sp.cos(W * t), -sp.sin(W * t), 0], [sp.sin(W * t), sp.cos(W * t), 0], [0, 0, 1]])
    r = turn * body
    v = r.diff(t)
    L = sp.simplify(mm * v.dot(v) / 2) - mm * gg * r[2]
    q = [al, be]
    x = sp.symbols("x0 x1")
    xd = sp.symbols("v0 v1")
    rep = {q[0].diff(t): xd[0], q[1].diff(t): xd[1]}
    Lp = L.subs(rep).subs({q[0]: x[0], q[1]: x[1]})
    beta0 = brentq(lambda b: gg * math.sin(b) - W**2 * math.cos(b) * (aa + ll * math.sin(b)), 0.1, 1.5)
    at = {x[0]: 0, x[1]: beta0, xd[0]: 0, xd[1]: 0}
    M = np.array([[float(Lp.diff(xd[i], xd[j]).subs(at)) for j in range(2)] for i in range(2)])
    C = [[float(Lp.diff(xd[i], x[j]).subs(at)) for j in range(2)] for i in range(2)]
    G = np.array([[C[i][j] - C[j][i] for j in range(2)] for i in range(2)])
    K = np.array([[-float(Lp.diff(x[i], x[j]).subs(at)) for j in range(2)] for i in range(2)])
    A = np.block([[np.zeros((2, 2)), np.eye(2)], [-np.linalg.solve(M, K), -np.linalg.solve(M, G)]])
    s = np.linalg.eigvals(A)
    return sorted(abs(z.imag) for z in s if z.imag > 0)


def test_a_frame_s_equilibrium_found_numerically_has_its_modes() -> None:
    """'modes: {frame: arm, about: {equilibrium: 2}}' (the stable one of the two the
    numeric equilibria list: the other, β₀ past π/2, is a maximum) where it has no closed
    form: the numeric route takes the numeric equilibria's root, steady to its rounding
    (it was refused: 'not a steady state … a decimal … is never exactly steady')."""
    (modes,) = solutions(ARM)
    assert modes.error is None, modes.error
    got = list(modes.answers.frequencies)
    want = _arm_by_hand()
    assert len(got) == 2 and all(abs(a - b) < 1e-8 * b for a, b in zip(got, want)), (got, want)
