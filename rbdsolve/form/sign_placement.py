"""Where a worked solution puts a product's signs: −(a sin θ + b sin φ) θ̇ rather than
(−a sin θ − b sin φ) θ̇, 2g/(3(R − r)) rather than −2g/(3(r − R)), 6gh/(4h² − b²)
rather than −6gh/(b² − 4h²). The printers (printers.py, mathml.py) ask ``signs_placed``
of every product before they write it; values never change."""

from __future__ import annotations

import sympy as sp


def signs_placed(expr: sp.Mul) -> sp.Expr | None:
    """A product's signs where a worked solution puts them, or None where nothing moves:

    - a factor whose terms are all negative gives its sign to the product,
      (−a sin θ − b sin φ) θ̇ as −(a sin θ + b sin φ) θ̇, and so does a negative number,
      (4 − 2π) as −(2π − 4);
    - a negative product takes its sign into a difference: −2g/(3(r − R)) as
      2g/(3(R − r)), −6g(a − 2R) as 6g(2R − a), −2g(cos θ₀ − 1) as 2g(1 − cos θ₀)
      (an odd power only; a common number factored out of it)."""
    coeff, rest = expr.as_coeff_Mul()
    if not coeff.is_Number:
        return None
    factors, moved = list(sp.Mul.make_args(rest)), False
    for i, factor in enumerate(factors):
        base, exp = factor.as_base_exp()
        if base.is_Add and exp.is_Integer and exp % 2 == 1 and _negative_sum(base):
            factors[i], coeff, moved = _power(-base, exp), -coeff, True
    if coeff < 0:
        turned = _turned(factors)
        if turned is not None:
            factors, coeff, moved = turned, -coeff, True
    elif coeff > 0:
        turned = _turned_twice(factors)
        if turned is not None:
            factors, moved = turned, True
    if not moved:
        return None
    # a number the turning took out of a difference above the line joins the coefficient:
    # 2 g (1 − x), not g 2 (1 − x) (below the line it stays with its difference: 3 (R − r))
    numbers = [f for f in factors if f.is_Number]
    if numbers:
        factors = [f for f in factors if not f.is_Number]
        coeff = coeff * sp.Mul(*numbers)
    return sp.Mul(coeff, *factors, evaluate=False) if coeff != 1 else sp.Mul(*factors, evaluate=False)


def _negative_sum(base: sp.Add) -> bool:
    """Every term negative, or a number below zero (4 − 2π)."""
    if base.is_number:
        return bool(base.is_negative)
    return all(term.could_extract_minus_sign() for term in base.args)


def _turned(factors: list) -> list | None:
    """The factors with a sign taken into the first difference (an odd power) that takes
    it: by sympy's own sign rule first (r − R, cos θ₀ − 1: 1 − cos θ₀ turned), else a
    difference of two terms below the line; never a number (2π − 4 is positive as it
    stands). None where no factor takes it."""
    odd = [(i, *f.as_base_exp()) for i, f in enumerate(factors) if _odd_difference(f)]
    for takes in (_by_sympy_rule, _two_term_denominator):
        for i, base, exp in odd:
            if takes(base, exp):
                return [*factors[:i], *_negated(base, exp), *factors[i + 1:]]
    return None


def _negated(base: sp.Add, exp: sp.Integer) -> list:
    """(−base)^exp as factors: its common number apart, 3 (R − r) for −(3r − 3R)."""
    return [p if exp == 1 else sp.Pow(p, exp, evaluate=not (p.is_Add or p.is_Number))
            for p in sp.Mul.make_args(sp.factor_terms(-base))]


def _turned_twice(factors: list) -> list | None:
    """Two differences turned at once where both read better so and the product keeps
    its sign: 4g (cos θ₀ − 1)/(3r − 3R) as 4g (1 − cos θ₀)/(3 (R − r)). None where
    fewer than two take a sign by sympy's rule."""
    takers = [i for i, f in enumerate(factors) if _odd_difference(f) and _two_terms_to_turn(f.as_base_exp()[0])]
    if len(takers) < 2:
        return None
    out = list(factors)
    for i in reversed(takers[:2]):  # from the right, so the first index still points at its factor
        out[i:i + 1] = _negated(*out[i].as_base_exp())
    return out


def _two_terms_to_turn(base: sp.Add) -> bool:
    """A difference of two terms that reads better turned: a number taken from a symbol
    (cos θ₀ − 1), or symbols by sympy's sign rule (3r − 3R); never a number first
    (28 − 3 cos² reads as it is)."""
    if len(base.args) != 2:
        return False
    numbers = [t for t in base.args if t.is_Number]
    if numbers:
        return numbers[0].is_negative
    return base.could_extract_minus_sign()


def _odd_difference(factor: sp.Expr) -> bool:
    base, exp = factor.as_base_exp()
    return base.is_Add and not base.is_number and exp.is_Integer and exp % 2 == 1


def _by_sympy_rule(base: sp.Add, exp: sp.Integer) -> bool:
    """sympy's own sign rule (r − R), or a number taken from a symbol (cos θ₀ − 1)."""
    if base.could_extract_minus_sign():
        return True
    return len(base.args) == 2 and any(t.is_Number and t.is_negative for t in base.args)


def _two_term_denominator(base: sp.Add, exp: sp.Integer) -> bool:
    """A difference below the line: −6gh/(b² − 4h²) reads 6gh/(4h² − b²) (above it,
    −g m (R − r) stays as written)."""
    return exp < 0 and len(base.args) == 2 and sum(t.could_extract_minus_sign() for t in base.args) == 1


def _power(base: sp.Expr, exp: sp.Expr) -> sp.Expr:
    return base if exp == 1 else sp.Pow(base, exp, evaluate=False)
