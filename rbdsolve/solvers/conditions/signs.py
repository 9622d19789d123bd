"""Signs decided exactly: of one expression (from the parameters' assumptions, else
their given values) and of a symmetric matrix's eigenvalues (its inertia: how many
positive, zero and negative). Stability rests on these; what they cannot decide is
returned as ``Undecided`` with the expression, never guessed."""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from typing import Iterable, Mapping

import sympy as sp

from rbdsolve.form.quotient import quotient
from rbdsolve.form.tidy import square_root, tidy


@dataclass(frozen=True)
class Undecided:
    """A sign the decision could not make: the expression whose sign is unknown."""

    expr: sp.Expr  # the quantity whose sign could not be decided


@dataclass(frozen=True)
class Inertia:
    """Eigenvalue sign counts of a symmetric matrix. ``negative`` may be a lower bound
    (≥ 1) when a negative eigenvalue is proven without counting them all."""

    positive: int
    zero: int
    negative: int


def matrix_inertia(H: sp.Matrix, values: Mapping[sp.Symbol, sp.Expr]) -> Inertia | Undecided:
    """Eigenvalue sign counts of a symmetric matrix, decided exactly.

    Cheap exact tests first: a diagonal matrix shows its eigenvalues; positive leading
    principal minors prove positive definiteness (Sylvester's criterion); a negative
    diagonal entry eᵢᵀHeᵢ < 0 proves a negative eigenvalue. Otherwise Descartes' rule of
    signs on det(λI − H), exact because a symmetric matrix has real eigenvalues only.
    Parameter values, when given, decide signs the parameters' assumptions cannot.
    """
    n = H.rows
    if H.is_diagonal():
        signs = [sign_of(H[i, i], values) for i in range(n)]
        undecided = [x for x in signs if isinstance(x, Undecided)]
        if undecided and -1 not in signs:
            return undecided[0]
        return Inertia(signs.count(1), signs.count(0), max(signs.count(-1), 1) if undecided else signs.count(-1))
    if all(sign_of(tidy(H[:k, :k].det()), values) == 1 for k in range(1, n + 1)):
        return Inertia(n, 0, 0)
    if any(sign_of(H[i, i], values) == -1 for i in range(n)):
        return Inertia(0, 0, 1)
    lam = sp.Dummy("lambda")
    signs = [sign_of(tidy(c), values) for c in H.charpoly(lam).all_coeffs()]  # leading 1
    undecided = [x for x in signs if isinstance(x, Undecided)]
    if undecided:
        return undecided[0]
    zero = 0
    while signs and signs[-1] == 0:
        signs.pop()
        zero += 1
    nonzero = [x for x in signs if x != 0]
    positive = sum(1 for a, b in zip(nonzero, nonzero[1:]) if a != b)
    return Inertia(positive, zero, n - positive - zero)


def sign_of(value: sp.Expr, values: Mapping[sp.Symbol, sp.Expr]) -> int | Undecided:
    """−1, 0 or 1 if the parameters' signs decide it, or ``values``: numbers, or the
    substitutions of the problem's assumptions (``Model.decided_by``)."""
    sign = symbolic_sign(value)
    if sign is not None:
        return sign
    if values:
        number = value.xreplace(values)
        if number.is_number:
            z = complex(sp.N(number, 30))
            if abs(z.imag) > 1e-12 * max(1.0, abs(z.real)):
                return Undecided(value)  # not real at these values
            return 0 if z.real == 0 else (1 if z.real > 0 else -1)
        sign = symbolic_sign(number)  # an assumption's substitution, R = r + δ with δ > 0
        if sign is None:
            sign = coefficient_sign(number)  # the parameters left open, in numbers
        if sign is not None:
            return sign
    return Undecided(value)


def coefficient_sign(value: sp.Expr) -> int | None:
    """1 (−1) where value = P/Q, P and Q polynomials in positive symbols whose
    coefficients are numbers, each of P's and each of Q's of one sign (or zero): a sum
    of positive monomials is positive. The values given and one stiffness k left open:
    K = (3 − 2√2) √2 k/8 + 981/100 at an inverted rod's hanging position, whose terms
    sympy's assumptions see with mixed signs (3 k and −2√2 k). Each coefficient's sign
    from 30 digits, one within 10⁻²⁰ of zero deciding nothing."""
    symbols = value.free_symbols
    if not symbols or not all(x.is_positive for x in symbols):
        return None
    signs = [_coefficients_sign(part, sorted(symbols, key=sp.default_sort_key))
             for part in quotient(value)]
    if None in signs:
        return None
    return signs[0] * signs[1]


def _coefficients_sign(part: sp.Expr, symbols: list[sp.Symbol]) -> int | None:
    try:
        coefficients = sp.Poly(sp.expand(part), *symbols).coeffs()
    except sp.PolynomialError:  # a root or a function of the open parameters
        return None
    seen = set()
    for c in coefficients:
        if not c.is_number:
            return None
        z = complex(sp.N(c, 30))
        if abs(z.imag) > 1e-20 * max(1.0, abs(z.real)) or abs(z.real) < 1e-20:
            return None
        seen.add(1 if z.real > 0 else -1)
    return seen.pop() if len(seen) == 1 else None


def nonzero_where_defined(values: Iterable[sp.Expr]) -> dict[sp.Expr, sp.Dummy]:
    """Each factor f of the values' denominators, as a nonzero real stand-in: where f = 0
    the values are not defined (s = g cos α/(Ω² sin² α) is no point where sin α = 0), so
    a sign decided at them may take f ≠ 0, and f² > 0 (K = −m Ω² sin² α < 0 there).
    A factor whose sign is already decided, or that is not real, is left as it is."""
    found = {}
    for value in values:
        _, factors = sp.factor_list(sp.denom(sp.together(value)))
        for f, _ in factors:
            if f.free_symbols and f.is_real and symbolic_sign(f) is None:
                found[f] = sp.Dummy("f", real=True, nonzero=True)
    return found


def roots_where_defined(H: sp.Basic) -> dict[sp.Expr, sp.Dummy]:
    """Each square root √X (X^(k/2)) in H whose sign the parameters leave open, as a
    positive stand-in: H is a Hessian at an equilibrium that is real only where it
    exists, so every root in it is real there, and positive off the boundary X = 0 (a
    half-disk on an incline at sin θ₀ = −(3π/4) sin β: K = R g m √(16 − 9π² sin² β)/(3π)
    > 0 wherever the equilibrium exists)."""
    return {p: sp.Dummy("r", positive=True) for p in H.atoms(sp.Pow)
            if square_root(p) and p.base.free_symbols and symbolic_sign(p.base) is None}


def sign_where_defined(value: sp.Expr, values: Mapping[sp.Symbol, sp.Expr],
                       nonzero: Mapping[sp.Expr, sp.Dummy]) -> int | Undecided:
    """``sign_of`` value, the factors ``nonzero`` (``nonzero_where_defined``) taken ≠ 0;
    the Undecided names value as written."""
    sign = sign_of(value, values)
    if not isinstance(sign, Undecided) or not nonzero:
        return sign
    found = sign_of(value.xreplace(nonzero), values)
    return sign if isinstance(found, Undecided) else found


def over_sines(value: sp.Expr, values: Iterable[sp.Expr]) -> sp.Expr:
    """``value`` divided by each 1 − c and 1 + c that divides it exactly, for every
    acos(c) and asin(c) in the ``values`` (an equilibrium's coordinates): a quantity of
    the same sign wherever that equilibrium exists, since −1 ≤ c ≤ 1 there (and c = ±1
    is where it meets θ = 0 or π). K = k l² h² L₀ sin²θ₀/s³ at cos θ₀ = c, written as
    four factors of six parameters, is (1 − c)(1 + c) times a sign the cases can split:
    a rod on a spring of natural length whose stiffness was left undecided."""
    for c in sorted({f.args[0] for v in values for f in sp.sympify(v).atoms(sp.acos, sp.asin)}, key=sp.default_sort_key):
        for side in (1 - c, 1 + c):
            value = _divided(value, side)
    return value


@lru_cache(maxsize=1024)  # each equilibrium's K and each λ about it divide by the same sides
def _divided(value: sp.Expr, side: sp.Expr) -> sp.Expr:
    """value / side where side's numerator divides value's exactly (as polynomials in
    the parameters), else value as it is."""
    top, bottom = quotient(value)
    n, d = quotient(side)
    gens = sorted(top.free_symbols | n.free_symbols, key=sp.default_sort_key)
    if not n.free_symbols or not gens:
        return value
    try:
        whole, rest = sp.div(sp.Poly(top, *gens), sp.Poly(n, *gens))
    except sp.PolynomialError:  # a root or a function of the parameters: not a polynomial
        return value
    if not rest.is_zero:
        return value
    return sp.factor(whole.as_expr() * d / bottom)


FACTOR_OPS = 200  # a longer expression is judged as written only: factoring it can take minutes


@lru_cache(maxsize=4096)  # one value is judged again and again (each piece, each question)
def symbolic_sign(value: sp.Expr) -> int | None:
    """−1, 0 or 1 where sympy's assumptions decide it (as written, or factored where it
    is short enough: the friction ratio of a slab rolling on a drum, F/N with θ and
    sin θ mixed, ran sympy's factor for minutes). The factored form is made only where
    the written one is undecided (a number, a sum of positive terms, is decided as it
    stands)."""
    sign = _assumed_sign(value)
    if sign is None and sp.count_ops(value) <= FACTOR_OPS:
        sign = _assumed_sign(sp.factor(value))
    return sign


def _assumed_sign(form: sp.Expr) -> int | None:
    if form.is_zero:
        return 0
    if form.is_positive:
        return 1
    if form.is_negative:
        return -1
    return None
