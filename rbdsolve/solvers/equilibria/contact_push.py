"""Equilibria where a contact would have to pull: a ring "resting on top of" a drum is in
equilibrium hanging under it at θ = π by ∂V/∂q = 0 alone, which holds the contact both
ways; the drum there would pull, N = −(M + m) g. Newton–Euler at rest (q̇ = q̈ = 0, at the
equilibrium) with every contact and string of the scene as its only supports
(solvers/reactions/balances.py) gives each push N and tension T; where the parameters
decide N < 0 (T < 0), the equilibrium's warning says so. Where those supports do not hold
the bodies at rest by themselves (a pivot too, unlisted), nothing is said."""

from __future__ import annotations

from typing import Mapping

import sympy as sp

from rbdsolve.form.printers import to_unicode, unicode_name
from rbdsolve.form.tidy import tidy
from rbdsolve.model.build import Model
from rbdsolve.solvers.conditions.signs import sign_of
from rbdsolve.solvers.reactions.balances import contact_forces
from rbdsolve.solvers.reactions.supports import How


def pulling(model: Model, at: Mapping[sp.Expr, sp.Expr]) -> tuple[str, ...]:
    """A warning per push or tension that would be negative at the equilibrium ``at``
    ({q: value})."""
    rest = {**dict(at), **{qd: sp.Integer(0) for qd in model.qd}, **{qdd: sp.Integer(0) for qdd in model.qdd}}
    solved = contact_forces(model, rest)
    if solved is None:
        return ()
    supports, forces = solved
    shown = ", ".join(f"{unicode_name(n)} = {to_unicode(model.readable(at[q]))}"
                      for n, q in zip(model.coordinate_names(), model.q))
    out = []
    for s in supports:
        what, would, only = ("string", "push", "hangs from") if s.how is How.STRING else ("contact", "pull", "rests on")
        for c in (c for c in s.components if c.one_sided and c.symbol in forces):
            value = tidy(forces[c.symbol])  # the state at rest is in already
            if sign_of(value, model.decided_by) == -1:
                out.append(f"at {shown} the {what} at {s.name} would have to {would} ({c.symbol.name} = "
                           f"{to_unicode(model.readable(value))} < 0 at rest there): an equilibrium of ∂V/∂q = 0, which "
                           f"holds the {what} both ways, but not of a body that only {only} it")
    return tuple(out)
