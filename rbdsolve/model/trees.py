"""Sympy values written back as the problem's expression trees, so that what the model
derives (a rolling body's place and angle, an assumption a contact implies) reads as if
the file had said it: located at ``where`` (anything with a ``loc``, a contact)."""

from __future__ import annotations

from fractions import Fraction

import sympy as sp

from rbdsolve.model.state import t
from rbdsolve.model.symbols import Symbols
from rbdsolve.problem import expr as ex



def reverse_names(names: Symbols) -> dict:
    """sympy symbol -> the name the file gives it (parameters, coordinates, t)."""
    table = {s: n for n, s in names.parameters.items()}
    table.update({q: n for n, q in names.coordinates.items()})
    table.update({f: n for n, f in names.prescribed.items() if isinstance(f, sp.Function)})
    table[t] = "t"
    return table


def as_expr(value, reverse: dict, names: Symbols, where) -> ex.Expr:
    """A sympy value as a checked expression tree located at ``where``."""
    readable = {q: sp.Symbol(n) for n, q in names.coordinates.items()}
    if isinstance(value, sp.MatrixBase):
        items = list(value) if value[2] != 0 else list(value[:2])
        tree = ex.Vec(tuple(tree_of(x, reverse) for x in items))
        return ex.Expr(tree, ex.Kind.VECTOR, sp.sstr(sp.Matrix(items).T.xreplace(readable)), where.loc)
    return ex.Expr(tree_of(value, reverse), ex.Kind.SCALAR, sp.sstr(value.xreplace(readable)), where.loc)


def tree_of(x: sp.Expr, reverse: dict) -> ex.Tree:
    """The expression tree of x: names, π, rationals, +, *, ** and the known functions."""
    if x in reverse:
        return ex.Name(reverse[x])
    if x is sp.pi:
        return ex.Const("pi")
    if x.is_Rational:
        number = ex.Num(Fraction(abs(x.p), x.q))
        return ex.Neg(number) if x < 0 else number
    if isinstance(x, (sp.Add, sp.Mul)):
        op = "+" if isinstance(x, sp.Add) else "*"
        trees = [tree_of(a, reverse) for a in x.args]
        out = trees[0]
        for item in trees[1:]:
            out = ex.BinOp(op, out, item)
        return out
    if isinstance(x, sp.Pow):
        return ex.BinOp("**", tree_of(x.base, reverse), tree_of(x.exp, reverse))
    name = type(x).__name__.lower()
    if name in ex.SCALAR_FUNCTIONS:
        return ex.Call(name, tuple(tree_of(a, reverse) for a in x.args))
    raise ValueError(f"cannot write {x} as a scene expression")  # pragma: no cover - from the trees above
