"""The rolling condition is a step of the solution, as a worked solution writes it: for
each planar contact under problems/contacts/, the step's relation between the rates is
the one derived by hand (below, each = 0, up to a constant factor), and the command line
prints it in the model section."""

from __future__ import annotations

import sympy as sp
import pytest
from click.testing import CliRunner

from rbdsolve.cli import main
from rbdsolve.model.build import build_model
from rbdsolve.problem import load_file
from rbdsolve.model.summary.summary import rolling_steps

from conftest import PROBLEMS

R, r = sp.symbols("R r", positive=True)
d = {n: sp.Symbol(f"d_{n}") for n in ("theta", "x", "y", "s", "psi", "l_S", "s_C")}
phi = sp.Symbol("d_phi")  # the rolling body's turn rate, φ̇
# by hand: the body's point at C at rest (or moving with the surface), v_G + φ̇ e_z × (C − G)
HAND = {
    ("cylinder-in-cylinder", "C"): r * phi + (R - r) * d["theta"],  # centre on R − r: (R − r) θ̇ = −r φ̇
    ("ball-in-bowl", "C"): r * phi + (R - r) * d["theta"],
    ("ring-on-drum", "C"): r * phi - (R + r) * d["theta"],  # outside: the ring turns with the line of centres
    ("wheel-on-incline", "C"): r * phi + d["x"],  # clockwise as it rolls down: r φ̇ = −ẋ
    ("yo-yo", "S"): r * phi + d["y"],
    ("cylinder-on-plank", "C"): r * phi + d["s"],  # relative to the plank
    ("cylinder-pulley-block", "C"): r * phi + d["x"],
    ("cylinder-pulley-block", "S"): d["l_S"] - 2 * d["x"],  # the top of a rolling wheel goes at 2ẋ
    ("disk-on-turning-disk", "C"): r * (phi - d["psi"]) - (R + r) * (d["theta"] - d["psi"]),
    ("half-disk-rocking", "C"): d["s_C"] + R * d["theta"],  # C travels back as the body turns: s = −R θ
    ("slab-on-drum", "C"): d["s_C"] + R * d["theta"],  # the arc R θ laid off along the slab
}


def _rates(expr: sp.Expr) -> sp.Expr:
    """Each q̇(t) as a symbol d_q (a rolling body's turn φ_body as d_phi)."""
    out = expr
    for der in expr.atoms(sp.Derivative):
        name = der.expr.func.__name__
        out = out.xreplace({der: phi if name.startswith("phi_") else sp.Symbol(f"d_{name}")})
    return out.xreplace({s: sp.Symbol(s.name, positive=True) for s in out.free_symbols if s.name in ("R", "r")})


@pytest.mark.parametrize("scene", sorted({s for s, _ in HAND}))
def test_the_rolling_step_is_the_hand_relation(scene: str) -> None:
    model = build_model(load_file(PROBLEMS / "contacts" / f"{scene}.yaml"))
    steps = [s for s in rolling_steps(model) if s.math]  # the notes (R > r assumed) have none
    assert len(steps) == sum(s == scene for s, _ in HAND)
    for c, step in zip(model.contacts, steps):
        assert f" at {c.name} " in step.text and ("v_" in step.text or "String" in step.text)
        shown = step.math[0]
        ratio = sp.simplify(_rates(shown.lhs - shown.rhs) / HAND[(scene, c.name)])
        assert ratio.is_number and ratio != 0, (scene, c.name, shown.lhs, shown.rhs)


def test_the_solution_prints_the_rolling_condition() -> None:
    result = CliRunner().invoke(main, ["solve", str(PROBLEMS / "contacts" / "wheel-on-incline.yaml")])
    assert result.exit_code == 0, result.output
    assert "Rolling without slipping at C (wheel on the line): v_C = 0 ⇒" in result.output
    assert "r φ̇_wheel = −ẋ" in result.output and "⇒ φ_wheel = −x/r" in result.output


def test_a_track_cut_in_a_body_is_named_as_a_circle() -> None:
    """A cylinder rolling inside a circle of radius R cut in a cart (rolls_on: {body: cart,
    radius: R, side: inside}) rolls on that circle's inside, not on "cart's axle" (a new
    user's cart with a track)."""
    text = (PROBLEMS / "forces" / "pendulum-on-sliding-cart.yaml").read_text(encoding="utf-8").split("points:")[0]
    text = text.replace("parameters:", "parameters:\n  R: track\n  r: radius")
    text += ("points:\n  O: [x, R]\nbodies:\n  cart: {mass: M, inertia: M*R**2, at: O}\n"
             "  cylinder: {shape: cylinder, mass: m, radius: r, height: r}\ncontacts:\n"
             "  C: {body: cylinder, rolls_on: {body: cart, radius: R, side: inside}, along: theta}\n"
             "questions:\n  - eom\n")
    from rbdsolve.problem import load_text

    (step,) = [s for s in rolling_steps(build_model(load_text(text, "p.yaml"))) if s.math]
    assert "(cylinder on the inside of cart's circle of radius R)" in step.text
