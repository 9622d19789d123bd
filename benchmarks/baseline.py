"""The way a sympy user gets the modes of an n-link pendulum chain today, written from
scratch with sympy.physics.mechanics: the chain of point masses (m on links l, angles
th1..thn from the downward vertical, gravity g), its equations of motion by
LagrangesMethod or KanesMethod, their Linearizer at the hanging state (A_and_B=True:
x' = A x with x = (q, q')), and the eigenvalues λ = ω² of the linearized system.

The parameters stay symbols through the linearization (as a user would write it) and
are replaced by the benchmark's values (m = l = 1, g = 981/100) afterwards. Then:

- exact: the characteristic polynomial of the block  −A[q', q] = M⁻¹K  over the
  rationals and its roots (CRootOf), the same question rbdsolve's exact route answers;
- numeric: numpy.linalg.eigvals of that block as floats (fairness: a user may stop there).

Run one size in its own process (the benchmark does, with a timeout):

    python3 -m benchmarks.baseline lagrange 5     # prints one JSON line

It prints the seconds of each phase (equations, linearize, exact eigenvalues, numeric
eigenvalues) measured with time.perf_counter, and the eigenvalues as strings.
"""

from __future__ import annotations

import json
import sys
import time

METHODS = ("lagrange", "kane")


def _chain(n: int):
    """Frame, coordinates, speeds, particles and the symbols m, l, g of the chain."""
    import sympy as sp
    import sympy.physics.mechanics as me

    m, l, g = sp.symbols("m l g", positive=True)
    q = me.dynamicsymbols(f"th1:{n + 1}")
    N = me.ReferenceFrame("N")
    O = me.Point("O")
    O.set_vel(N, 0)
    particles, previous = [], O
    for i in range(n):
        P = previous.locatenew(f"P{i + 1}", l * (sp.sin(q[i]) * N.x - sp.cos(q[i]) * N.y))
        P.set_vel(N, P.pos_from(O).dt(N))
        bob = me.Particle(f"bob{i + 1}", P, m)
        bob.potential_energy = m * g * P.pos_from(O).dot(N.y)
        particles.append(bob)
        previous = P
    return N, q, particles, (m, l, g)


def lagrange_A(n: int):
    """A of x' = A x by LagrangesMethod + linearize; returns (A, symbols, seconds of the
    equations, seconds of the linearization)."""
    import sympy.physics.mechanics as me

    start = time.perf_counter()
    N, q, particles, symbols = _chain(n)
    L = me.Lagrangian(N, *particles)
    method = me.LagrangesMethod(L, q)
    method.form_lagranges_equations()
    equations = time.perf_counter()
    qd = [x.diff() for x in q]
    op = {x: 0 for x in q} | {x: 0 for x in qd} | {x.diff(): 0 for x in qd}
    A, _, _ = method.linearize(q_ind=q, qd_ind=qd, op_point=op, A_and_B=True)
    return A, symbols, equations - start, time.perf_counter() - equations


def kane_A(n: int):
    """A of x' = A x by KanesMethod (u_i = th_i') + linearize; same return as lagrange_A."""
    import sympy.physics.mechanics as me

    start = time.perf_counter()
    N, q, particles, (m, l, g) = _chain(n)
    u = me.dynamicsymbols(f"u1:{n + 1}")
    for bob, x, v in zip(particles, q, u):
        bob.point.set_vel(N, bob.point.vel(N).subs({y.diff(): w for y, w in zip(q, u)}))
    forces = [(bob.point, -m * g * N.y) for bob in particles]
    kd = [x.diff() - v for x, v in zip(q, u)]
    method = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=kd)
    method.kanes_equations(particles, forces)
    equations = time.perf_counter()
    op = {x: 0 for x in q} | {x: 0 for x in u} | {x.diff(): 0 for x in u}
    A, _, _ = method.linearize(op_point=op, A_and_B=True)
    return A, (m, l, g), equations - start, time.perf_counter() - equations


def eigen_exact(A, symbols, n: int) -> tuple[list[str], float]:
    """λ of M⁻¹K = −A[n:, :n] with the values in: charpoly over QQ, then its roots."""
    import sympy as sp

    start = time.perf_counter()
    m, l, g = symbols
    block = -A[n:, :n].xreplace({m: 1, l: 1, g: sp.Rational(981, 100)})
    poly = block.charpoly(sp.Symbol("lamda"))
    roots = sp.Poly(poly.as_expr(), sp.Symbol("lamda")).all_roots()
    return [str(sp.N(r, 30)) for r in roots], time.perf_counter() - start


def eigen_numeric(A, symbols, n: int) -> tuple[list[float], float]:
    """λ of M⁻¹K as floats: numpy.linalg.eigvals after lambdify of the block."""
    import numpy as np
    import sympy as sp

    start = time.perf_counter()
    m, l, g = symbols
    f = sp.lambdify((m, l, g), -A[n:, :n], "numpy")
    lam = np.sort(np.linalg.eigvals(np.asarray(f(1.0, 1.0, 9.81), dtype=float)).real)
    return [float(x) for x in lam], time.perf_counter() - start


def run(method: str, n: int) -> dict:
    """All phases for one method and size; seconds per phase and the eigenvalues."""
    A, symbols, t_eq, t_lin = (lagrange_A if method == "lagrange" else kane_A)(n)
    exact, t_exact = eigen_exact(A, symbols, n)
    numeric, t_num = eigen_numeric(A, symbols, n)
    return {"method": method, "n": n, "equations": t_eq, "linearize": t_lin, "eigen_exact": t_exact,
            "eigen_numeric": t_num, "eigenvalues_exact": exact, "eigenvalues_numeric": numeric}


if __name__ == "__main__":
    print(json.dumps(run(sys.argv[1], int(sys.argv[2]))))
