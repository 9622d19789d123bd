"""The sympy names of a problem, and the fold from checked expression trees to sympy.

Parameters are positive symbols unless declared otherwise; a generalized coordinate
and its rates are the plain symbols of :class:`~rbdsolve.model.state.State`, so
``theta`` and ``dot(theta)`` in a file become q and q̇ here.
"""

from __future__ import annotations

import functools
from collections import ChainMap
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Mapping

import sympy as sp

from rbdsolve.form.printers import to_unicode
from rbdsolve.errors import InputError
from rbdsolve.model.state import State, t, user_function

from rbdsolve.problem import expr as ex
from rbdsolve.problem.quantities.quantity import Value
from rbdsolve.problem.schema import Problem
from rbdsolve.form.zero import simplifies_to_zero

_FUNCTIONS = {
    "sin": sp.sin, "cos": sp.cos, "tan": sp.tan, "cot": sp.cot, "sec": sp.sec, "csc": sp.csc,
    "asin": sp.asin, "acos": sp.acos, "atan": sp.atan, "atan2": sp.atan2,
    "sinh": sp.sinh, "cosh": sp.cosh, "tanh": sp.tanh,
    "exp": sp.exp, "log": sp.log, "sqrt": sp.sqrt, "abs": sp.Abs,
}  # fmt: skip


@dataclass(frozen=True)
class Symbols:
    """Every name a problem declares, as sympy objects."""

    parameters: Mapping[str, sp.Symbol]
    state: State
    points: Mapping[str, sp.Matrix]
    prescribed: Mapping[str, sp.Expr] = field(default_factory=dict)  # name -> y_A(t) or f(t)

    @staticmethod
    def of(problem: Problem) -> Symbols:
        params = {
            p.name: sp.Symbol(p.name, positive=True) if p.positive else sp.Symbol(p.name, real=True)
            for p in problem.parameters
        }
        params.update({name: sp.Symbol(name, real=True) for name in problem.unknowns})
        state = State.of(tuple(c.name for c in problem.coordinates))
        names = Symbols(params, state, {})
        prescribed = {p.name: user_function(p.name)(t) if p.value is None else names.scalar(p.value)
                      for p in problem.prescribed}
        return Symbols(params, state, {}, prescribed)

    @functools.cached_property  # read at every name a fold meets
    def coordinates(self) -> Mapping[str, sp.Symbol]:
        return dict(zip(self.state.names, self.state.q))

    def with_points(self, points: Mapping[str, sp.Matrix]) -> Symbols:
        """These names and ``points`` (which win over points of the same name), merged
        without reading them: points may be folded on first read (model/deferred.py)."""
        own = dict(points) if isinstance(points, dict) else points  # a caller's dict may change later
        return Symbols(self.parameters, self.state, ChainMap(own, self.points) if self.points else own,
                       self.prescribed)

    def scalar(self, expr: ex.Expr) -> sp.Expr:
        return _real(to_sympy(expr.tree, self), expr)

    def vector(self, expr: ex.Expr) -> sp.Matrix:
        return _real(to_sympy(expr.tree, self), expr)

    def axis(self, expr: ex.Expr) -> sp.Matrix:
        """A direction: refused when it is the zero vector, written as zeros or zero by
        arithmetic ([m - m, 0, 0]: the loader, without sympy, sees only the former)."""
        value = self.vector(expr)
        if all(simplifies_to_zero(c) for c in value):
            raise InputError(f"an axis direction must not be the zero vector ('{expr.text}' is zero)", expr.loc)
        return value


def _real(value, expr: ex.Expr):
    """Scene values are real numbers: refuse 1/(1-1), sqrt(-1), log(0) where they show.
    A sum is real in this sense exactly when each of its terms is, and a point of a
    chain repeats the terms of the point before it, so each term is asked once."""
    for item in (value if isinstance(value, sp.MatrixBase) else [value]):
        if not all(_real_term(term) for term in sp.Add.make_args(item)):
            raise InputError(f"'{expr.text}' is not a real number here ({to_unicode(item)})", expr.loc)
    return value


_REAL_CALLS = frozenset({"sin", "cos", "cross", "inner"})  # real and defined for every real argument


def plainly_real(tree: ex.Tree) -> bool:
    """Is the tree real wherever its names are, so that ``_real`` could never refuse its
    fold? Names, numbers and π, combined by −, +, ×, division by a nonzero number,
    powers to integers ≥ 0, sin, cos, cross and inner products: no term can then be
    infinite, NaN, imaginary or leave the reals. (Other trees may be real too: ask
    ``_real`` about their fold.)"""
    if isinstance(tree, (ex.Num, ex.Const, ex.Name)):
        return True
    if isinstance(tree, ex.Neg):
        return plainly_real(tree.operand)
    if isinstance(tree, ex.Vec):
        return all(plainly_real(x) for x in tree.items)
    if isinstance(tree, ex.Call):
        return tree.func in _REAL_CALLS and all(plainly_real(x) for x in tree.args)
    if isinstance(tree, ex.BinOp):
        right = tree.right
        if tree.op == "/":
            safe = isinstance(right, ex.Num) and right.value != 0
        elif tree.op == "**":
            safe = isinstance(right, ex.Num) and right.value.denominator == 1 and right.value >= 0
        else:
            safe = plainly_real(right)
        return safe and plainly_real(tree.left)
    return False  # a rate dot(…): its fold is asked


@functools.lru_cache(maxsize=4096)
def _real_term(term: sp.Expr) -> bool:
    """No infinity, NaN or i in the term, and no piece of it provably complex."""
    return not (term.has(sp.zoo, sp.nan, sp.oo, -sp.oo) or term.has(sp.I) or _provably_complex(term))


def _provably_complex(item: sp.Expr) -> bool:
    """Does a piece of ``item`` have no real value (sqrt(-m), log(-m), asin(2))? Sums,
    products, integer powers and sin/cos of real symbols are real, so only the pieces that
    can leave the reals are asked: asking sympy about a whole 50-term sum is slow."""
    risky = item.atoms(sp.Pow, sp.log, sp.asin, sp.acos)
    return any(p.is_real is False for p in risky if not (isinstance(p, sp.Pow) and p.exp.is_integer))


def exact_number(value: Value | Fraction | int) -> sp.Expr:
    """A parameter's value as an exact sympy number: 3/10, pi/6, sqrt(2)."""
    if isinstance(value, Value):
        return to_sympy(value.tree, None)  # a constant tree names nothing
    value = Fraction(value)
    return sp.Rational(value.numerator, value.denominator)


def to_sympy(tree: ex.Tree, names: Symbols):
    """Fold a checked tree into a sympy scalar or a 3x1 column vector."""
    if isinstance(tree, ex.Num):
        return sp.Rational(tree.value.numerator, tree.value.denominator)
    if isinstance(tree, ex.Const):
        return sp.pi
    if isinstance(tree, ex.Name):
        if tree.id == "t":
            return t
        for table in (names.parameters, names.coordinates, names.prescribed, names.points):
            if tree.id in table:
                return table[tree.id]
        raise KeyError(tree.id)  # the loader checked every name
    if isinstance(tree, ex.Derivative):
        if tree.name in names.prescribed:  # ẏ_A(t), or the derivative of a given f(t)
            return sp.diff(names.prescribed[tree.name], t, tree.order)
        index = names.state.names.index(tree.name)
        return (names.state.qd if tree.order == 1 else names.state.qdd)[index]
    if isinstance(tree, ex.Neg):
        return -to_sympy(tree.operand, names)
    if isinstance(tree, ex.Vec):
        items = [to_sympy(item, names) for item in tree.items]
        return sp.Matrix(items + [sp.Integer(0)] * (3 - len(items)))
    if isinstance(tree, ex.BinOp):
        a, b = to_sympy(tree.left, names), to_sympy(tree.right, names)
        if tree.op == "+":
            return a + b
        if tree.op == "-":
            return a - b
        if tree.op == "*":
            return a * b
        if tree.op == "/":
            return a / b
        return a**b
    if isinstance(tree, ex.Call):
        args = [to_sympy(a, names) for a in tree.args]
        if tree.func == "cross":
            return args[0].cross(args[1])
        if tree.func == "inner":
            return args[0].dot(args[1])
        if tree.func == "norm":
            return sp.sqrt(args[0].dot(args[0]))
        return _FUNCTIONS[tree.func](*args)
    raise TypeError(f"unexpected expression node {tree!r}")  # pragma: no cover
