"""A singular mass matrix, detected and said in words.

T = ½ q̇ᵀ M q̇ with M positive semidefinite, so T = 0 for a rate q̇ = a ≠ 0 exactly when
M a = 0: a motion along a moves no mass. Then Lagrange's equations cannot be solved
for the accelerations (M q̈ = … has no unique solution), small oscillations have no
eigenproblem (det(K − λM) drops degree) and the impulse equations M Δq̇ = I of an
impact have no unique solution. Two causes, told apart by the null vector a:

- a has one nonzero entry: that coordinate moves no mass (it moves only massless
  points, e.g. the junction of two springs in series, or bodies of zero mass);
- a has several: the coordinates move the masses only together (redundant
  coordinates, e.g. x and y that enter the scene only as x + y), or that combination
  moves only massless points.

Exact matrices: the null space over sympy's field (``exact_reason``). Float matrices:
the eigenvectors of the symmetric M whose eigenvalue is within n ε ‖M‖₂ of zero, its
rounding (Golub & Van Loan, Matrix Computations, §8.1: Weyl's bound), as
``float_reason`` finds. The model's M(q) at every configuration (``generic_reason``):
M at a random configuration and sample parameter values, in 30-digit arithmetic
(mpmath), singular when λ_min(M) < 1e-20 λ_max(M) there: M(q) is analytic in q, so a
matrix singular at a random point is singular everywhere (with probability 1), and a
regular one is far from 1e-20 there.
"""

from __future__ import annotations

import random
from typing import TYPE_CHECKING, Sequence

import sympy as sp
from sympy.polys.matrices import DomainMatrix

from rbdsolve.form.printers import to_unicode
from rbdsolve.model.build import Model
from rbdsolve.model.energies.energy import mass_matrix

if TYPE_CHECKING:  # numpy is imported where floats are used: the exact routes need none
    import numpy as np

EPS = 2.0**-52  # binary64's machine epsilon
GENERIC_DIGITS = 30
GENERIC_TOL = 1e-20
SEED = 20151029  # a fixed sample: the same verdict every run


def describe(vectors: Sequence[Sequence[str]], names: Sequence[str], where: str) -> str:
    """The reason, from null vectors given as their entries' texts ('0' for zero)."""
    parts = []
    for a in vectors:
        moving = [n for n, x in zip(names, a) if x != "0"]
        if len(moving) == 1:
            parts.append(f"the coordinate {moving[0]} moves no mass (only massless points, or bodies of zero mass)")
        else:
            shown = ", ".join(x.replace("-", "−") for x in a)  # a float's sign as the printer writes it
            parts.append(f"the motion q̇ ∝ ({shown}) of ({', '.join(names)}) moves no mass: "
                         f"{', '.join(moving)} are redundant (they move the masses only together, as x and y in "
                         "x + y) or that motion moves only massless points")
    return f"the mass matrix is singular {where}: " + "; ".join(parts)


def exact_reason(M: sp.Matrix, names: Sequence[str], where: str) -> str | None:
    """None when M is regular, else the reason (exact null space). The determinant is
    taken over the ring of M's entries (DomainMatrix: fraction-free, fast on the
    polynomials in the parameters that M at a configuration usually holds)."""
    ring = DomainMatrix.from_Matrix(sp.Matrix(M))
    if not ring.domain.is_zero(ring.det()):
        return None
    null = sp.Matrix(M).nullspace(simplify=True)
    texts = []
    for v in null:
        first = next(x for x in v if x != 0)
        texts.append([to_unicode(sp.simplify(x / first)) for x in v])
    return describe(texts, names, where)


def float_reason(M: np.ndarray, names: Sequence[str], where: str) -> str | None:
    """None when every eigenvalue of M exceeds n ε ‖M‖₂, else the reason, naming the
    eigenvectors of the eigenvalues below it (zero within rounding)."""
    import numpy as np

    M = np.asarray(M, dtype=float)
    if not np.all(np.isfinite(M)):
        return None  # not this module's to diagnose
    lam, vectors = np.linalg.eigh((M + M.T) / 2)
    bound = len(M) * EPS * max(np.max(np.abs(lam)), np.finfo(float).tiny)
    small = [vectors[:, i] for i in range(len(lam)) if lam[i] <= bound]
    if not small:
        return None
    return describe([_texts(v) for v in small], names,
                    f"in floating point {where} (an eigenvalue within its rounding n ε ‖M‖₂ = {bound:.2g} of 0)")


def _texts(v: Sequence[float]) -> list[str]:
    """Entries scaled so the largest is 1, rounded to 4 digits; round-off shows as 0."""
    import numpy as np

    v = np.asarray(v, dtype=float)
    v = v / v[np.argmax(np.abs(v))]
    return ["0" if abs(x) < 1e-9 else f"{x:.4g}" for x in v]


def generic_reason(model: Model, M: sp.Matrix | None = None) -> str | None:
    """The reason M(q) is singular at every configuration, or None (regular at a random
    one, or not a number there: a prescribed function of time in the Jacobians). ``M``:
    M(q) already in hand (∂E/∂q̈ of Lagrange's equations), else built at the sample
    (tidying its entries there costs more than the test: ~15 ms on a seed problem)."""
    import mpmath

    rng = random.Random(SEED)
    sample = {q: sp.Rational(rng.randint(100, 900), 1000) for q in model.q}
    for s in model.symbols.parameters.values():
        sample[s] = model.values.get(s, sp.Rational(rng.randint(500, 2000), 1000))
    M = (mass_matrix(model, sample) if M is None else M).xreplace(sample)
    if M.free_symbols or any(x.has(sp.Function) and not x.is_number for x in M):
        return None
    with mpmath.workdps(GENERIC_DIGITS):
        A = mpmath.matrix([[mpmath.mpf(sp.N(x, GENERIC_DIGITS)) for x in row] for row in M.tolist()])
        lam, vectors = mpmath.eigsy(A)
        big = max(abs(x) for x in lam)
        small = [i for i in range(len(lam)) if abs(lam[i]) <= GENERIC_TOL * max(big, mpmath.mpf(1e-300))]
        vecs = [[float(vectors[r, i]) for r in range(len(lam))] for i in small]
    if not small:
        return None
    return describe([_texts(v) for v in vecs], model.coordinate_names(), "at every configuration")


def eom_warnings(model: Model, M: sp.Matrix | None = None) -> tuple[str, ...]:
    """Lagrange's equations are right even with a singular M, but cannot be solved for
    the accelerations: both eom routes say so (``M``: as for ``generic_reason``)."""
    singular = generic_reason(model, M)
    return (f"{singular}: these equations cannot be solved for the accelerations",) if singular else ()
