"""The stability of an equilibrium of one coordinate where K = ∂²V/∂q² = 0: V's first
derivative past the second that is not zero there decides (Taylor's theorem about q₀):

    V(q₀ + u) = V(q₀) + V⁽ⁿ⁾(q₀) uⁿ/n! + …,

- n even and V⁽ⁿ⁾ > 0: a strict minimum of V, stable (Lagrange–Dirichlet);
- n even and V⁽ⁿ⁾ < 0: a strict maximum, unstable;
- n odd: V falls on one side (an inflection), unstable — released there at rest, the
  body cannot come back to q₀, whose V is above its energy.

A hoop with a particle on top of its centre rolling inside a cylinder of radius 3R (a new
user's trial): V = −m g R (4 cos φ + sin 2φ) has V'' = 0 at φ = 0 and V⁽⁴⁾ = 12 m g R
> 0 there, V ≈ −3 m g R + ½ m g R φ⁴: stable, with no linear oscillation. One
coordinate only: with more, a singular K leaves directions that need more than one
derivative along each.
"""

from __future__ import annotations

from typing import Mapping

import sympy as sp

from rbdsolve.form.printers import to_unicode, unicode_name
from rbdsolve.form.tidy import tidy
from rbdsolve.form.zero import simplifies_to_zero
from rbdsolve.model.build import Model
from rbdsolve.model.energies.energy import memoized, potential_energy
from rbdsolve.solvers.conditions.signs import Undecided, sign_of
from rbdsolve.solvers.equilibria.answers import Stability

HIGHEST = 6  # the last derivative of V tried


def higher_order(model: Model, at: Mapping[sp.Expr, sp.Expr]) -> tuple[Stability, str] | None:
    """(stability, reason) from the first derivative of V past the second that is not
    zero at ``at``, where its sign is decided (the parameters' signs, the values, the
    assumptions); None with more than one coordinate, or where none up to the sixth is
    known not to vanish. Once per model and point (the equilibria classify it, the modes
    about it ask again)."""
    return _higher_order(model, tuple(at.items()))


@memoized
def _higher_order(model: Model, at: tuple) -> tuple[Stability, str] | None:
    if len(model.q) != 1:
        return None
    (q,) = model.q
    name = unicode_name(model.coordinate_names()[0])
    derivative = sp.diff(potential_energy(model).total, q, 2)
    for n in range(3, HIGHEST + 1):
        derivative = sp.diff(derivative, q)
        value = tidy(derivative.xreplace(dict(at)))
        if simplifies_to_zero(value):
            continue
        sign = sign_of(value, model.decided_by)
        if isinstance(sign, Undecided):
            return None
        if sign == 0:  # zero at the values given: the next one decides
            continue
        return _verdict(n, sign, f"∂{_power(n)}V/∂{name}{_power(n)} = {to_unicode(model.readable(value))}")
    return None


def _verdict(n: int, sign: int, shown: str) -> tuple[Stability, str]:
    singular = f"the Hessian of V is singular (K = 0), and the first derivative past it that is not zero, {shown}"
    if n % 2:
        return Stability.UNSTABLE, f"{singular}, is of odd order: V falls on one side (an inflection)"
    if sign > 0:
        return Stability.STABLE, f"{singular}, is of even order and positive: a strict minimum of V (no linear " \
                                 "oscillation: the small motions are not harmonic)"
    return Stability.UNSTABLE, f"{singular}, is of even order and negative: a strict maximum of V"


def _power(n: int) -> str:
    return str(n).translate(str.maketrans("0123456789", "⁰¹²³⁴⁵⁶⁷⁸⁹"))


def degenerate_minimum_note(model: Model, at: Mapping[sp.Expr, sp.Expr], K: sp.Matrix) -> tuple[str, ...]:
    """For the modes about an equilibrium of one coordinate with K = 0 that V's higher
    derivatives make a strict minimum: their λ = 0 is no free direction (a neutral one
    would let the body drift); the motion stays near q₀, periodic but not harmonic."""
    if K.shape != (1, 1) or not simplifies_to_zero(K[0, 0]):
        return ()
    decided = higher_order(model, at)
    if decided is None or decided[0] is not Stability.STABLE:
        return ()
    return (f"λ = 0 is no free direction here (the body stays near the equilibrium): {decided[1]}",)
