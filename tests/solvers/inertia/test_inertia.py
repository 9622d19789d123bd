"""The inertia question: invariants on random composite bodies, and its options."""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from rbdsolve.errors import InputError
from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.solvers import solve_problem

SHAPES = {
    "sphere": "radius: {a}",
    "box": "width: {a}, depth: {b}, height: {c}",
    "cylinder": "radius: {a}, height: {b}",
    "cone": "radius: {a}, height: {b}",
    "rod": "length: {a}",
    "triangle": "base: {a}, height: {b}, apex: {c}",
}
small = st.integers(min_value=1, max_value=5)


@st.composite
def bodies(draw):
    parts = []
    for i in range(draw(st.integers(min_value=1, max_value=3))):
        shape = draw(st.sampled_from(sorted(SHAPES)))
        dims = SHAPES[shape].format(a=draw(small), b=draw(small), c=draw(small))
        at = [draw(st.integers(-3, 3)) for _ in range(3)]
        axis = [draw(st.integers(-2, 2)) for _ in range(3)]
        axis_text = f", axis: {axis}" if any(axis) else ""
        parts.append(f"      p{i}: {{shape: {shape}, mass: {draw(small)}*m, {dims}, at: {at}{axis_text}}}")
    point = [draw(st.integers(-2, 2)) for _ in range(3)]
    return "\n".join([
        "parameters: {m: mass}",
        "bodies:", "  b:", "    at: [0, 0, 0]", "    parts:", *parts,
        f"questions:\n  - inertia: {{about: {point}}}",
    ])


@settings(max_examples=6, deadline=None)
@given(bodies())
def test_principal_axes_are_orthonormal_eigenvectors(text: str) -> None:
    result = solve_problem(build_model(load_text(text, "b.yaml"))).solutions[0]
    assert result.solved, result.error
    a = result.answers
    assert sp.Matrix(a.J) == sp.Matrix(a.J).T
    m = sp.Symbol("m", positive=True)

    def number(x: sp.Expr) -> complex:
        return complex(sp.N(sp.sympify(x).subs(m, 1), 30))

    J = np.array([[number(x) for x in row] for row in sp.Matrix(a.J).tolist()])
    moments = np.array([number(x) for x in a.principal_moments])
    E = np.array([[number(x) for x in v] for v in a.principal_axes]).T  # columns: the axes
    assert np.abs(moments.imag).max() < 1e-9 and np.abs(E.imag).max() < 1e-9
    scale = max(1.0, np.abs(J).max())
    assert np.abs(J @ E - E * moments).max() < 1e-9 * scale  # J e = λ e
    assert np.abs(E.T @ E - np.eye(3)).max() < 1e-9  # orthonormal
    J1, J2, J3 = moments.real
    assert J1 <= J2 + 1e-9 * scale and J2 <= J3 + 1e-9 * scale  # ascending
    assert J1 + J2 >= J3 - 1e-9 * scale and J1 >= -1e-9 * scale  # a physical tensor


def test_parallel_axis_round_trip() -> None:
    # J about a point P, then back to G by the same theorem, gives J_G again.
    text = """
parameters: {m: mass, a: size}
points: {P: [a, 2*a, -a]}
bodies:
  b: {shape: box, mass: m, width: a, depth: 2*a, height: 3*a, at: [0, 0, 0], axis: [1, 1, 1]}
questions:
  - inertia: {about: P}
"""
    a = solve_problem(build_model(load_text(text, "b.yaml"))).solutions[0].answers
    d = sp.Matrix(a.centre) - sp.Matrix(a.about)
    m = sp.Symbol("m", positive=True)
    back = sp.Matrix(a.J) - m * (d.dot(d) * sp.eye(3) - d * d.T)
    assert (back - sp.Matrix(a.J_G)).applyfunc(sp.simplify) == sp.zeros(3, 3)


def test_a_rotated_frame() -> None:
    # A rod along x seen from axes turned 90° about z: its zero moment moves to y'.
    text = """
parameters: {m: mass, L: length}
bodies:
  rod: {shape: rod, mass: m, length: L, at: [0, 0, 0]}
questions:
  - inertia: {axes: [[0, 1, 0], [-1, 0, 0], [0, 0, 1]]}
"""
    a = solve_problem(build_model(load_text(text, "r.yaml"))).solutions[0].answers
    m, L = sp.symbols("m L", positive=True)
    assert sp.Matrix(a.J) == sp.diag(m * L**2 / 12, 0, m * L**2 / 12)


@pytest.mark.parametrize(
    "question, words",
    [
        ("inertia: {body: rood}", "no body 'rood' (did you mean 'rod'?)"),
        ("inertia: {axes: [[1, 0, 0], [0, 1, 0]]}", "three axis vectors"),
        ("inertia: {about: Q}", "unknown point 'Q'"),
        ("inertia: {abut: O}", "unknown key 'abut' in question 'inertia' (did you mean 'about'?)"),
    ],
)
def test_bad_inertia_options(question: str, words: str) -> None:
    text = f"""
parameters: {{m: mass, L: length}}
points: {{O: [0, 0, 0]}}
bodies:
  rod: {{shape: rod, mass: m, length: L, at: O}}
questions:
  - {question}
"""
    with pytest.raises(InputError, match=words.replace("(", r"\(").replace(")", r"\)").replace("?", r"\?")):
        load_text(text, "r.yaml")


def test_frame_axes_must_be_orthonormal() -> None:
    text = """
parameters: {m: mass, L: length}
bodies:
  rod: {shape: rod, mass: m, length: L, at: [0, 0, 0]}
questions:
  - inertia: {axes: [[1, 1, 0], [0, 1, 0], [0, 0, 1]]}
"""
    result = solve_problem(build_model(load_text(text, "r.yaml"))).solutions[0]
    assert not result.solved
    assert "r.yaml:6:" in result.error and "orthonormal" in result.error


def test_parts_errors() -> None:
    base = """
parameters: {m: mass, a: size}
bodies:
  b:
    at: [0, 0, 0]
    parts:
{parts}
questions: [inertia]
"""
    with pytest.raises(InputError, match="all holes"):
        load_text(base.replace("{parts}", "      h: {shape: sphere, mass: m, radius: a, hole: true}"), "b.yaml")
    with pytest.raises(InputError, match="unknown key 'colour'"):
        load_text(base.replace("{parts}", "      p: {shape: sphere, mass: m, radius: a, colour: red}"), "b.yaml")
    with pytest.raises(InputError, match="a part's position in its body must be constant"):
        load_text(base.replace("{parts}", "      p: {shape: sphere, mass: m, radius: a, at: [t, 0, 0]}"), "b.yaml")
