"""``sympy.expand`` without its walk where an expression is plainly expanded already.

Most coefficients reach ``tidy``, ``collect_in`` and the fractions of q̈ expanded
already (they were made by expanding), and ``expand`` then walks them once per hint
(mul, multinomial, power_exp, power_base, log, basic), building every node again to
find nothing to do: about 0.2 ms a coefficient, 45 times in seed problem 1. A single
walk that recognises the plainly expanded form costs a tenth of that.

Plainly expanded: a sum of products of numbers (rationals, π, at most one radical of an
integer), symbols, their powers with rational exponents, and sin, cos or an undefined
function (a coordinate θ(t)) of plainly expanded arguments. Each default hint leaves
such an expression as it is: there is no product with a sum for ``mul`` to distribute,
no power of a sum for ``multinomial``, no power of a sum or product for ``power_exp``
and ``power_base``, no log, and ``deep`` finds the arguments plainly expanded in turn. Anything else (a Float,
exp, a power of a sum, a derivative) goes to ``expand`` itself.
"""

from __future__ import annotations

import sympy as sp
from sympy.core.function import AppliedUndef


def expanded(expr: sp.Expr) -> sp.Expr:
    """``sp.expand(expr)``: ``expr`` itself where it is plainly expanded (see above)."""
    return expr if plainly_expanded(expr) else sp.expand(expr)


def plainly_expanded(expr: sp.Basic) -> bool:
    """A sum of products of the plain factors (module docstring)?"""
    if expr.is_Add:
        return all(_plain_term(term) for term in expr.args)
    return _plain_term(expr)


def _plain_term(term: sp.Basic) -> bool:
    """At most one radical of an integer in a product: Mul's flattening is not idempotent
    on several (2**(1/3)·√6·2·18**(1/3) stays 2·6**(1/3)·6**(5/6), which ``mul`` rebuilds
    as 12·6**(1/6))."""
    if term.is_Mul:
        radicals = sum(1 for factor in term.args if factor.is_Pow and factor.base.is_Integer)
        return radicals <= 1 and all(_plain_factor(factor) for factor in term.args)
    return _plain_factor(term)


def _plain_factor(factor: sp.Basic) -> bool:
    if factor.is_Atom:
        return _plain_atom(factor)
    if factor.is_Pow:
        base, exponent = factor.args
        return exponent.is_Rational and (isinstance(base, (sp.Symbol, sp.Integer)) or _plain_function(base))
    return _plain_function(factor)


def _plain_atom(atom: sp.Basic) -> bool:
    return isinstance(atom, (sp.Symbol, sp.Rational)) or atom is sp.pi


def _plain_function(value: sp.Basic) -> bool:
    """sin, cos or a coordinate θ(t) of plainly expanded arguments (``deep`` expands
    the arguments of a function; these three have no expansion of their own under the
    default hints: trig=False)."""
    return isinstance(value, (sp.sin, sp.cos, AppliedUndef)) and all(plainly_expanded(a) for a in value.args)
