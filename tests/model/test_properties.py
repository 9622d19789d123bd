"""Property tests on random planar chains of bodies (hypothesis).

Each chain hangs from O: link i turns by q_i, its joint P_i = P_(i-1) + l_i e(q_i), and
its body (a random shape) sits at the link's midpoint or end. For every such scene:

* M(q) is positive definite at a random configuration (it is symmetric by construction);
* T = ½ q̇ᵀ M(q) q̇ exactly: the energy built body by body (½ m v·v + ½ ω·Jω) and the
  mass matrix built from the velocity Jacobians agree.
"""

from __future__ import annotations

import numpy as np
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from rbdsolve.model.build import build_model
from rbdsolve.model.energies.energy import kinetic_energy, mass_matrix
from rbdsolve.problem import load_text

SHAPES = {
    "particle": "",
    "rod": ", length: {a}",
    "ring": ", radius: {a}",
    "disk": ", radius: {a}",
    "plate": ", width: {a}, height: {b}",
}
positive = st.integers(min_value=1, max_value=9)


@st.composite
def chains(draw):
    n = draw(st.integers(min_value=1, max_value=3))
    points, bodies = ["  P0: [0, 0]"], []
    for i in range(1, n + 1):
        length = draw(positive)
        points.append(f"  P{i}: P{i - 1} + {length}/2 * [sin(q{i}), -cos(q{i})]")
        shape = draw(st.sampled_from(sorted(SHAPES)))
        at = draw(st.sampled_from(["mid", "end"]))
        where = f"(P{i - 1} + P{i})/2" if at == "mid" else f"P{i}"
        dims = SHAPES[shape].format(a=draw(positive), b=draw(positive))
        bodies.append(f"  b{i}: {{shape: {shape}, mass: {draw(positive)}*m, at: '{where}', angle: q{i}{dims}}}")
    text = "\n".join([
        "parameters: {m: mass}",
        f"coordinates: [{', '.join(f'q{i}' for i in range(1, n + 1))}]",
        "points:", *points, "bodies:", *bodies, "questions: [eom]",
    ])
    angles = [draw(st.integers(min_value=-6, max_value=6)) for _ in range(n)]
    return text, angles


@settings(max_examples=25, deadline=None)
@given(chains())
def test_mass_matrix_is_symmetric_positive_definite(chain) -> None:
    text, angles = chain
    model = build_model(load_text(text, "chain.yaml"))
    at = {q: sp.Rational(a, 3) for q, a in zip(model.q, angles)}
    M = mass_matrix(model, at)
    numeric = np.array(M.subs({model.symbols.parameters["m"]: 1}).evalf(), dtype=float)
    assert np.linalg.eigvalsh(numeric).min() > 1e-9


@settings(max_examples=15, deadline=None)
@given(chains())
def test_kinetic_energy_is_half_qdot_M_qdot(chain) -> None:
    text, _ = chain
    model = build_model(load_text(text, "chain.yaml"))
    qd = sp.Matrix(model.qd)
    quadratic = (qd.T * mass_matrix(model) * qd)[0, 0] / 2
    assert sp.simplify(kinetic_energy(model).total - quadratic) == 0
