"""Rolling bodies of any make (issue 40): a body given by its inertia rolls at a given
radius, a composite body on the edge of the part that touches. Expected values by hand,
or by the same scene written with a library shape of the same inertia."""

from __future__ import annotations

import sympy as sp

from rbdsolve.model.build import build_model
from rbdsolve.model.energies.energy import kinetic_energy, mass_matrix, potential_energy
from rbdsolve.problem import load_text

SPOOL = """
parameters: {M: mass, m_h: mass, R: length, r: length, w: length, m: mass, g: gravity, d: length}
coordinates: [x]
gravity: [0, -g]
points: {P: [d, R + r]}
bodies:
  spool:
    parts:
      hub: {shape: cylinder, mass: m_h, radius: r, height: w}
      left: {shape: disk, mass: M, radius: R, at: [0, 0, -w/2]}
      right: {shape: disk, mass: M, radius: R, at: [0, 0, w/2]}
  block: {shape: particle, mass: m}
contacts:
  C: {body: spool, part: left, rolls_on: floor, along: x}
  S: {body: block, hangs_from: {drum: spool, part: hub, direction: [1, 0], over: P}}
questions: [eom]
"""


def test_a_spool_of_parts_rolls_on_a_flange_and_pays_out_from_its_hub() -> None:
    """By hand: the flanges (radius R) roll, ω = ẋ/R; the hub's top, r above the centre,
    moves at ẋ (1 + r/R), so the block falls by (R + r) x/R. J = 2·M R²/2 + m_h r²/2,
    T = ½ (2M + m_h + J/R²) ẋ² + ½ m (R + r)² ẋ²/R², V = −m g (R + r) x/R. The flange at
    z = −w/2 touches the floor: the centre stays R above it, in the scene's plane."""
    model = build_model(load_text(SPOOL))
    p = model.symbols.parameters
    M, m_h, R, r, m, g = (p[k] for k in ("M", "m_h", "R", "r", "m", "g"))
    (x,) = model.q
    J = M * R**2 + m_h * r**2 / 2
    expected = 2 * M + m_h + J / R**2 + m * (R + r) ** 2 / R**2
    assert sp.simplify(mass_matrix(model)[0, 0] - expected) == 0
    force = -sp.diff(potential_energy(model).total, x)
    assert sp.simplify(force - m * g * (R + r) / R) == 0
    spool = next(b for b in model.bodies if b.name == "spool")
    assert sp.simplify(spool.position - sp.Matrix([x, R, 0])) == sp.zeros(3, 1)
    (contact, _) = model.contacts
    assert sp.simplify(contact.point - sp.Matrix([x, 0, 0])) == sp.zeros(3, 1)


DRUM = """
parameters: {M: mass, m: mass, R: length, r: length, g: gravity}
coordinates: [psi, theta]
gravity: [0, -g]
bodies:
  drum: {DRUM, at: [0, 0], angle: psi}
  disk: {shape: disk, mass: m, radius: r}
contacts:
  C: {body: disk, rolls_on: {body: drum RADIUS}, along: theta}
questions: [eom]
"""


def test_a_drum_given_by_its_inertia_is_rolled_on_as_the_disk_of_that_inertia() -> None:
    """A disk rolling on a drum that turns on its axle: the drum given by J = M R²/2 and
    the radius R of its rim gives the T and V of the drum written as a disk of radius R."""
    shaped = build_model(load_text(DRUM.replace("DRUM", "shape: disk, mass: M, radius: R").replace(" RADIUS", "")))
    given = build_model(load_text(DRUM.replace("DRUM", "mass: M, inertia: M*R**2/2").replace(" RADIUS", ", radius: R")))
    common = sp.symbols("psi theta psi_dot theta_dot")

    def plain(model, energy):  # each model has its own coordinate symbols
        return energy(model).total.xreplace(dict(zip((*model.q, *model.qd), common)))

    for energy in (kinetic_energy, potential_energy):
        assert sp.simplify(plain(shaped, energy) - plain(given, energy)) == 0


def test_a_wheel_rolls_on_its_axle_on_rails() -> None:
    """A disk of radius R rolling on rails on its axle of radius r: ω = ẋ/r, so by hand
    T = ½ m ẋ² (1 + R²/(2 r²)); the axle inside the rim is assumed (R ≥ r)."""
    model = build_model(load_text("""
parameters: {m: mass, R: length, r: length, g: gravity, alpha: angle}
coordinates: [x]
gravity: [0, -g]
bodies: {wheel: {shape: disk, mass: m, radius: R}}
contacts:
  C: {body: wheel, radius: r, rolls_on: {line: {through: [0, 0], angle: -alpha}}, along: x}
questions: [eom]
"""))
    p = model.symbols.parameters
    m, R, r = p["m"], p["R"], p["r"]
    assert sp.simplify(mass_matrix(model)[0, 0] - m * (1 + R**2 / (2 * r**2))) == 0
    (implied,) = model.assumptions
    assert not implied.strict and sp.expand(implied.difference - (R - r)) == 0
