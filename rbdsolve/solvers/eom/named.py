"""The names the equations of motion's worked solution prints its answers by
(report/numbers.py): each q̈ solved for (ẍ, θ̈), the q̈ at the state asked for, and the
total derivative F by which a frame's Lagrangian differs."""

from __future__ import annotations

import sympy as sp

from rbdsolve.model.build import Model
from rbdsolve.report.numbers import Named
from rbdsolve.solvers.routes.naming import coordinate


def named(question, answers, model: Model) -> tuple[Named, ...]:
    out = [Named(("accelerations", k), coordinate(model, f"ddot({k})")) for k in (getattr(answers, "accelerations", None) or {})]
    out += [Named(("at", k), coordinate(model, f"ddot({k})"), "At the state asked") for k in (getattr(answers, "at", None) or {})]
    frames = getattr(answers, "frames", ())
    out += [Named(("frames", i, "total_derivative"), sp.Symbol("F"), f"In frame {f.frame}")
            for i, f in enumerate(frames) if hasattr(f, "total_derivative")]
    return tuple(out)
