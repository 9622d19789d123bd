"""∂e/∂x for a model's expressions, without sympy's Derivative at every node.

``sympy.diff`` builds and checks a Derivative object at every node it differentiates
before evaluating it: about 0.4 ms a call on a seed problem's Lagrangian, 64 calls in
seed problem 1. A model's energies, equations and positions are sums and products of
numbers, symbols, powers and sin and cos, and for those sympy's own rules are applied
here directly, in the order sympy applies them, so the result is the very expression
``sympy.diff`` gives (tests/model/test_derivative.py compares the two on every call over
problems/):

    ∂(Σ tᵢ)/∂x = Σ ∂tᵢ/∂x                                  (Add)
    ∂(Π fⱼ)/∂x = Σⱼ Π (the factors, fⱼ replaced by ∂fⱼ/∂x)   (Mul: Leibniz's rule)
    ∂(bᵖ)/∂x = bᵖ · (∂b/∂x · p / b),  p free of x            (Pow)
    ∂ sin u/∂x = cos u · ∂u/∂x,   ∂ cos u/∂x = (−sin u) · ∂u/∂x

A node free of x gives 0; any other node holding x (a function of time, exp, a power
with x in its exponent) goes to ``sympy.diff``, as does an x that is not a symbol.
"""

from __future__ import annotations

import sympy as sp


def derivative(expr: sp.Expr, x: sp.Symbol) -> sp.Expr:
    """∂expr/∂x (see the module docstring)."""
    if not isinstance(x, sp.Symbol) or not isinstance(expr, sp.Expr):
        return sp.diff(expr, x)
    return _of(expr, x)


def matrix_derivative(matrix: sp.MatrixBase, x: sp.Symbol) -> sp.MatrixBase:
    """∂M/∂x entry by entry: what ``Matrix.diff`` gives, without its route through sympy's
    array derivatives (and their import)."""
    return matrix.applyfunc(lambda e: derivative(e, x))


def _of(e: sp.Expr, x: sp.Symbol) -> sp.Expr:
    if e == x:
        return sp.Integer(1)
    if not e.has(x):
        return sp.Integer(0)
    if e.is_Add:
        return sp.Add(*[_of(term, x) for term in e.args])
    if e.is_Mul:
        factors = e.args
        return sp.Add(*[sp.Mul(*factors[:j], _of(f, x), *factors[j + 1:])
                        for j, f in enumerate(factors) if f.has(x)])
    if e.is_Pow and not e.exp.has(x):
        base, p = e.args
        return e * (_of(base, x) * p / base)
    if isinstance(e, sp.sin):
        return sp.cos(e.args[0]) * _of(e.args[0], x)
    if isinstance(e, sp.cos):
        return -sp.sin(e.args[0]) * _of(e.args[0], x)
    return sp.diff(e, x)
