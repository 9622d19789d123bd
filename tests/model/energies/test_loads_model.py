"""Applied loads in the model: each generalized force against the power written by hand
(P = F·v + M ω, Q_i its coefficient of q̇_i), and each potential found against the
work by hand (or absent where the load changes with t)."""

from __future__ import annotations

import re

import pytest
import sympy as sp

from rbdsolve.errors import InputError
from rbdsolve.model.build import build_model
from rbdsolve.model.energies.loads import free_forces
from rbdsolve.problem import load_file, load_text

from conftest import PROBLEMS

SPOOL = PROBLEMS / "forces" / "spool-pulled-at-angle.yaml"


def _symbols(model) -> dict[str, sp.Symbol]:
    return {**dict(model.symbols.parameters), **dict(zip(model.coordinate_names(), model.q))}


def _zero(expr) -> bool:
    if isinstance(expr, sp.MatrixBase):
        return all(sp.simplify(x) == 0 for x in expr)
    return sp.simplify(expr) == 0


def test_the_spool_s_pull_by_hand() -> None:
    """Power of the pull: F·v_G + τ φ̇, τ = r F (the string leaves the axle from below, so
    its line passes r below G: moment r F counterclockwise), φ̇ = −ẋ/R (rolling):
    Q_x = F cos α − r F/R; a potential, V_F = −F x (cos α − r/R) + a constant."""
    model = build_model(load_file(SPOOL))
    s = _symbols(model)
    F, R, r, alpha = s["F"], s["R"], s["r"], s["alpha"]
    (pull,) = model.loads
    assert _zero(pull.generalized[0] - (F * sp.cos(alpha) - r * F / R))
    assert _zero(sp.diff(pull.potential, s["x"]) + F * (sp.cos(alpha) - r / R))
    assert free_forces(model) is None


def test_the_string_leaving_the_axle_from_above_turns_the_other_way() -> None:
    model = build_model(load_text(SPOOL.read_text(encoding="utf-8").replace("side: below", "side: above"), "s.yaml"))
    s = _symbols(model)
    assert _zero(model.loads[0].generalized[0] - s["F"] * (sp.cos(s["alpha"]) + s["r"] / s["R"]))


def test_a_wound_side_the_signs_do_not_decide_is_refused_with_the_way_out() -> None:
    text = SPOOL.read_text(encoding="utf-8").replace("assumptions: [r < R, alpha < pi/2]", "assumptions: [r < R]")
    try:
        build_model(load_text(text, "s.yaml"))
    except Exception as exc:  # noqa: BLE001 - the message is what is tested
        message = str(exc)
    else:
        raise AssertionError("the side below the axle was taken without knowing the sign of cos α")
    assert "depends on the sign of cos(α)" in message and "alpha < pi/2" in message
    assert build_model(load_text(text.replace("questions:", "values: {alpha: pi/3}\nquestions:"), "s.yaml")).loads
    renamed = re.sub(r"\balpha\b", "beta", text)  # the way out names the file's own angle
    with pytest.raises(InputError, match=re.escape("such as 'assumptions: [beta < pi/2]'")):
        build_model(load_text(renamed, "s.yaml"))


def test_the_assumption_the_way_out_suggests_is_taken() -> None:
    """A pull at a sum of two angles, a + b: the message asks for [cos(a + b) > 0], and
    given, it decides (it was refused the same way again: the test of what an assumption
    implies read one-parameter conditions only). Q_x = F (cos(a + b) − r/R), as the
    spool's by hand above with α = a + b."""
    text = SPOOL.read_text(encoding="utf-8").replace("assumptions: [r < R, alpha < pi/2]", "assumptions: [r < R]")
    text = text.replace("  alpha: angle of the string above the horizontal", "  a: slope\n  b: string to the slope")
    text = text.replace("F*[cos(alpha), sin(alpha)]", "F*[cos(a + b), sin(a + b)]")
    with pytest.raises(InputError, match=re.escape("such as 'assumptions: [cos(a + b) > 0]'")):
        build_model(load_text(text, "s.yaml"))
    model = build_model(load_text(text.replace("assumptions: [r < R]", "assumptions: [r < R, cos(a + b) > 0]"),
                                  "s.yaml"))
    s = _symbols(model)
    angle = sp.cos(s["a"] + s["b"])
    assert _zero(model.loads[0].generalized[0] - s["F"] * (angle - s["r"] / s["R"]))


ROD = """\
parameters: {m: mass, l: length, h: height, W: weight, g: gravity, F0: force, w: rate, M0: couple}
coordinates: [theta]
gravity: [0, -g]
points:
  O: [0, 0]
  A: [0, h]
bodies:
  rod: {shape: rod, mass: m, length: l, at: "l/2*[sin(theta), -cos(theta)]", angle: theta, axis: y,
        points: {B: [0, -l/2]}}
forces:
  tow: {at: B, force: W, towards: A}
  shake: {at: B, force: "[F0*cos(w*t), 0]"}
couples:
  drive: {on: rod, moment: M0}
questions: [eom]
"""


def test_a_pull_towards_a_peg_a_force_in_time_and_a_couple() -> None:
    """B = l (sin θ, −cos θ). The pull W towards A = (0, h): V = W |A − B| (the string
    over the peg shortens as B nears it); the force F0 cos(wt) along x: power
    F0 cos(wt) l cos θ θ̇, no potential; the couple: power M0 θ̇, V = −M0 θ."""
    model = build_model(load_text(ROD, "rod.yaml"))
    s = _symbols(model)
    theta, l, h, W = s["theta"], s["l"], s["h"], s["W"]
    tow, shake, drive = model.loads
    distance = sp.sqrt((l * sp.sin(theta)) ** 2 + (h + l * sp.cos(theta)) ** 2)
    assert _zero(tow.potential - W * distance)
    assert _zero(tow.generalized[0] + sp.diff(W * distance, theta))
    t = sp.Symbol("t", real=True)
    assert shake.potential is None
    assert _zero(shake.generalized[0] - s["F0"] * sp.cos(s["w"] * t) * l * sp.cos(theta))
    assert _zero(drive.potential + s["M0"] * theta) and drive.generalized == (s["M0"],)
    assert free_forces(model) == shake.generalized
    assert model.depends_on_time()


TWO_DISKS = """\
parameters: {m1: mass, m2: mass, r: radius, Q: couple}
coordinates: [a, b]
points: {O: [0, 0]}
bodies:
  one: {shape: disk, mass: m1, radius: r, at: O, angle: a}
  two: {shape: disk, mass: m2, radius: r, at: O, angle: b}
couples:
  motor: {on: two, by: one, moment: Q}
questions: [eom]
"""


def test_a_motor_between_two_bodies() -> None:
    """Q on disk two, −Q on disk one: power Q (ḃ − ȧ), V = −Q (b − a)."""
    model = build_model(load_text(TWO_DISKS, "d.yaml"))
    s = _symbols(model)
    (motor,) = model.loads
    assert motor.generalized == (-s["Q"], s["Q"])
    assert _zero(motor.potential + s["Q"] * (s["b"] - s["a"]))


def test_body_points_move_with_their_body() -> None:
    """The rod's own point B = G + R(θ) (0, −l/2): l (sin θ, −cos θ); the body's name is
    its origin, G."""
    model = build_model(load_text(ROD, "rod.yaml"))
    s = _symbols(model)
    theta, l = s["theta"], s["l"]
    assert _zero(model.point("B") - sp.Matrix([l * sp.sin(theta), -l * sp.cos(theta), 0]))
    assert _zero(model.point("rod") - sp.Matrix([l * sp.sin(theta) / 2, -l * sp.cos(theta) / 2, 0]))
    assert "B" not in model.points  # the file's points stay the file's


def test_a_body_at_another_body_s_point() -> None:
    """problems/forces/motor-on-pendulum.yaml: the disk sits at the rod's end A, so the
    disk's origin (its name) is A = l (sin θ, −cos θ), read through A's own fold."""
    model = build_model(load_file(PROBLEMS / "forces" / "motor-on-pendulum.yaml"))
    s = _symbols(model)
    end = sp.Matrix([s["l"] * sp.sin(s["theta"]), -s["l"] * sp.cos(s["theta"]), 0])
    assert _zero(model.point("disk") - end) and _zero(model.point("A") - end)
