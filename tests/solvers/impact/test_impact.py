"""Impacts: physical laws the answers must obey, on random scenes, and the errors found
only when solving.

Expected values are laws, not rbdsolve output: with e = 1 kinetic energy is conserved;
with e = 0 the struck point and what hit it do not separate along the normal; a free
system with the particle that hits it keeps its momentum and its angular momentum; the
impulse equations' matrix is the mass matrix at the instant, derived by hand.
"""

from __future__ import annotations

from fractions import Fraction

import pytest
import sympy as sp
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from rbdsolve.errors import InputError
from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.solvers import Options, solve_problem
from rbdsolve.solvers.impact.equations import ImpactEquations, blows, instant

from conftest import PROBLEMS

# A cart (x) carrying a hanging rod (θ); a particle hits the rod at Q, a distance d
# below the cart, at the angle th0 where cos and sin are exact. Random scenes put
# numbers in place of M, m, l, so each is solved exactly in a fraction of a second.
CART = """
parameters: {{M: cart mass, m: rod mass, l: length}}
coordinates: [x, theta]
points:
  C: [x, 0]
  G: C + {l}/2 * [sin(theta), -cos(theta)]
  Q: C + {d} * [sin(theta), -cos(theta)]
bodies:
  cart: {{shape: particle, mass: {M}, at: C}}
  rod: {{shape: rod, mass: {m}, length: {l}, at: G, angle: theta, axis: y}}
questions:
  - impact:
      at: {{theta: {th0}}}
      before: {{x: {xd}, theta: {thd}}}
      collisions:
        Q: {{normal: [{n1}, {n2}], restitution: {e}, particle: {{mass: {mu}, velocity: [{u1}, {u2}]}}}}
"""

# A free rod on a smooth table, hit at Q by a particle.
FREE = """
coordinates: [x, y, theta]
points:
  G: [x, y]
  Q: G + {s} * [cos(theta), sin(theta)]
bodies:
  rod: {{shape: rod, mass: {m}, length: {l}, at: G, angle: theta}}
questions:
  - impact:
      at: {{theta: {th0}}}
      before: {{x: {xd}, y: {yd}, theta: {thd}}}
      collisions:
        Q: {{normal: [{n1}, {n2}], restitution: {e}, particle: {{mass: {mu}, velocity: [{u1}, {u2}]}}}}
      points: [G, Q]
"""

ANGLES = ["0", "pi/2", "pi/3", "pi/4", "-pi/6"]
small = st.fractions(min_value=Fraction(-3), max_value=Fraction(3), max_denominator=5)
positive = st.fractions(min_value=Fraction(1, 4), max_value=Fraction(4), max_denominator=5)


def solve(text: str, **values):
    model = build_model(load_text(text, "scene.yaml"))
    return solve_problem(model.with_values({k: Fraction(v) for k, v in values.items()}), Options()).solutions[0]


def answered(text: str):
    solution = solve(text)
    assume(solution.error is None or "nothing approaches" not in solution.error)
    assert solution.error is None, solution.error
    return solution.answers


def vector(values) -> sp.Matrix:
    return sp.Matrix([sp.nsimplify(v) if not isinstance(v, sp.Basic) else v for v in values])


@st.composite
def cart_scenes(draw, e: str):
    n1, n2 = draw(small), draw(small)
    assume(n1 != 0 or n2 != 0)
    text = CART.format(M=draw(positive), m=draw(positive), l=draw(positive), d=draw(positive),
                       th0=draw(st.sampled_from(ANGLES)), xd=draw(small), thd=draw(small),
                       n1=n1, n2=n2, e=e, mu=draw(positive), u1=draw(small), u2=draw(small))
    return text, sp.Matrix([sp.Rational(str(n1)), sp.Rational(str(n2)), 0])


@settings(max_examples=10, deadline=None)
@given(cart_scenes(e="1"))
def test_elastic_impact_conserves_kinetic_energy(scene) -> None:
    answers = answered(scene[0])
    assert sp.simplify(answers.energy_lost) == 0
    assert sp.simplify(answers.energy_before - answers.energy_after) == 0


@settings(max_examples=6, deadline=None)
@given(cart_scenes(e="0"))
def test_plastic_impact_leaves_no_normal_separation_speed(scene) -> None:
    answers = answered(scene[0])
    n = scene[1]
    v_Q, u = sp.Matrix(answers.points["Q"]), sp.Matrix(answers.particles["Q"])
    assert sp.simplify(n.dot(v_Q - u)) == 0
    assert sp.simplify(answers.energy_lost) >= 0


@settings(max_examples=5, deadline=None)
@given(m=positive, l=positive, s=small, th0=st.sampled_from(ANGLES), xd=small, yd=small, thd=small,
       n1=small, n2=small, e=st.sampled_from(["0", "1/3", "1"]), mu=positive, u1=small, u2=small)
def test_free_rod_and_particle_keep_momentum_and_angular_momentum(m, l, s, th0, xd, yd, thd, n1, n2, e,
                                                                  mu, u1, u2) -> None:
    assume(n1 != 0 or n2 != 0)
    text = FREE.format(m=m, l=l, s=s, th0=th0, xd=xd, yd=yd, thd=thd, n1=n1, n2=n2, e=e, mu=mu, u1=u1, u2=u2)
    answers = answered(text)
    m, l, mu = sp.Rational(str(m)), sp.Rational(str(l)), sp.Rational(str(mu))
    angle = sp.sympify(th0)
    r_Q = sp.Rational(str(s)) * sp.Matrix([sp.cos(angle), sp.sin(angle), 0])  # from G, at G = 0
    u_i = sp.Matrix([sp.Rational(str(u1)), sp.Rational(str(u2)), 0])
    v_i = sp.Matrix([sp.Rational(str(xd)), sp.Rational(str(yd)), 0])
    w_i = sp.Rational(str(thd))
    v_f, u_f = sp.Matrix(answers.points["G"]), sp.Matrix(answers.particles["Q"])
    w_f = answers.velocities["theta"]
    J = m * l**2 / 12
    assert sp.simplify(m * v_f + mu * u_f - (m * v_i + mu * u_i)) == sp.zeros(3, 1)
    L_i = J * w_i + r_Q.cross(mu * u_i)[2]  # about the instantaneous position of G
    L_f = J * w_f + r_Q.cross(mu * u_f)[2]
    assert sp.simplify(L_f - L_i) == 0


def test_impulse_equations_matrix_is_the_mass_matrix() -> None:
    """Hand: T = ½ (M + m) ẋ² + ½ m l cos θ ẋ θ̇ + 1/6 m l² θ̇² for the cart and rod."""
    text = CART.format(M="M", m="m", l="l", d="l", th0="pi/3", xd=0, thd=0, n1=1, n2=0, e="1/2",
                       mu=1, u1=1, u2=0)
    model = build_model(load_text(text, "scene.yaml"))
    opts = model.problem.questions[0].options
    now = instant(model, opts)
    work = ImpactEquations(model, opts, now, blows(model, opts, now))
    A, _ = sp.linear_eq_to_matrix([sp.expand(x) for x in work.lagrange()], list(work.final))
    M, m, l = (model.symbols.parameters[n] for n in ("M", "m", "l"))
    by_hand = sp.Matrix([[M + m, m * l / 2 * sp.cos(sp.pi / 3)], [m * l / 2 * sp.cos(sp.pi / 3), m * l**2 / 3]])
    assert sp.simplify(A - by_hand) == sp.zeros(2, 2)


PENDULUM = """
parameters: {m: mass, l: length, v0: speed, e: restitution}
coordinates: [theta]
points:
  A: l * [sin(theta), -cos(theta)]
bodies:
  bob: {shape: particle, mass: m, at: A}
questions:
  - impact:
      at: {theta: 0}
      collisions:
        A: {normal: x, restitution: e, particle: {mass: m, velocity: [v0, 0]}}
"""


def test_equal_masses_exchange_velocities_when_elastic() -> None:
    """A particle hits an equal hanging bob head on: with e = 1 they swap velocities."""
    answers = solve(PENDULUM.replace("restitution: e", "restitution: 1")).answers
    v0, l = sp.Symbol("v0", positive=True), sp.Symbol("l", positive=True)
    assert sp.simplify(answers.velocities["theta"] - v0 / l) == 0
    assert answers.particles["A"] == (0, 0, 0)


def test_restitution_outside_zero_one_from_values_is_located() -> None:
    with pytest.raises(InputError) as info:
        solve(PENDULUM, e=2)
    assert "between 0 and 1" in info.value.message
    assert info.value.location.key_path() == "questions[0].impact.collisions.A.restitution"


def test_a_missing_configuration_is_named() -> None:
    with pytest.raises(InputError) as info:
        solve(PENDULUM.replace("      at: {theta: 0}\n", ""))
    assert "depend on theta: give its value with 'at:'" in info.value.message
    assert info.value.location.key_path() == "questions[0].impact"


def test_a_receding_particle_is_not_a_collision() -> None:
    solution = solve(PENDULUM.replace("velocity: [v0, 0]", "velocity: [-v0, 0]"))
    assert solution.error is not None and "nothing approaches" in solution.error


def test_a_coordinate_without_inertia_is_refused() -> None:
    text = PENDULUM.replace("coordinates: [theta]", "coordinates: [theta, s]")
    solution = solve(text)
    assert solution.error is not None and "singular" in solution.error


def test_a_negative_particle_mass_or_restitution_is_refused() -> None:
    with pytest.raises(InputError, match="a particle's mass must be positive, found -m"):
        solve(PENDULUM.replace("particle: {mass: m,", "particle: {mass: -m,"))
    with pytest.raises(InputError, match="between 0 and 1, found 1 \\+ e"):
        solve(PENDULUM.replace("restitution: e", "restitution: 1 + e"))


ROD_ON_LEDGES = """
parameters: {m: mass, l: length, v0: speed}
coordinates: [x, y, theta]
points:
  G: [x, y]
  A: G + l/2 * [cos(theta), sin(theta)]
bodies:
  rod: {shape: rod, mass: m, length: l, at: G, angle: theta}
questions:
  - impact:
      at: {theta: 0}
      before: {x: -v0, y: -v0}
      collisions:
        A: {normal: [sqrt(3), 1], restitution: 1/2}
        G: {normal: [3, sqrt(3)], restitution: 1/2}
"""


def test_singular_only_through_radicals_is_detected() -> None:
    """Normals (√3, 1) and (3, √3) are parallel only because √3·√3 = 3: with both at
    the centre of mass line the equations are singular; never zoo or nan."""
    text = ROD_ON_LEDGES.replace("A: {normal", "H: {normal").replace("  A: G +", "  H: G +")
    solution = solve(text.replace("H: G + l/2 * [cos(theta), sin(theta)]", "H: G + [0, 0]"))
    assert solution.error is not None and "singular" in solution.error


def test_centre_of_percussion_needs_every_component_to_vanish() -> None:

    text = (PROBLEMS / "impact" / "pendulum-struck.yaml").read_text()
    solution = solve(text.replace("impulses: {Q: [P, 0]}", "impulses: {Q: [P, P]}"))
    assert solution.answers.centre_of_percussion is None
    assert any("no single value of d" in w for w in solution.warnings)


@pytest.mark.parametrize("e", ["0", "1/3", "1/2", "1"])
def test_a_head_on_hit_gives_the_velocities_by_hand_for_each_restitution(e) -> None:
    """A particle of mass μ at v0 hits a hanging bob m head on (A at θ = 0, normal x).
    By hand, momentum μ v0 = m l θ̇ + μ u and Newton's law l θ̇ − u = e v0 give
    l θ̇ = μ (1 + e) v0/(m + μ), u = (μ − e m) v0/(m + μ), and the energy lost
    ½ m μ/(m + μ) (1 − e²) v0². A flipped sign in the law (−e) gives the same energy for
    e = 1 and the same result for e = 0: the values in between tell."""
    text = PENDULUM.replace("restitution: e", f"restitution: {e}").replace("mass: m, velocity", "mass: mu, velocity")
    text = text.replace("parameters: {m: mass,", "parameters: {mu: mass, m: mass,")
    answers = solve(text).answers
    m, mu, l, v0 = (sp.Symbol(n, positive=True) for n in ("m", "mu", "l", "v0"))
    ee = sp.Rational(e)
    assert sp.simplify(answers.velocities["theta"] - mu * (1 + ee) * v0 / ((m + mu) * l)) == 0
    assert sp.simplify(answers.particles["A"][0] - (mu - ee * m) * v0 / (m + mu)) == 0
    assert sp.simplify(answers.energy_lost - m * mu * (1 - ee**2) * v0**2 / (2 * (m + mu))) == 0
