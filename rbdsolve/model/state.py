"""Generalized coordinates as plain symbols, and back to functions of time.

Internally each coordinate q, its rate q̇ and its acceleration q̈ are plain (Dummy)
symbols: differentiating with respect to symbols is much faster than with respect to
``theta(t)`` and ``Derivative(theta(t), t)``. The total time derivative is the chain rule

    d/dt f(q, q̇, t) = Σ_j (∂f/∂q_j q̇_j + ∂f/∂q̇_j q̈_j) + ∂f/∂t.

Answers leave the model as functions of time (``theta(t)``), via :meth:`State.to_time`.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property, lru_cache

import sympy as sp
from sympy.core.function import UndefinedFunction
from sympy.printing.precedence import PRECEDENCE

from rbdsolve.model.derivative import derivative, matrix_derivative

t = sp.Symbol("t", real=True)


@lru_cache(maxsize=None)
def user_function(name: str) -> UndefinedFunction:
    """The real function of time that a name from a problem file stands for (θ(t)).

    sympy names a function's class after the function, and its printers look a
    precedence up by class name: a coordinate called ``Integer``, ``Rational`` or
    ``Float`` would be printed as if it were that number class, and crash. An object's
    own ``precedence`` is asked first, so giving the class one (that of any function)
    keeps the user's names in a namespace of their own.

    Cached: each call would otherwise build a new class (sympy prepares its assumptions
    per class), thousands of times for a large model's answers."""
    return UndefinedFunction(name, __dict__={"precedence": PRECEDENCE["Func"]}, real=True)


@dataclass(frozen=True)
class State:
    """The coordinates q and their rates q̇, q̈ as plain real symbols, with their names;
    ``to_time`` writes them as q(t) and its derivatives."""

    names: tuple[str, ...]
    q: tuple[sp.Symbol, ...]
    qd: tuple[sp.Symbol, ...]
    qdd: tuple[sp.Symbol, ...]

    @staticmethod
    def of(names: tuple[str, ...]) -> State:
        return State(
            names,
            tuple(sp.Dummy(n, real=True) for n in names),
            tuple(sp.Dummy(f"{n}_dot", real=True) for n in names),
            tuple(sp.Dummy(f"{n}_ddot", real=True) for n in names),
        )

    def d_dt(self, expr):
        """Total time derivative (works on scalars and matrices)."""
        d = matrix_derivative if isinstance(expr, sp.MatrixBase) else derivative
        out = d(expr, t)
        for q, qd, qdd in zip(self.q, self.qd, self.qdd):
            out += d(expr, q) * qd + d(expr, qd) * qdd
        return out

    def functions(self) -> tuple[sp.Expr, ...]:
        return self._functions

    @cached_property
    def _functions(self) -> tuple[sp.Expr, ...]:
        return tuple(user_function(n)(t) for n in self.names)

    @cached_property
    def _to_time_table(self) -> dict:
        table = {}
        for f, q, qd, qdd in zip(self.functions(), self.q, self.qd, self.qdd):
            table[q] = f
            table[qd] = sp.Derivative(f, t)
            table[qdd] = sp.Derivative(f, (t, 2))
        return table

    def to_time(self, expr):
        """q -> q(t), q̇ -> Derivative(q(t), t), q̈ -> Derivative(q(t), (t, 2))."""
        table = self._to_time_table
        return expr.xreplace(table) if table else expr
