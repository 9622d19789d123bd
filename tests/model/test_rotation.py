"""Turn by turn: a sequence's angular velocity and a body's inertia in scene axes,
against Ṙ Rᵀ = [ω]× and R J Rᵀ multiplied out (Goldstein, ch. 4.8)."""

from __future__ import annotations

import random

import pytest
import sympy as sp

from rbdsolve.model.build import build_model
from rbdsolve.model.energies.energy import kinetic_energy
from rbdsolve.model.rotation import sequence_rotation, turns_angular_velocity, turns_conjugate, unit_turns, vee
from rbdsolve.model.state import State, t
from rbdsolve.problem import load_text

AXES = {"x": sp.Matrix([1, 0, 0]), "y": sp.Matrix([0, 1, 0]), "z": sp.Matrix([0, 0, 1]),
        "d": sp.Matrix([1, 2, 2])}


@pytest.mark.parametrize("sequence", [("z", "x", "z"), ("x", "y", "z"), ("d", "z"), ("y", "d", "x", "z")])
def test_turn_by_turn_agrees_with_the_rotation_multiplied_out(sequence) -> None:
    state = State.of(tuple(f"q{k}" for k in range(len(sequence))))
    s = sp.Symbol("s", positive=True)
    angles = [q + (s * t if k == len(sequence) - 1 else 0) for k, q in enumerate(state.q)]
    turns = unit_turns([(AXES[a], angle) for a, angle in zip(sequence, angles)])
    R = sequence_rotation([(AXES[a], angle) for a, angle in zip(sequence, angles)])
    J = sp.Matrix([[3, 1, 0], [1, 2, sp.Rational(1, 2)], [0, sp.Rational(1, 2), 5]])
    omega = turns_angular_velocity(turns, state)
    rng = random.Random(len(sequence))
    at = {x: sp.Rational(rng.randint(-300, 300), 100) for x in (*state.q, *state.qd)}
    at |= {t: sp.Rational(7, 10), s: sp.Rational(13, 10)}
    # the reference multiplied out at the point, in 30 digits (the same products, and
    # seconds less than multiplying the symbolic matrices out first)
    R_at, dR_at = (M.xreplace(at).evalf(30) for M in (R, state.d_dt(R)))
    reference = vee(dR_at * R_at.T)
    assert max(abs(sp.N(omega[i].xreplace(at), 30) - reference[i]) for i in range(3)) < 1e-25
    inertia = turns_conjugate(turns, J)
    multiplied = R_at * J * R_at.T
    assert max(abs(sp.N(inertia[i].xreplace(at), 30) - multiplied[i]) for i in range(9)) < 1e-25


def test_a_spin_about_an_axis_of_symmetry_leaves_no_t_in_T() -> None:
    """A top tilted by a, b and spun at the constant rate s about its axis: with
    J = diag(A', A', C) about G (A' = A − m h²) and G = h e₃, by hand
    T = ½ A (ȧ² cos²b + ḃ²) + ½ C (s + ȧ sin b)², t-free."""
    text = """
parameters: {m: mass, h: length, A: inertia, C: inertia, s: spin rate}
coordinates: [a, b]
triads:
  T: {turns: [[x, a], [y, b], [z, s*t]], vectors: [e1, e2, e3]}
points:
  G: h*e3
bodies:
  top: {mass: m, inertia: [A - m*h**2, A - m*h**2, C], at: G, orientation: [T]}
questions: [eom]
"""
    model = build_model(load_text(text, "top.yaml"))
    (_, b), (da, db) = model.q, model.qd
    A, C, s = (model.symbols.parameters[n] for n in ("A", "C", "s"))
    T = kinetic_energy(model).total
    expected = A * (da**2 * sp.cos(b) ** 2 + db**2) / 2 + C * (s + da * sp.sin(b)) ** 2 / 2
    assert not T.has(t)
    assert sp.simplify(T - expected) == 0
    assert not model.depends_on_time()
