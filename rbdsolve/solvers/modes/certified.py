"""Certified decimals for the roots a reader cannot use as formulas.

An irreducible factor of degree ≥ 5 of det(K̂ − μM̂) has no formula in radicals in
general, and sympy's CRootOf(f, k) is exact but unreadable (and its mode shapes, built
from it, fill megabytes). Such roots are given as decimals every digit of which is
proven, with ball arithmetic (Arb, through python-flint):

- the roots: ``fmpz_poly.complex_roots`` encloses each root of f in a ball that is
  proven to hold exactly one root (Johansson, "Arb: efficient arbitrary-precision
  midpoint-radius interval arithmetic", IEEE Trans. Comput. 66, 2017); a ball with an
  imaginary part of exactly 0 is proven real. K̂ symmetric and M̂ positive definite make
  every root real (Parlett, The Symmetric Eigenvalue Problem, §15.3), so a ball that is
  not is an inconsistency, and the factor is left exact;
- the mode shape of a root μ: with its first entry 1, the others solve the last n − 1
  rows of (K̂ − μM̂) a = 0, (K̂ − μM̂)[1:, 1:] a' = −(K̂ − μM̂)[1:, 0], solved in ball
  arithmetic (``arb_mat.solve``) with μ's ball: the result encloses the true shape;
- the printed decimal: each ball [x − r, x + r] is rounded at both ends to ``digits``
  significant digits (Python's decimal module, correctly rounded); when both ends round
  to the same decimal, so does every number in the ball, and that decimal is the root
  correctly rounded. Otherwise the working precision doubles, up to MAX_BITS.

A root or shape that cannot be certified so (a true zero entry, whose ball always
contains 0; a first entry that is 0) is not given in decimals: ``certified_roots``
returns None and the caller keeps the exact route (CRootOf).
"""

from __future__ import annotations

from dataclasses import dataclass
from decimal import ROUND_HALF_EVEN, Decimal, localcontext
from fractions import Fraction

import sympy as sp

DIGITS = 15  # significant digits of every certified decimal (a binary64's worth)
START_BITS = 128
MAX_BITS = 4096


@dataclass(frozen=True)
class CertifiedRoot:
    """A real root μ of an irreducible factor, its √|μ| and its mode shape, each a
    decimal correctly rounded to ``digits`` significant digits (proven)."""

    value: sp.Float
    root: sp.Float  # √μ for μ > 0 (the frequency's), √(−μ) for μ < 0 (the growth rate's)
    shape: tuple[sp.Expr, ...]  # first entry 1 (exact), the others Floats
    digits: int


def certified_roots(factor: sp.Poly, K: sp.Matrix, M: sp.Matrix,
                    digits: int = DIGITS) -> list[CertifiedRoot] | None:
    """Every root of ``factor`` (irreducible over QQ, a factor of det(K − μM), K and M
    rational) with its mode shape, certified to ``digits`` digits, ascending; None
    where one of them cannot be certified (see the module's docstring)."""
    import flint

    integer = flint.fmpz_poly([int(c) for c in reversed(_integral(factor).all_coeffs())])
    bits = START_BITS
    while bits <= MAX_BITS:
        with flint.ctx.workprec(bits):
            found = _at_precision(integer, _arb_matrix(K), _arb_matrix(M), digits)
        if found is not _FINER:
            return found
        bits *= 2
    return None


_FINER = object()  # the balls are too wide to round: try again at a higher precision


def _at_precision(integer, K, M, digits: int):
    """The certified roots at the context's precision, None if a root is not proven
    real or a shape not determined by its first entry, _FINER if a ball is too wide."""
    out = []
    for ball, _ in integer.complex_roots():
        if not ball.imag.is_zero():
            return None
        mu = ball.real
        if mu.contains(0):  # an irreducible factor of degree > 1 has no root 0: a finer ball excludes it
            return _FINER
        shape = _shape(K, M, mu)
        if shape is None:
            return None
        rounded = [_rounded(x, digits) for x in (mu, abs(mu).sqrt(), *shape)]
        if any(r is None for r in rounded):
            return _FINER if all(_decided(x) for x in (mu, *shape)) else None
        value, root, *rest = rounded
        out.append(CertifiedRoot(value, root, (sp.Integer(1), *rest), digits))
    return sorted(out, key=lambda r: r.value)


def _shape(K, M, mu):
    """The entries 2..n of the mode shape with first entry 1, as balls; None if the
    system for them is not proven regular (the first entry may be 0)."""
    import flint

    n = K.nrows()
    if n == 1:
        return []
    A = K - mu * M
    rest = flint.arb_mat(n - 1, n - 1, [A[i, j] for i in range(1, n) for j in range(1, n)])
    rhs = flint.arb_mat(n - 1, 1, [-A[i, 0] for i in range(1, n)])
    try:
        solved = rest.solve(rhs)
    except ZeroDivisionError:  # python-flint: the matrix is not proven invertible
        return None
    return [solved[i, 0] for i in range(n - 1)]


def _decided(x) -> bool:
    """Whether a ball excludes 0: more precision will then round it (a ball holding 0
    may be a true zero, which no precision rounds)."""
    return not x.contains(0)


def _rounded(x, digits: int) -> sp.Float | None:
    """The decimal to which every number of the ball x rounds at ``digits`` significant
    digits (round half to even), or None where its ends round differently."""
    mid, radius = _dyadic(x.mid()), _dyadic(x.rad())
    if mid == 0:
        return None
    low, high = (_decimal(mid - radius, digits), _decimal(mid + radius, digits))
    if low != high:
        return None
    return sp.Float(str(low), digits)


def _decimal(q: Fraction, digits: int) -> Decimal:
    """q correctly rounded to ``digits`` significant digits (a decimal quotient is)."""
    with localcontext() as context:
        context.prec, context.rounding = digits, ROUND_HALF_EVEN
        return context.divide(Decimal(q.numerator), Decimal(q.denominator))


def _dyadic(exact) -> Fraction:
    """An exact arb (a midpoint or radius) as a fraction m·2^e."""
    mantissa, exponent = (int(v) for v in exact.man_exp())
    return Fraction(mantissa) * Fraction(2) ** exponent


def _integral(factor: sp.Poly) -> sp.Poly:
    """The factor with integer coefficients (the same roots)."""
    _, primitive = factor.clear_denoms(convert=True)
    return primitive


def _arb_matrix(A: sp.Matrix):
    import flint

    return flint.arb_mat(A.rows, A.cols, [flint.fmpq(int(x.p), int(x.q)) for x in A])
