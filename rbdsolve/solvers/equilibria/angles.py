"""An equilibrium's angle from its sine and cosine, as an exam writes it: the angle in
(−π, π] with s = sin θ₀ and c = cos θ₀ is atan2(s, c); where s = ±√(1 − c²) it is
±acos(c) when the sign of s is known, asin(s) when c > 0 is (a half-disk on an incline,
sin θ₀ = −(3π/4) sin β: θ₀ = −asin(3π sin β/4) for either tilt), else atan2(s, c)."""

from __future__ import annotations

from typing import Mapping

import sympy as sp

from rbdsolve.solvers.conditions.signs import Undecided, nonzero_where_defined, roots_where_defined, sign_of


def angle_of(sin_value: sp.Expr, cos_value: sp.Expr, assumed: Mapping) -> sp.Expr:
    """The angle in (−π, π] with this sine and cosine; ±acos(c) or asin(s) when
    s = ±√(1 − c²) and the signs allow (``_by_sign``)."""
    angle = sp.atan2(sin_value, cos_value)
    if angle.is_number:
        return sp.nsimplify(angle) if angle.is_rational else angle
    if sin_value.is_zero:
        return sp.Integer(0) if cos_value.is_positive else sp.pi
    pythagoras = sin_value**2 - (1 - cos_value**2)  # 0 where s = ±√(1 − c²)
    if sp.expand(pythagoras) == 0:
        return _by_sign(sin_value, cos_value, assumed)
    if (not _radical(sin_value) or not _radical(cos_value)) and sp.cancel(sp.together(pythagoras)) == 0:
        # one of them free of roots, s² = 1 − c² once over one denominator (a rod on a wall spring:
        # cos θ₀ = (14 a² k² − 8 a g k m + g² m²)/(4 a k − g m)²): ±acos(c), not a long atan2
        return _by_sign(sin_value, cos_value, assumed)
    if sp.count_ops(angle) < 40:
        return sp.simplify(angle)  # atan(2 P/(g m)): shorter than acos(g m/√(4 P² + g² m²))
    if sp.cancel(sp.together(pythagoras)) == 0:
        # s = ±√(1 − c²) once over one denominator (c = −6 g h/(Ω² b² − 4 Ω² h²)): a long atan2 of them,
        # which simplify is not asked to read, is ±acos(c)
        return _by_sign(sin_value, cos_value, assumed)
    return angle


def _by_sign(sin_value: sp.Expr, cos_value: sp.Expr, assumed: Mapping) -> sp.Expr:
    """atan2(s, c) where s = ±√(1 − c²): ±acos(c) where the sign of s is decided (by the
    parameters' signs and the assumptions, each root in it real where the equilibrium
    exists), asin(s) where c > 0 is, else atan2(s, c) as it is. (The sign as written was
    taken before: −(3π/4) sin β read as negative gave −acos(c) for an incline tilted the
    other way, β < 0, where the half-disk rests at +acos(c); it rests at −asin(3π sin β/4)
    either way.)"""
    if _radical(cos_value) and not _radical(sin_value):
        by_sine = _by_its_sine(sin_value, cos_value, assumed)
        if by_sine is not None:
            return by_sine
    sign = _decided_sign(sin_value, assumed)
    if sign is not None:
        return -sp.acos(cos_value) if sign < 0 else sp.acos(cos_value)
    if _decided_sign(cos_value, assumed) == 1:
        return sp.asin(sin_value)
    return sp.atan2(sin_value, cos_value)


def _by_its_sine(sin_value: sp.Expr, cos_value: sp.Expr, assumed: Mapping) -> sp.Expr | None:
    """Where s has no root in it and c = ±√(1 − s²) has: asin(s) where c > 0, π − asin(s)
    (−π − asin(s)) where c < 0 and s > 0 (s < 0), as an exam writes a wheel held by a
    couple, sin θ₀ = C/(m g R): θ₀ = asin(C/(m g R)) and π − asin(C/(m g R)), not
    ±acos(√(m g R − C) √(m g R + C)/(m g R)); None where the signs are not decided."""
    cos_sign = _decided_sign(cos_value, assumed)
    if cos_sign == 1:
        return sp.asin(sin_value)
    sin_sign = _decided_sign(sin_value, assumed) if cos_sign == -1 else None
    if sin_sign is None:
        return None
    return sin_sign * sp.pi - sp.asin(sin_value)


def _radical(value: sp.Expr) -> bool:
    """Whether a root of the parameters (a power of them with a fractional exponent) is in
    ``value``: √2 C/(m g a) has none (a plate hung from a corner, turned by a couple:
    asin(√2 C/(a g m)), not acos(√(a² g² m² − 2C²)/(a g m)))."""
    return any(not p.exp.is_integer and p.base.free_symbols for p in value.atoms(sp.Pow))


def _decided_sign(value: sp.Expr, assumed: Mapping) -> int | None:
    """The sign the assumptions give value, its roots real (so positive) where it is."""
    found = sign_of(value.xreplace(roots_where_defined(value)), assumed)
    if isinstance(found, Undecided):  # a denominator is ≠ 0 where the angle is defined: 1/(4 a k − g m)² > 0
        found = sign_of(value.xreplace(roots_where_defined(value)).xreplace(nonzero_where_defined([value])), assumed)
    return None if isinstance(found, Undecided) else found
