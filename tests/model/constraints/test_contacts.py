"""Rolling contacts, checked by their definition rather than by the formulas of
model/constraints/contacts.py: for each problem under problems/contacts/, the body's material point
at the contact C (placed by the model) moves with the surface there — at rest, or with
the plank — at random configurations and rates; and C lies on the surface."""

from __future__ import annotations

import random
from pathlib import Path

import pytest
import sympy as sp

from rbdsolve.model.build import build_model
from rbdsolve.problem import load_file, load_text

from conftest import PROBLEMS, counted_calls

CASES = sorted((PROBLEMS / "contacts").glob("*.yaml"))
CASES = [p for p in CASES if not p.name.endswith(".expected.yaml")]
# the velocity of the surface's material point at C, by hand: a fixed surface is at rest,
# the plank translates with ẋ, the turning disk and the ring on its axle (centres at the
# origin) turn at ψ̇: ψ̇ e_z × C
TURNING = lambda rate, C: rate["psi"] * sp.Matrix([-C[1], C[0], 0])  # noqa: E731
SURFACE_VELOCITY = {"cylinder-on-plank": lambda rate, C: sp.Matrix([rate["x"], 0, 0]),
                    "disk-on-turning-disk": TURNING, "ring-and-disk-inside": TURNING}


@pytest.mark.parametrize("path", CASES, ids=[p.stem for p in CASES])
def test_the_contact_point_of_the_body_moves_with_the_surface(path: Path) -> None:
    model = build_model(load_file(path))
    state = model.state
    rng = random.Random(20)
    for contact in (c for c in model.contacts if c.source.pulley is None):  # strings: tests/model/constraints/test_strings.py
        body = next(b for b in model.bodies if b.name == contact.body)
        origin = model.symbols.vector(next(b for b in model.problem.bodies if b.name == body.name).at)
        omega = body.angular_velocity(state)
        v_c = state.d_dt(origin) + omega.cross(contact.point - origin)  # rigid body: v_O + ω × (C − O)
        for _ in range(3):
            at = {q: sp.Rational(rng.randint(-900, 900), 1000) for q in state.q}
            at |= {qd: sp.Rational(rng.randint(-900, 900), 1000) for qd in state.qd}
            at |= {p: sp.Rational(rng.randint(1100, 2900), 1000) for p in model.symbols.parameters.values()}
            rates = {n: at[qd] for n, qd in zip(state.names, state.qd)}
            surface = SURFACE_VELOCITY.get(path.stem, lambda rate, C: sp.zeros(3, 1))(rates, contact.point)
            difference = (v_c - surface).xreplace(at)
            assert all(abs(sp.N(x, 30)) < 1e-20 for x in difference), (path.stem, difference)


def test_the_cylinder_touches_the_track() -> None:
    """C is on the circle of radius R, and r from the cylinder's centre."""
    model = build_model(load_file(PROBLEMS / "contacts" / "cylinder-in-cylinder.yaml"))
    (contact,) = model.contacts
    R, r = model.symbols.parameters["R"], model.symbols.parameters["r"]
    centre = model.bodies[0].position
    assert sp.simplify(contact.point.dot(contact.point) - R**2) == 0
    d = contact.point - centre
    assert sp.simplify(d.dot(d) - r**2) == 0


def test_the_rolling_disk_touches_the_turning_disk() -> None:
    """C is on the turning disk's rim (radius R about the origin) and r from the rolling
    disk's centre, which stays R + r from the origin, at the angle θ from the upward vertical."""
    model = build_model(load_file(PROBLEMS / "contacts" / "disk-on-turning-disk.yaml"))
    (contact,) = model.contacts
    R, r = model.symbols.parameters["R"], model.symbols.parameters["r"]
    theta = model.symbols.coordinates["theta"]
    centre = next(b for b in model.bodies if b.name == "disk").position
    assert sp.simplify(contact.point.dot(contact.point) - R**2) == 0
    assert sp.simplify(centre - (R + r) * sp.Matrix([-sp.sin(theta), sp.cos(theta), 0])) == sp.zeros(3, 1)


def test_a_cylinder_segment_rocks_at_the_hand_frequency() -> None:
    """A log cut flat (a cylinder segment, arc 2α, curved side down) rocking on the floor:
    its centre O stays r above the floor and G is ȳ from O towards the arc, so V = m g (r − ȳ cos θ);
    C is the instantaneous centre, T = ½ (J_G + m (r − ȳ)²) θ̇² at θ = 0, so by hand
    ω² = g ȳ/(k_G² + (r − ȳ)²). ȳ and k_G² = J_G/m are integrated here by sympy over the
    cross-section, not taken from the shape library."""
    from rbdsolve.model.energies.energy import mass_matrix, potential_energy
    from rbdsolve.model.energies.energy import hessian

    text = """
parameters: {m: mass, r: radius, h: length, g: gravity}
values: {r: 1, h: 2}
coordinates: [theta]
gravity: [0, -g]
bodies:
  trunk: {shape: cylinder_segment, mass: m, radius: r, height: h, half_angle: pi/3, axis: -y}
contacts:
  C: {body: trunk, edge: curved, rolls_on: floor, angle: theta}
questions: [modes]
"""
    model = build_model(load_text(text))
    (theta,) = model.q
    rho, psi = sp.symbols("rho psi", real=True)
    alpha = sp.pi / 3

    def over_section(f):  # r = 1, polar from O with ψ from the symmetry axis
        return sp.integrate(sp.integrate(f * rho, (rho, sp.cos(alpha) / sp.cos(psi), 1)), (psi, -alpha, alpha))

    area = over_section(sp.Integer(1))
    ybar = over_section(rho * sp.cos(psi)) / area
    k_G2 = over_section(rho**2) / area - ybar**2  # about the axis through G, along the log
    g, m = model.symbols.parameters["g"], model.symbols.parameters["m"]
    K = hessian(potential_energy(model).total, model.q).xreplace({theta: 0})[0, 0]
    M = mass_matrix(model).xreplace({theta: 0})[0, 0]
    omega2 = (K / M).xreplace(dict(model.values))
    expected = g * ybar / (k_G2 + (1 - ybar) ** 2)
    assert abs(sp.N((omega2 - expected).subs(g, 1), 30)) < 1e-25


def test_rolling_inside_a_circle_assumes_the_circle_is_the_larger() -> None:
    """A ball in a bowl with no 'assumptions:': the contact adds R > r (strict), shown as
    a step, so the stability of θ = 0 (K = m g (R − r), by hand) is decided without a
    case r > R; a file assuming R > r itself gets no second copy."""
    from rbdsolve.solvers.conditions.signs import sign_of
    from rbdsolve.model.summary.summary import rolling_steps

    model = build_model(load_file(PROBLEMS / "contacts" / "ball-in-bowl.yaml"))
    R, r = model.symbols.parameters["R"], model.symbols.parameters["r"]
    (implied,) = model.assumptions
    assert implied.strict and sp.expand(implied.difference - (R - r)) == 0
    assert "contact 'C'" in implied.implied_by
    assert sign_of(R - r, model.assumed) == 1
    assert any("R > r" in step.text for step in rolling_steps(model))
    stated = build_model(load_file(PROBLEMS / "contacts" / "cylinder-in-cylinder.yaml"))
    assert len(stated.assumptions) == 1 and not stated.assumptions[0].implied_by


def test_values_set_inside_out_break_the_implied_assumption() -> None:
    """--set r=2 R=1 on the ball in the bowl: refused at the contact, naming it."""
    from rbdsolve.errors import InputError

    model = build_model(load_file(PROBLEMS / "contacts" / "ball-in-bowl.yaml"))
    with pytest.raises(InputError, match=r"break the assumption 'R > r' \(implied by contact 'C'"):
        model.with_values({"r": 2, "R": 1})


SPOOL = """
parameters: {m: mass, R: radius, b: radius, g: gravity}
coordinates: [y]
gravity: [0, -g]
points: {A: [0, 0]}
bodies:
  spool: {shape: disk, mass: m, radius: R}
contacts:
  S: {body: spool, string: {fixed_at: A, direction: [0, -1], radius: b}, along: y}
questions: [eom]
"""


def test_a_string_wound_on_an_axle_assumes_it_inside_the_rim_and_falls_at_the_hand_rate() -> None:
    """Maxwell's wheel: a disk of radius R unwinding from a string wound at radius b.
    By hand, b ω = −ẏ, T = ½ m ẏ² + ½ (m R²/2) ẏ²/b², V = −m g y, so
    ÿ = g/(1 + R²/(2 b²)). The string lies on the disk: R ≥ b, assumed (not strict)."""
    from rbdsolve.model.energies.energy import kinetic_energy, potential_energy

    model = build_model(load_text(SPOOL, "spool.yaml"))
    p = model.symbols.parameters
    (wound,) = model.assumptions
    assert not wound.strict and sp.expand(wound.difference - (p["R"] - p["b"])) == 0 and "'S'" in wound.implied_by
    y, yd = model.q[0], model.qd[0]
    T, V = kinetic_energy(model).total, potential_energy(model).total
    M, force = sp.diff(T, yd, 2), -sp.diff(V, y)
    assert sp.simplify(force / M - p["g"] / (1 + p["R"] ** 2 / (2 * p["b"] ** 2))) == 0


def test_a_string_wound_outside_the_rim_is_refused_at_its_radius() -> None:
    from rbdsolve.errors import InputError

    with pytest.raises(InputError, match="outside the rim of 'spool'") as caught:
        build_model(load_text(SPOOL.replace("radius: b}", "radius: 2*R}"), "spool.yaml"))
    assert (caught.value.location.line, caught.value.location.column) == (9, 70)  # at 2*R
    with pytest.raises(InputError, match=r"break the assumption 'R ≥ b' \(implied by contact 'S'"):
        build_model(load_text(SPOOL.replace("questions", "values: {R: 1, b: 2}\nquestions"), "spool.yaml"))


DISK_IN_TRACK = """\
parameters: {m: mass, r: length, R: length, g: acceleration}
assumptions: [R > r]
coordinates: [theta]
gravity: [0, -g]
bodies:
  disk: {shape: disk, mass: m, radius: r}
contacts:
  C: {body: disk, rolls_on: {circle: {centre: [0, 0], radius: R, side: inside}}, along: theta}
questions: [eom]
"""


def test_a_rolling_contact_is_placed_without_simplify(monkeypatch) -> None:
    """The disk's place, angle and contact point by tidy alone (simplify's first call in a
    process imports sympy's physical units, ~0.1 s); by hand: the centre at (R − r)
    (sin θ, −cos θ), the disk turned by −(R − r) θ/r."""
    calls = counted_calls(monkeypatch, sp, "simplify")
    model = build_model(load_text(DISK_IN_TRACK, "disk-in-track.yaml"))
    # a number or a symbol: simplify returns it before any import
    assert [args[0] for args in calls if sp.sympify(args[0]).args] == []
    R, r = (model.symbols.parameters[n] for n in ("R", "r"))
    theta = model.q[0]
    disk = next(b for b in model.bodies if b.name == "disk")
    assert sp.expand(disk.position[0] - (R - r) * sp.sin(theta)) == 0
    assert sp.expand(disk.position[1] + (R - r) * sp.cos(theta)) == 0
    assert sp.expand(disk.angle + (R - r) * theta / r) == 0
