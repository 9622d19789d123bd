"""Contact limits: where a support stops holding, and the conditions for it to hold.

A push N (a contact) or a tension T (a string) holds while it is ≥ 0; rolling holds
while the friction it needs is within reach, |F| ≤ μ N. So

- along a motion (the forces functions of q alone), the contact is lost (the string goes
  slack) where N (T) reaches zero: the roots of its numerator, as cos q = c (or sin q = c,
  or q = c), with |c| ≤ 1 for an angle (``zeros``); where c holds parameters, such a
  point exists when |c| ≤ 1, solved for one parameter (``exists``);
- the least coefficient of friction for rolling is μ = |F|/N (``least_mu``);
- at a state, the support holds when N ≥ 0 (T ≥ 0), and rolls when μ ≥ |F|/N: where the
  parameters' signs do not decide N's, the condition solved for one parameter in the
  form of the conditions on parameters (solvers/conditions/conditions.py), "holds when ω ≤ ω_c",
  with its critical values (``holds``).
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import mpmath
import sympy as sp

from rbdsolve.form.printers import to_unicode
from rbdsolve.form.tidy import has_root, tidy_fraction
from rbdsolve.model.build import Model
from rbdsolve.model.energies.energy import memoized
from rbdsolve.solvers.reactions.supports import Held, How
from rbdsolve.solvers.lagrange.accelerations import clean_fraction
from rbdsolve.solvers.reactions.first_zero import reaches
from rbdsolve.model.assumptions import implies
from rbdsolve.solvers.conditions.bounds import leaves_no_room, sign_for_every_value
from rbdsolve.solvers.conditions.conditions import Critical, nonnegative_where
from rbdsolve.solvers.conditions.condition_roots import radical_roots
from rbdsolve.solvers.conditions.polynomial import sine_cosine_quartic, trig_transcendental, under_long_radical
from rbdsolve.solvers.conditions.signs import Undecided, sign_of
from rbdsolve.form.zero import simplifies_to_zero


def zeros(value: sp.Expr, model: Model) -> list[sp.Relational] | None:
    """Where a force of q alone vanishes: cos q = c (|c| ≤ 1), sin q = c, or q = c; a
    factor of the numerator of degree 3 or more in sin q (or cos q, once cos² q =
    1 − sin² q is put in where cos q enters in even powers) left as its equation,
    P(sin q) = 0: its closed forms (Cardano's) hold i where its roots are real, and
    dropping them dropped the root (a ladder with a load at its top leaving the wall);
    None where that has no closed form.

    |u| vanishes where u does, and |u|/u (a push along a normal that turns, ±1) nowhere:
    each |u| is taken as u before the numerator is read, so that the ±1 cancels. A
    numerator that holds q both inside and outside sin and cos (a slab rolling on a
    drum: θ³ sin θ beside θ² cos θ), or sines of incommensurate multiples of q (a
    half-disk on a drum: sin(r θ/(R + r)) beside cos θ), or q under a radical in a long
    one (a spring of natural length to a point off a disk's line) has no closed-form
    zeros: None, not a search by sympy's solve (minutes, issue 37). Only real roots count."""
    q = model.q[0]
    top = _numerator(value)
    if not top.has(q):
        return []
    if trig_transcendental(top, q) or under_long_radical(top, q):
        return None
    read = [(f, _implicit(f, q, model)) for f, _ in sp.factor_list(top)[1] if f.has(q)]
    implicit = [w for _, w in read if w is not None]
    if any(w is None and sine_cosine_quartic(f, q) for f, w in read):
        return None  # a quartic in tan(q/2): the numeric search finds where it is reached
    rest = sp.Mul(*(f for f, w in read if w is None))
    return [*_closed_zeros(rest, q, model), *implicit] if rest.has(q) else implicit


def _numerator(value: sp.Expr) -> sp.Expr:
    """The numerator of a force as zeros() reads it, each |u| taken as u."""
    return sp.fraction(tidy_fraction(value.replace(sp.Abs, lambda u: u)))[0]


def no_closed_form(value: sp.Expr, model: Model) -> str:
    """Why zeros() gives no closed form for ``value`` = 0, in a reader's words, read in
    zeros()' own order: a numerator transcendental in q is said so before anything is
    factored (a slab rolling on a drum: θ³ sin θ beside θ² cos θ, whose factor_list ran
    for minutes under some of sympy's random evaluation points, and a test run hung)."""
    q = model.q[0]
    x = to_unicode(model.readable(q))
    top = _numerator(value)
    if trig_transcendental(top, q):
        return f"transcendental in {x}: no substitution makes it a polynomial"
    if has_root(top, (q,)):
        return f"{x} under a radical: squared away, a polynomial of high degree"
    if any(sine_cosine_quartic(f, q) for f, _ in sp.factor_list(top)[1]):
        return f"sin {x} and cos {x} mixed: a quartic in tan({x}/2), whose closed forms no reader uses"
    return f"transcendental in {x}: no substitution makes it a polynomial"


IMPLICIT_DEGREE = 3  # a factor of this degree in sin q (cos q) is left as its equation


def _closed_zeros(top: sp.Expr, q: sp.Symbol, model: Model) -> list[sp.Relational]:
    """cos q = c where top is a polynomial in cos q alone, sin q = c in sin q alone,
    else sympy's roots in q (each of degree < 3 in sin q and cos q: ``_implicit``)."""
    c = sp.Dummy("c", real=True)
    for f in (sp.cos, sp.sin):
        swapped = top.xreplace({f(q): c})
        if not swapped.has(q):
            roots = [r for r in _real_roots(swapped, c, model) if _within_one(r, model)]
            return [sp.Eq(f(model.to_time(q)), r) for r in roots]
    return [sp.Eq(model.to_time(q), r) for r in _real_roots(top, q, model)]


def _implicit(factor: sp.Expr, q: sp.Symbol, model: Model) -> sp.Relational | None:
    """P(sin q) = 0 (P(cos q) = 0), its highest coefficient positive, for a factor that
    is a polynomial of degree 3 or more in one of them, the other in even powers only."""
    c = sp.Dummy("c", real=True)
    for f, other in ((sp.sin, sp.cos), (sp.cos, sp.sin)):
        swapped = _even_powers_swapped(factor, q, other, f).xreplace({f(q): c})
        if swapped.has(q) or sp.degree(swapped, c) < IMPLICIT_DEGREE:
            continue
        side = sp.expand(-swapped if sp.Poly(swapped, c).LC().could_extract_minus_sign() else swapped)
        return sp.Eq(side.xreplace({c: f(model.to_time(q))}), 0)
    return None


def _even_powers_swapped(expr: sp.Expr, q: sp.Symbol, other, f) -> sp.Expr:
    """expr with other(q)² = 1 − f(q)² put in, where other(q) enters in even powers only."""
    x = sp.Dummy("x")
    swapped = sp.expand(expr).xreplace({other(q): x})
    if not swapped.has(x):
        return expr
    try:
        poly = sp.Poly(swapped, x)
    except sp.PolynomialError:
        return expr
    if any(k % 2 for (k,) in poly.monoms()):
        return expr
    return sp.expand(swapped.xreplace({x: sp.sqrt(1 - f(q) ** 2)}))


def is_implicit(where: sp.Relational) -> bool:
    """A zero left as its equation, P(sin q) = 0 (``zeros``): not cos q = c nor q = c."""
    return where.rhs == 0 and not isinstance(where.lhs, (sp.sin, sp.cos)) and not where.lhs.is_Function


def _real_roots(expr: sp.Expr, x: sp.Symbol, model: Model) -> list[sp.Expr]:
    """sympy's roots of expr in x (``radical_roots`` where x stands under a radical),
    those that may be real (no Piecewise, no i, no NaN)."""
    try:
        roots = radical_roots(expr, x, model) if has_root(expr, (x,)) else sp.solve(expr, x)
    except NotImplementedError:
        return []
    return [r for r in roots if not r.has(sp.Piecewise, sp.I, sp.nan, sp.zoo) and r.is_real is not False]


def _within_one(r: sp.Expr, model: Model) -> bool:
    """|r| ≤ 1, where the parameters' values or signs decide it (undecided: kept)."""
    value = r.xreplace(model.decided_by) if model.decided_by else r
    if value.is_real is False:
        return False
    if value.is_number:
        z = complex(sp.N(value, 30))
        return abs(z.imag) <= 1e-20 * max(1.0, abs(z.real)) and abs(z.real) <= 1 + 1e-15
    return True


SIMPLIFY_OPS = 80  # the least μ is simplified by sympy up to this many operations


def least_mu(F: sp.Expr, N: sp.Expr, model: Model) -> sp.Expr:
    """μ ≥ |F|/N: the friction a rolling contact needs, over the normal push; |…| kept
    where neither the parameters' signs nor their values decide the sign, nor the
    assumptions, nor where the contact holds at all (N ≥ 0: a cylinder on an incline
    pushes only for α ≤ π/2, where tan α ≥ 0, so μ ≥ tan(α)/3). Once per model and
    pair: the condition that the contact holds at the state and the least μ there ask
    for the same one (a slab released on a drum: 0.1 s each)."""
    return _least_mu(model, F, N)


@memoized
def _least_mu(model: Model, F: sp.Expr, N: sp.Expr) -> sp.Expr:
    ratio = clean_fraction(F / N)
    if sp.count_ops(ratio) <= SIMPLIFY_OPS:  # a longer one (a slab rolling on a drum): minutes of trigsimp
        ratio = _simplified(ratio)
    sign = sign_of(ratio, model.decided_by)
    if isinstance(sign, Undecided):
        pushes = _nonnegative(N, model).condition if not N.has(*model.q) else sp.true
        if implies(model.assumptions, sp.Ge(ratio, 0)) or _on(pushes, sp.Ge(ratio, 0)):  # tan α ≥ 0 under 0 < α < π/2
            return ratio
        if implies(model.assumptions, sp.Le(ratio, 0)) or _on(pushes, sp.Le(ratio, 0)):
            return -ratio
        return sp.Abs(ratio)
    return ratio if sign >= 0 else -ratio


@functools.lru_cache(maxsize=256)
def _simplified(ratio: sp.Expr) -> sp.Expr:
    """sympy's simplify, once per ratio: a rolling contact's least μ is asked at the
    state and again by its check (a quarter disk released from rest: 0.3 s each time)."""
    return sp.simplify(ratio)


def _on(where: sp.Basic, relation: sp.Basic) -> bool:
    """Whether ``relation`` holds inside the set ``where`` allows, both in one parameter
    p (its boundary left out, where the ratio may not be defined: tan α at α = π/2)."""
    free = relation.free_symbols
    if len(free) != 1 or where in (sp.true, sp.false) or where.free_symbols != free:
        return False
    (p,) = free
    try:
        allowed = sp.Intersection(where.as_set(), sp.Interval.open(0, sp.oo) if p.is_positive else sp.S.Reals)
        inside = allowed.interior
        return not inside.is_empty and inside.is_subset(sp.solveset(relation, p, inside)) is True
    except (NotImplementedError, TypeError, ValueError):
        return False


@dataclass(frozen=True)
class Holds:
    """When one support holds at the state: the condition (true, false, or solved for one
    parameter) and the critical values it uses."""

    condition: sp.Basic
    criticals: tuple[Critical, ...]


def holds(s: Held, values: dict[str, sp.Expr], model: Model) -> Holds:
    """N ≥ 0 (T ≥ 0) for each push or tension, and μ ≥ |F|/N for a rolling contact's
    friction, at the state (``values``: component name -> value there)."""
    condition, criticals = sp.true, []
    for c in s.components:
        if c.one_sided:
            found = _nonnegative(values[str(c.symbol)], model)
            condition, criticals = sp.And(condition, found.condition), criticals + list(found.criticals)
    if s.how is How.ROLLING and condition is not sp.false:
        N, F = (values[str(c.symbol)] for c in s.components)
        if not simplifies_to_zero(N):
            condition = sp.And(condition, sp.Ge(mu(s.name), least_mu(F, N, model)))
    return Holds(condition, tuple(criticals))


def mu(name: str) -> sp.Symbol:
    return sp.Symbol(f"mu_{name}")


def _nonnegative(value: sp.Expr, model: Model) -> Holds:
    """value ≥ 0: decided by the parameters' signs, else solved for one parameter (a
    rate first), else left as it is (``nonnegative_where``)."""
    found = nonnegative_where(value, model)
    return Holds(found.condition, found.criticals)


@dataclass(frozen=True)
class Release:
    """A push or tension at the release from rest (q̇ = 0 there), and where each push and
    tension of its support is ≥ 0 there (``held``, friction aside: ``pushes_held``)."""

    push: sp.Expr
    held: sp.Basic


def pushes_held(found: Holds, name: str) -> sp.Basic:
    """Where a support's pushes and tensions are ≥ 0 at the state: ``holds``' condition
    without its friction's μ ≥ |F|/N."""
    return sp.And(*(part for part in sp.And.make_args(found.condition) if not part.has(mu(name))))


def exists(where: sp.Relational, model: Model, rate_squared: sp.Expr, start: sp.Expr | None,
           release: Release) -> Holds:
    """Where the motion from rest reaches a zero cos q = c (sin q = c, q = c) as a loss: |c| ≤ 1,
    and q̇² ≥ 0 there (the motion turns back before a zero where q̇² < 0 — a cylinder released
    inside a cylinder below the horizontal never leaves it); each solved for one parameter
    where the parameters' signs do not decide it. A zero left as its equation (``is_implicit``)
    is reached where, at the values, one of its roots lies on the way from ``start``.

    A zero is where the support lets go only if it held at the release (``release``). A disk
    released inside a track has N = m g cos θ₀ there and N = 0 at cos θ = 4/7 cos θ₀, where
    q̇² = −4 g cos θ₀/(7 (R − r)): q̇² there and N at the release have opposite signs for
    every value (``_opposed``), so the zero is reached only where the disk has left the track
    at once, and rises back through zero there: no loss. Likewise where the two conditions
    leave no room but a point (θ₀ ≥ π/2 and θ₀ ≤ π/2, ``leaves_no_room``). Elsewhere the
    condition given is the zero's own; the release's is said at the release."""
    rate = _rate_at(where, model, rate_squared)
    if rate is not None and _opposed(rate, release.push, model):
        return Holds(sp.false, ())
    parts = [_reached(where, rate, model, rate_squared, start)]
    c = where.rhs
    if isinstance(where.lhs, (sp.cos, sp.sin)) and c.free_symbols and not _within(c):
        parts += [_nonnegative(1 - c, model), _nonnegative(1 + c, model)]
    condition = sp.And(*(h.condition for h in parts))
    if leaves_no_room(sp.And(condition, release.held), model):
        return Holds(sp.false, ())
    return Holds(condition, tuple(c for h in parts for c in h.criticals))


def _opposed(a: sp.Expr, b: sp.Expr, model: Model) -> bool:
    """Whether a and b have opposite signs for every value the assumptions allow, so that
    a ≥ 0 and b ≥ 0 hold together only where both vanish: a/b < 0, decided by signs."""
    if simplifies_to_zero(b):
        return False
    return sign_for_every_value(a / b, model) == -1


def _rate_at(where: sp.Relational, model: Model, rate_squared: sp.Expr) -> sp.Expr | None:
    """q̇² at the zero: q̇²(q) with cos q = c put in (sin² q = 1 − c²; likewise for
    sin q = c), or q = c; None where q̇² holds q otherwise, or the zero is left as its
    equation (``is_implicit``)."""
    if is_implicit(where):
        return None
    q = model.q[0]
    side = where.lhs.xreplace({model.to_time(q): q})
    c = where.rhs
    if side == q:
        value = rate_squared.xreplace({q: c})
    else:
        other = sp.sin(q) if isinstance(side, sp.cos) else sp.cos(q)
        value = sp.expand(rate_squared).xreplace({side: c}).subs(other**2, 1 - c**2)
    return None if value.has(q) else clean_fraction(value)


def _reached(where: sp.Relational, rate: sp.Expr | None, model: Model, rate_squared: sp.Expr,
             start: sp.Expr | None) -> Holds:
    """q̇² ≥ 0 at the zero (``rate``, ``_rate_at``); kept (true) where q̇² holds q there
    otherwise. A zero left as its equation (``is_implicit``) is reached unless, at the
    values, the motion gets to none of its roots (``_never_reached``)."""
    if is_implicit(where):
        return Holds(sp.false if _never_reached(where.lhs, model, rate_squared, start) else sp.true, ())
    return Holds(sp.true, ()) if rate is None else _nonnegative(rate, model)


def implicit_variable(where: sp.Relational, model: Model) -> sp.Expr:
    """sin q(t) (cos q(t)) of a zero left as its equation, P(sin q) = 0."""
    q = model.to_time(model.q[0])
    return next(a for a in where.lhs.atoms(sp.sin, sp.cos) if a.args[0] == q)


def _never_reached(P: sp.Expr, model: Model, rate_squared: sp.Expr, start: sp.Expr | None) -> bool:
    """At the parameters' values, P(sin q) = 0 (P(cos q) = 0) has no real root x with
    |x| ≤ 1 whose angles (asin x and π − asin x; ± acos x) the motion released from rest
    at ``start`` gets to (``first_zero.reaches``); the roots to 30 digits (mpmath's
    polyroots). False where the values do not decide it."""
    f = implicit_variable(sp.Eq(P, 0, evaluate=False), model)
    values, x = dict(model.values), sp.Dummy("x")
    poly = sp.Poly(P.xreplace(values).xreplace({f: x}), x)
    if start is None or any(not c.is_number for c in poly.all_coeffs()):
        return False
    with mpmath.workdps(30):
        roots = mpmath.polyroots([mpmath.mpmathify(sp.N(c, 30)) for c in poly.all_coeffs()], maxsteps=200,
                                 extraprec=60)
    real = [float(mpmath.re(r)) for r in roots if abs(mpmath.im(r)) <= 1e-20 and abs(mpmath.re(r)) <= 1 + 1e-20]
    q = model.q[0]
    for c in (max(min(c, 1.0), -1.0) for c in real):
        angles = (math.asin(c), math.pi - math.asin(c)) if isinstance(f, sp.sin) else (math.acos(c), -math.acos(c))
        if any(reaches(rate_squared, q, start, sp.Float(a, 17), values) is not False for a in angles):
            return False
    return True


def _within(c: sp.Expr) -> bool:
    """|c| ≤ 1 for every value of the angles in it: each sine and cosine of a parameter
    put in as the interval [−1, 1] (interval arithmetic bounds c from outside)."""
    box = {f: sp.AccumBounds(-1, 1) for f in c.atoms(sp.sin, sp.cos)}
    bound = c.xreplace(box)
    if not isinstance(bound, sp.AccumBounds) or bound.free_symbols:
        return False
    return bool(bound.min >= -1) and bool(bound.max <= 1)
