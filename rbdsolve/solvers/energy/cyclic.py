"""The energy question's speeds where cyclic coordinates are solved from their momenta
(solvers/lagrange/momentum_integrals.py): each cyclic rate is ċ = a(q) ṡ + b(q), ṡ the
rate of the one coordinate left, so a point's velocity v = Σ ∂r/∂qᵢ q̇ᵢ is linear in ṡ
and

    v² = a₂ ṡ² + a₁ ṡ + a₀,   ṡ² from the energy integral.

Where the momenta start at 0 (released from rest), b = 0 and a₁ = a₀ = 0: v² = a₂ ṡ²,
whatever the direction. Otherwise the direction of ṡ matters (a cart pushed as its
pendulum is released: the bob's speed at the bottom is |ẋ + l θ̇|, not |ẋ − l θ̇|). The
motion from the start gets to ``to`` first moving towards it, so ṡ there has the sign of
s(to) − s(start) (of ṡ at the start where they are equal); that sign is taken for the
cyclic rates and the speeds there, and along the motion where it is known.
"""

from __future__ import annotations

import sympy as sp

from rbdsolve.form.factor import factored
from rbdsolve.form.tidy import tidy
from rbdsolve.model.build import Model
from rbdsolve.solvers.conditions.signs import sign_of
from rbdsolve.solvers.lagrange.accelerations import at_state, clean_fraction

Parts = tuple[sp.Expr, sp.Expr, sp.Expr]  # a₂, a₁, a₀ of v² = a₂ ṡ² + a₁ ṡ + a₀


def speed_parts(model: Model, point: str, rates: dict[sp.Symbol, sp.Expr], kept: sp.Symbol) -> Parts:
    """a₂, a₁, a₀ of the point's v² with the cyclic ``rates`` put in, each one fraction
    factored for reading: (R − r)² (M² + m (2 M + m) sin²θ)/(M + m)²."""
    r = model.point(point)
    v = sum((r.diff(q) * rates.get(qd, qd) for q, qd in zip(model.q, model.qd)), sp.zeros(*r.shape)).applyfunc(sp.expand)
    v2 = sp.expand(v.dot(v))
    a2, a1, a0 = (_readable(v2.coeff(kept, n)) for n in (2, 1, 0))
    return a2, a1, a0


def _readable(expr: sp.Expr) -> sp.Expr:
    top, bottom = sp.fraction(sp.factor(sp.together(expr)))
    return factored(tidy(sp.expand(top))) / bottom


def direction(model: Model, kept: int, start: dict, to: dict[str, sp.Expr] | None) -> int | None:
    """The sign of ṡ as the motion from the start first gets to ``to``: of s(to) − s(start),
    else (equal, or no ``to``) of ṡ at the start; None where the parameters' signs, the
    assumptions and the values do not decide it."""
    s, sd = model.q[kept], model.qd[kept]
    for difference in ((to[model.coordinate_names()[kept]] - start[s]) if to else sp.Integer(0), start.get(sd, 0)):
        sign = sign_of(tidy(sp.sympify(difference)), model.decided_by)
        if isinstance(sign, int) and sign != 0:
            return sign
        if not isinstance(sign, int):
            return None
    return None


def along(parts: Parts, rate_squared: sp.Expr, sign: int | None, kept: sp.Symbol) -> sp.Expr:
    """v² along the motion: a₂ ṡ² + a₀ with ṡ² put in, and a₁ ṡ with ṡ = sign √(ṡ²);
    where a₁ ≠ 0 and the sign is not known, ṡ is left as it is."""
    a2, a1, a0 = parts
    if a1 == 0:
        return clean_fraction(a2 * rate_squared + a0) if a0 != 0 else a2 * rate_squared
    rate = kept if sign is None else sign * sp.sqrt(rate_squared)
    return a2 * rate_squared + a1 * rate + a0


def there(parts: Parts, table: dict, w2: sp.Expr, root: sp.Expr, sign: int) -> sp.Expr:
    """v² at the configuration ``table``: each of a₂, a₁, a₀ put at it first (cheap: the
    whole sum with √ in it ran sympy's simplify for seconds), then ṡ = sign √(w2)."""
    a2, a1, a0 = (at_state(a, table) for a in parts)
    return a2 * w2 + a1 * sign * root + a0 if a1 != 0 else a2 * w2 + a0


def cyclic_rate(rate: sp.Expr, kept: sp.Symbol, root: sp.Expr, sign: int) -> sp.Expr:
    """A cyclic rate a ṡ + b at ṡ = sign × ``root``, the root kept whole: m (r − R)/(M +
    m) √(…), not its factors' roots spread through the product."""
    a, b = (clean_fraction(sp.expand(rate).coeff(kept, n)) for n in (1, 0))
    return (sp.Mul(*sp.Mul.make_args(sign * a), root, evaluate=False) if a != 0 else sp.Integer(0)) + b
