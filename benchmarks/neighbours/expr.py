"""The oracle's reading of the expression language: scalar and vector expressions as
the generator writes them (the same grammar as a problem file: numbers, names, + − * /
**, sin cos … sqrt, [x, y] vectors), compiled to Python functions that evaluate in
floats (``math``), in many digits (``mpmath``) or in floats on arrays of points (``numpy``).

The strings are the generator's own (never a user's file), so compiling them is safe;
the parse is still checked node by node against the grammar, so a typo in a family
fails at once instead of evaluating something else."""

from __future__ import annotations

import ast
import math
from functools import lru_cache
from typing import Any, Callable

import mpmath
import numpy as np

FUNCTIONS = ("sin", "cos", "tan", "asin", "acos", "atan", "atan2", "sqrt", "exp", "log",
             "sinh", "cosh", "tanh", "abs", "norm", "inner", "cross")
_ALLOWED = (ast.Expression, ast.BinOp, ast.UnaryOp, ast.Call, ast.Name, ast.Load, ast.Constant,
            ast.List, ast.Add, ast.Sub, ast.Mult, ast.Div, ast.Pow, ast.USub, ast.UAdd)


class Vec:
    """A 3-vector of floats or mpf: [x, y] gets z = 0; + − with vectors, * / by scalars."""

    __slots__ = ("c",)
    # numpy's operators give way to the vector's own (an array of points times a vector
    # is a vector of arrays, not an array of vectors)
    __array_ufunc__ = None

    def __init__(self, *c):
        if len(c) == 2:
            c = (c[0], c[1], 0 * c[0])
        if len(c) != 3:
            raise ValueError(f"a vector has 2 or 3 components, found {len(c)}")
        self.c = tuple(c)

    def __add__(self, o):
        return Vec(*(a + b for a, b in zip(self.c, _vec(o).c)))

    def __sub__(self, o):
        return Vec(*(a - b for a, b in zip(self.c, _vec(o).c)))

    def __neg__(self):
        return Vec(*(-a for a in self.c))

    def __pos__(self):
        return self

    def __mul__(self, s):
        if isinstance(s, Vec):
            raise TypeError("cannot multiply two vectors")
        return Vec(*(a * s for a in self.c))

    __rmul__ = __mul__

    def __truediv__(self, s):
        return Vec(*(a / s for a in self.c))

    def __getitem__(self, i):
        return self.c[i]

    def __iter__(self):
        return iter(self.c)

    def __repr__(self):
        return f"Vec{self.c}"


def _vec(o) -> Vec:
    if not isinstance(o, Vec):
        raise TypeError(f"cannot add a vector and {o!r}")
    return o


class Namespace:
    """The functions an expression may call, in one arithmetic (floats or mpmath)."""

    def __init__(self, lib):
        self.lib = lib
        self.pi = mpmath.pi if lib is mpmath.mp else lib.pi
        # numpy's own float64 arrays for floats (the same IEEE doubles, computed in C), an
        # array of Python objects for mpmath's 40 digits
        self.dtype = object if lib is mpmath.mp else float
        self.table: dict[str, Any] = {name: getattr(lib, name) for name in
                                      ("sin", "cos", "tan", "asin", "acos", "atan", "atan2", "sqrt",
                                       "exp", "log", "sinh", "cosh", "tanh")}
        self.table["abs"] = abs
        self.table["norm"] = lambda v: self.table["sqrt"](sum(x * x for x in v))
        self.table["inner"] = lambda a, b: sum(x * y for x, y in zip(a, b))
        self.table["cross"] = lambda a, b: Vec(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                                               a[0] * b[1] - a[1] * b[0])
        self.table["_V"] = Vec
        # eval's globals, built once: an expression reads them and never assigns (they were
        # copied per evaluation: 1.6 million copies judging one file's equilibria)
        self.globals = {"__builtins__": {}, **self.table}


FLOAT = Namespace(math)
MP = Namespace(mpmath.mp)
# floats on numpy arrays, one element per point: an expression evaluated at many points at
# once (numpy's sin, cos … in place of math's, the same doubles to an ulp or so)
ARRAYS = Namespace(np)
mpmath.mp.dps = 40


class _Rewrite(ast.NodeTransformer):
    def visit_List(self, node):
        self.generic_visit(node)
        return ast.Call(func=ast.Name(id="_V", ctx=ast.Load()), args=node.elts, keywords=[])

    def visit_Name(self, node):
        if node.id in FUNCTIONS or node.id == "_V":
            return node
        return ast.Subscript(value=ast.Name(id="_e", ctx=ast.Load()),
                             slice=ast.Constant(node.id), ctx=ast.Load())


@lru_cache(maxsize=None)
def compiled(text: str):
    """The code of one expression; names other than functions are read from ``_e``."""
    tree = ast.parse(text.strip(), mode="eval")
    for node in ast.walk(tree):
        if not isinstance(node, _ALLOWED):
            raise ValueError(f"{text!r}: {type(node).__name__} is not in the grammar")
        if isinstance(node, ast.Constant) and not isinstance(node.value, (int, float)):
            raise ValueError(f"{text!r}: constant {node.value!r}")
        if isinstance(node, ast.Call) and (not isinstance(node.func, ast.Name) or node.func.id not in FUNCTIONS):
            raise ValueError(f"{text!r}: unknown function")
    tree = ast.fix_missing_locations(_Rewrite().visit(tree))
    return compile(tree, f"<{text}>", "eval"), names_in(text)


@lru_cache(maxsize=None)
def names_in(text: str) -> frozenset[str]:
    """The names (not functions) an expression uses."""
    tree = ast.parse(text.strip(), mode="eval")
    return frozenset(n.id for n in ast.walk(tree) if isinstance(n, ast.Name) and n.id not in FUNCTIONS)


class Env(dict):
    """Values by name; a point is evaluated on first use from its expression (points may
    refer to other points, in any order)."""

    def __init__(self, ns: Namespace, values: dict, points: dict[str, str]):
        super().__init__(values)
        self.ns = ns
        self.points = points
        self._busy: set[str] = set()

    def __missing__(self, name):
        if name == "pi":
            return self.ns.pi
        if name in self.points:
            if name in self._busy:
                raise ValueError(f"cyclic point {name}")
            self._busy.add(name)
            value = evaluate(self.points[name], self)
            self._busy.discard(name)
            self[name] = value
            return value
        raise KeyError(f"unknown name {name!r}")


def evaluate(text: str, env: Env):
    """The value of ``text`` (a number or a Vec) with the names in ``env``."""
    code, _ = compiled(text)
    return eval(code, env.ns.globals, {"_e": env})  # noqa: S307 - the generator's own text


def constant(text: str, ns: Namespace = MP, values: dict | None = None):
    """A constant expression (numbers, pi, functions, and ``values``' names)."""
    return evaluate(text, Env(ns, dict(values or {}), {}))


def as_function(text: str, ns: Namespace, points: dict[str, str]) -> Callable[[dict], Any]:
    """``text`` as a function of a dict of values (parameters, coordinates, t)."""
    def f(values: dict):
        return evaluate(text, Env(ns, values, points))
    return f
