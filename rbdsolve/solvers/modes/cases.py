"""The kind of each small oscillation, and where it exists: oscillation, growth or
neutral by the sign of λ; where the parameters decide that sign, the cases an exam
writes ("oscillation when Ω < Ω_c, growth when Ω > Ω_c", ``solvers/conditions/conditions.py``),
only where the equilibrium exists and the assumptions allow: a λ left with one case is
of that kind (an off-axis equilibrium that exists only above Ω_c oscillates there), and
a mode's cases are two or more (docs/json.md). What ``equilibria/cases.py`` is to equilibria.
"""

from __future__ import annotations

from typing import Mapping

import sympy as sp

from rbdsolve.errors import UnsolvedError
from rbdsolve.form.printers import to_unicode, unicode_name
from rbdsolve.model.build import Model
from rbdsolve.model.energies.spring_length import held_sides
from rbdsolve.solvers.equilibria.cases import existence_where
from rbdsolve.solvers.equilibria.exact import decided_inertia
from rbdsolve.solvers.modes.answers import Motion, MotionCase
from rbdsolve.solvers.conditions.condition_roots import angle_parameters, parameter_roots
from rbdsolve.solvers.conditions.angle_signs import angle_sign
from rbdsolve.solvers.conditions.conditions import (Piece, changes, existing_within_bounds, partition, sign_on,
                                                 what_decides)
from rbdsolve.solvers.conditions.present_conditions import condition_text
from rbdsolve.solvers.conditions.signs import (Inertia, Undecided, matrix_inertia, nonzero_where_defined, over_sines,
                                              roots_where_defined, sign_of, sign_where_defined)


def existence(at: dict, model: Model, first: sp.Symbol | None = None) -> sp.Basic:
    """Where the equilibrium ``at`` is real (θ = acos(g/(R Ω²)) only where Ω ≥ √(g/R)),
    solved for ``first`` where it can; true where it always is, or cannot be split."""
    found = existence_where(at, model, first)
    return found.condition if found else sp.true


def absent(at: dict, where: sp.Basic, model: Model) -> str | None:
    """Why the equilibrium ``at`` does not exist at the given values (a coordinate that is
    not a real number there: acos(g/(R Ω²)) below Ω_c; a spring past its zero length:
    ``existing_where``), or None: no modes of it."""
    names = dict(zip(model.q, model.coordinate_names()))
    needs = "" if where is sp.true else f": it exists only where {condition_text(where)}"
    shown = ", ".join(f"{unicode_name(names[q])} = {to_unicode(v)}" for q, v in at.items())
    for side in held_sides(model.springs, at):
        number = side.xreplace(dict(model.values))
        if model.values and number.is_number and number.is_negative:
            return (f"the equilibrium {shown} does not exist at the parameter values (a spring would be past its zero "
                    f"length there, {to_unicode(side)} < 0){needs}")
    for q, value in at.items():
        number = value.xreplace(dict(model.values))
        if not model.values or number.free_symbols:
            continue
        z = complex(sp.N(number, 20))
        if abs(z.imag) > 1e-12 * max(1.0, abs(z.real)):
            return (f"the equilibrium {unicode_name(names[q])} = {to_unicode(value)} does not exist at the parameter "
                    f"values ({unicode_name(names[q])} is not a real number there){needs}")
    return None


def _for_every_value(K: sp.Matrix, model: Model, nonzero: Mapping, counts: Inertia) -> bool:
    """Is K definite (all its eigenvalues of one sign), or of the inertia ``counts``, for
    every value the assumptions allow, where the equilibrium is defined (its roots real,
    its denominators ≠ 0), not only at the values given?"""
    found = matrix_inertia(K.xreplace({**roots_where_defined(K), **nonzero}), model.assumed)
    return isinstance(found, Inertia) and (K.rows in (found.positive, found.negative) or found == counts)


def kinds(eigenvalues: list[sp.Expr], K: sp.Matrix, model: Model, where: sp.Basic = sp.true,
          first: sp.Symbol | None = None, at: Mapping[sp.Expr, sp.Expr] | None = None):
    """Oscillation, growth or neutral for each λ, and the cases of a λ whose sign the
    parameters decide (its critical values: ``solvers/conditions/conditions.py``), those outside
    ``where`` the equilibrium exists or outside the assumptions left out (a λ left with
    one case is of that kind: an off-axis equilibrium that exists only above Ω_c
    oscillates there). A λ has cases only where it has two or more; then its kind is
    ``depends``, or, where the values decide its sign, the kind of the case they fall
    in. When a λ's sign is not decided by itself, Sylvester's law of inertia decides it: with M
    positive definite, K a = λ M a has as many positive, zero and negative λ as K has
    eigenvalues of each sign, so a positive definite K (a stable equilibrium) makes
    every λ positive. At the equilibrium ``at``, a factor of its coordinates'
    denominators is ≠ 0 (``nonzero_where_defined``: λ = −Ω² sin² α < 0 where s = g cos α/(Ω² sin² α)),
    and a factor sin²θ₀ = (1 − c)(1 + c) at θ₀ = acos(c) is > 0 (``over_sines``)."""
    counts = decided_inertia(K, model, at)
    nonzero = nonzero_where_defined(at.values()) if at else {}
    zeros = sum(1 for lam in eigenvalues if lam == 0)
    motions, cases, criticals = [], [], []
    for written in eigenvalues:
        lam, sign = written, _decided_sign(written, model, nonzero)
        if isinstance(sign, Undecided) and at:  # judged by λ/sin²θ₀, of λ's sign where it exists
            lam = over_sines(written, at.values())
            sign = _decided_sign(lam, model, nonzero) if lam is not written else sign
        by_inertia = False  # decided by K's inertia, which holds for every value allowed: no cases to say
        if isinstance(sign, Undecided) and isinstance(counts, Inertia) \
                and counts.positive + counts.zero + counts.negative == len(eigenvalues):
            sign = _sign_by_inertia(counts, len(eigenvalues), zeros, sign)
            by_inertia = not isinstance(sign, Undecided) and _for_every_value(K, model, nonzero, counts)
        if isinstance(sign, Undecided):
            found = _cases(lam, model, where, first) or _cases_at_values(lam, model, where, first)
            if found is None:
                raise UnsolvedError(f"the sign of the eigenvalue {to_unicode(written)} depends on the parameters in a "
                                    f"way rbdsolve cannot split into cases; "
                                    f"{what_decides(lam.xreplace(dict(model.values)))}")  # (names those without values)
            if len(found[0]) == 1:
                motions.append(found[0][0].kind)
                cases.append(())
                continue
            motions.append(Motion.DEPENDS)
            cases.append(found[0])
            criticals += found[1]
            continue
        motions.append(KIND[sign])
        # decided by the values: the cases still say where that holds, as for equilibria
        open_ = model.values and not by_inertia and isinstance(sign_of(lam, model.assumed), Undecided)
        found = _cases(lam, model, where, first) if open_ else None
        kept = found if found and len(found[0]) > 1 else None
        cases.append(kept[0] if kept else ())
        criticals += kept[1] if kept else []
    return tuple(motions), tuple(cases), criticals


KIND = {1: Motion.OSCILLATION, 0: Motion.NEUTRAL, -1: Motion.GROWTH}


def _sign_by_inertia(counts: Inertia, n: int, zeros: int, sign: int | Undecided) -> int | Undecided:
    """A λ not 0 itself, by K's inertia (M positive definite: as many λ of each sign as K
    has eigenvalues): all of one sign, or K semidefinite with its zero eigenvalues each
    a λ written 0 (two carts and a pendulum, free along the track: K ≥ 0, one λ = 0,
    the other two positive)."""
    if counts.positive == n or (counts.negative == 0 and counts.zero == zeros):
        return 1
    if counts.negative == n or (counts.positive == 0 and counts.zero == zeros):
        return -1
    return sign


def _decided_sign(lam: sp.Expr, model: Model, nonzero: Mapping[sp.Expr, sp.Dummy]) -> int | Undecided:
    """λ's sign by the values and the assumptions' substitutions, else by the assumptions
    alone (as ``decided_inertia``: R given drops R = r + δ), the factors ``nonzero`` ≠ 0."""
    sign = sign_where_defined(lam, model.decided_by, nonzero)
    if isinstance(sign, Undecided) and model.assumed:
        alone = sign_where_defined(lam, model.assumed, nonzero)
        sign = sign if isinstance(alone, Undecided) else alone
    if isinstance(sign, Undecided):  # with each angle parameter in (0, π): λ = 3 (2 L k + g m sin α)/(2 L m) > 0
        angled = angle_sign(lam, model)
        return sign if angled is None else angled
    return sign


def _cases_at_values(lam: sp.Expr, model: Model, where: sp.Basic, first: sp.Symbol | None = None):
    """``_cases`` of λ with the parameters that have values put in, where that leaves
    one or more free (k alone, M, g, l, m given: its critical values numbers, as the
    equilibria's are); None where there are no values, or it still cannot be split."""
    values = dict(model.values)
    if not values or not lam.free_symbols - set(values):
        return None
    valued = lam.xreplace(values)
    return _cases(valued, model, where.xreplace(values), first) or _one_sign(valued, model)


def _one_sign(lam: sp.Expr, model: Model):
    """λ of one parameter p with no root (nor pole) inside p's range: one sign over all
    of it, a single case (the larger λ of two where the smaller's sign changes at k_c)."""
    if len(lam.free_symbols) != 1:
        return None
    (p,) = lam.free_symbols
    angles = angle_parameters(lam)
    if parameter_roots(lam, p, angles, model) != []:  # roots inside, or not known: not one sign
        return None
    sign = sign_on(lam, Piece(p, None, None, 0, angles.get(p, (sp.Integer(0), sp.oo))), model, angles)
    return None if sign is None else ((MotionCase(sp.true, KIND[sign]),), [])


def _cases(lam: sp.Expr, model: Model, where: sp.Basic, first: sp.Symbol | None = None):
    """(cases, critical values) for a λ whose sign changes at critical values, the
    pieces where the equilibrium does not exist (or the assumptions rule out) left out;
    None where it cannot be split (or a piece lies partly where it exists)."""
    found = partition(lam, model, first)
    kept = existing_within_bounds(found.pieces, where, model) if found else None
    if not kept:
        return None
    return tuple(MotionCase(piece.when(), KIND[piece.sign]) for piece in kept), list(changes(kept))

