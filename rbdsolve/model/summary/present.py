"""A model's expressions in the exam form: ``form.arrange`` with the model's rates as
the generators (q̈, q̇), its coordinates, its parameters' common scale, and the
coordinates shown as functions of time."""

from __future__ import annotations

import sympy as sp

from rbdsolve.form.arrange import arranged, arranged_equation
from rbdsolve.form.display import Math
from rbdsolve.model.build import Model


def present(expr: sp.Expr, model: Model) -> Math:
    """An energy or a Lagrangian (its coefficients tidied already), ordered, its scale
    pulled out: m r² [7/8 θ̇² + 1/4 cos(φ − θ) θ̇ φ̇ + 1/6 φ̇²]."""
    return arranged(expr, [*model.qdd, *model.qd], model.q, set(model.symbols.parameters.values()),
                    model.to_time)


def present_equation(expr: sp.Expr, model: Model) -> Math:
    """An equation's left side: m r² [7/4 θ̈ + …] + 2 g m r sin(θ)."""
    return arranged_equation(expr, [*model.qdd, *model.qd], model.q, set(model.symbols.parameters.values()),
                             model.to_time)
