"""The model section of a large model: T = ½ q̇ᵀ M(q) q̇ and V = ½ qᵀ K q as matrices.

Expected values by hand: the n-link pendulum of point masses m on links l has
M_ij(q) = m l² (n − max(i, j) + 1) cos(θᵢ − θⱼ) (i, j from 1; Goldstein §1.6 for n = 2);
n masses on a line joined by springs k, the first to a wall, have V = ½ qᵀ K q with
K = k tridiag(−1, 2, −1) and K_nn = k.
"""

from __future__ import annotations

import sympy as sp

from rbdsolve.form.display import Scaled, plain
from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.model.summary.large_energy import SCAN_TERMS
from rbdsolve.model.summary.summary import summarize_model

m, l, g, k = sp.symbols("m l g k", positive=True)


def chain(n: int) -> str:
    points = "\n".join(f"  P{i}: P{i - 1} + l * [sin(th{i}), -cos(th{i})]" for i in range(1, n + 1))
    bodies = "\n".join(f"  bob{i}: {{shape: particle, mass: m, at: P{i}}}" for i in range(1, n + 1))
    return (f"parameters: {{m: mass, l: length, g: acceleration}}\n"
            f"coordinates: [{', '.join(f'th{i}' for i in range(1, n + 1))}]\ngravity: [0, -g]\n"
            f"points:\n  P0: [0, 0]\n{points}\nbodies:\n{bodies}\nquestions: [eom]\n")


def springs(n: int) -> str:
    bodies = "\n".join(f"  b{i}: {{shape: particle, mass: m, at: [x{i}, 0]}}" for i in range(1, n + 1))
    links = "\n".join(f"  s{i}: {{stiffness: k, between: [[{f'x{i - 1}' if i > 1 else 0}, 0], [x{i}, 0]]}}"
                      for i in range(1, n + 1))
    return (f"parameters: {{m: mass, k: stiffness}}\ncoordinates: [{', '.join(f'x{i}' for i in range(1, n + 1))}]\n"
            f"bodies:\n{bodies}\nsprings:\n{links}\nquestions: [eom]\n")


def relation(summary, symbol: str):
    return next(r for s in summary.steps for r in s.math if str(r.lhs) == symbol)


def matrix_of(rhs) -> sp.Matrix:
    return sp.Matrix(rhs.inner) * rhs.factor if isinstance(rhs, Scaled) else sp.Matrix(rhs)


def test_a_chain_of_five_has_its_kinetic_energy_as_a_matrix() -> None:
    n = 5  # 15 products θ̇ᵢθ̇ⱼ > SCAN_TERMS
    model = build_model(load_text(chain(n), "chain.yaml"))
    summary = summarize_model(model)
    theta = model.state.functions()
    expected = sp.Matrix(n, n, lambda i, j: m * l**2 * (n - max(i, j)) * sp.cos(theta[i] - theta[j]))
    shown = matrix_of(relation(summary, "M(q)").rhs)
    assert (shown - expected).applyfunc(lambda x: sp.simplify(sp.expand_trig(x))) == sp.zeros(n, n)
    rates = sp.Matrix([sp.Derivative(f, model.state.functions()[0].args[0]) for f in theta])
    assert sp.simplify(sp.expand_trig(summary.T - (rates.T * expected * rates)[0] / 2)) == 0


def test_a_chain_of_four_is_written_body_by_body() -> None:
    summary = summarize_model(build_model(load_text(chain(4), "chain.yaml")))  # 10 products ≤ SCAN_TERMS
    assert not any(str(r.lhs) == "M(q)" for s in summary.steps for r in s.math)
    assert any(str(r.lhs) == "T_4" for s in summary.steps for r in s.math)


def test_a_long_spring_chain_has_its_potential_as_a_matrix() -> None:
    n = 8  # V expanded: 2n − 1 + n − 1 terms > SCAN_TERMS
    model = build_model(load_text(springs(n), "springs.yaml"))
    summary = summarize_model(model)
    expected = sp.Matrix(n, n, lambda i, j: 2 * k if i == j else -k if abs(i - j) == 1 else 0)
    expected[n - 1, n - 1] = k
    assert matrix_of(relation(summary, "K").rhs) == expected
    assert SCAN_TERMS == 12


def test_a_chain_of_seven_has_its_potential_as_one_sum() -> None:
    n = 7  # its bodies' V together: 1 + 2 + … + 7 = 28 terms > 2 SCAN_TERMS
    model = build_model(load_text(chain(n), "chain.yaml"))
    summary = summarize_model(model)
    assert not any(str(r.lhs) == "V_1" for s in summary.steps for r in s.math)
    theta = model.state.functions()
    expected = -m * g * l * sum((n - i) * sp.cos(theta[i]) for i in range(n))  # by hand
    shown = relation(summary, "V").rhs
    assert sp.expand(plain(shown) - expected) == 0
    assert sp.expand(summary.V - expected) == 0


def test_a_matrix_shown_over_q_of_t_keeps_its_factored_entries() -> None:
    """M(q) is put over q(t) before it is arranged, as substituting into M(q(t)) whole
    did: after factoring, 3/2 (1 + cos θ + cos φ) would be multiplied out again (a
    reviewer's case: an entry that is a number times a sum holding a coordinate)."""
    from rbdsolve.form.arrange import scaled_matrix
    from rbdsolve.form.printers import to_unicode
    from rbdsolve.model.summary.large_energy import in_time

    m, l, th, ph = sp.symbols("m l theta phi")
    t = sp.Symbol("t", real=True)
    timed = {th: sp.Function("theta")(t), ph: sp.Function("phi")(t)}
    M = sp.Matrix([[m * l**2 * (sp.Rational(3, 2) + sp.Rational(3, 2) * sp.cos(th) + sp.Rational(3, 2) * sp.cos(ph)),
                    m * l**2 * sp.cos(th - ph)], [m * l**2 * sp.cos(th - ph), m * l**2 / 3]])
    shown = to_unicode(scaled_matrix(in_time(M, lambda e: e.xreplace(timed)), {m, l}))
    assert shown == to_unicode(scaled_matrix(M.xreplace(timed), {m, l}))
    assert "3/2 (1 + cos(φ) + cos(θ))" in shown
