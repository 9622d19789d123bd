"""Generalized coordinates as plain symbols, and back to functions of time.

Internally each coordinate q, its rate q̇ and its acceleration q̈ are plain (Dummy)
symbols: differentiating with respect to symbols is much faster than with respect to
``theta(t)`` and ``Derivative(theta(t), t)``. The total time derivative is the chain rule

    d/dt f(q, q̇, t) = Σ_j (∂f/∂q_j q̇_j + ∂f/∂q̇_j q̈_j) + ∂f/∂t.

Answers leave the model as functions of time (``theta(t)``), via :meth:`State.to_time`.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

t = sp.Symbol("t", real=True)


@dataclass(frozen=True)
class State:
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
        out = sp.diff(expr, t)
        for q, qd, qdd in zip(self.q, self.qd, self.qdd):
            out += sp.diff(expr, q) * qd + sp.diff(expr, qd) * qdd
        return out

    def functions(self) -> tuple[sp.Expr, ...]:
        return tuple(sp.Function(n, real=True)(t) for n in self.names)

    def to_time(self, expr):
        """q -> q(t), q̇ -> Derivative(q(t), t), q̈ -> Derivative(q(t), (t, 2))."""
        table = {}
        for f, q, qd, qdd in zip(self.functions(), self.q, self.qd, self.qdd):
            table[q] = f
            table[qd] = sp.Derivative(f, t)
            table[qdd] = sp.Derivative(f, (t, 2))
        return expr.xreplace(table) if table else expr
