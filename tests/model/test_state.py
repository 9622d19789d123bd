"""model/state.py: the partial derivative of a matrix, entry by entry, and the total
time derivative built on it (the chain rule over q, q̇ and t)."""

from __future__ import annotations

import sympy as sp

from rbdsolve.model.state import State, partial, t


def test_a_matrix_is_differentiated_entry_by_entry() -> None:
    x, y = sp.symbols("x y")
    m = sp.Matrix([[x**2 * y, sp.sin(x)], [sp.exp(y), 3]])
    assert partial(m, x) == sp.Matrix([[2 * x * y, sp.cos(x)], [0, 0]])
    assert isinstance(partial(m, x), sp.MutableDenseMatrix)
    assert isinstance(partial(sp.ImmutableMatrix(m), y), sp.ImmutableDenseMatrix)
    assert partial(x**3, x) == 3 * x**2


def test_the_time_derivative_of_a_position() -> None:
    """r = (l sin q, −l cos q, t²): ṙ = (l cos q q̇, l sin q q̇, 2t) by hand."""
    state = State.of(("q",))
    (q,), (qd,) = state.q, state.qd
    length = sp.Symbol("l", positive=True)
    r = sp.Matrix([length * sp.sin(q), -length * sp.cos(q), t**2])
    expected = sp.Matrix([length * sp.cos(q) * qd, length * sp.sin(q) * qd, 2 * t])
    assert sp.simplify(state.d_dt(r) - expected) == sp.zeros(3, 1)
