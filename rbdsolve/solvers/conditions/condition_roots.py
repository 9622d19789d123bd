"""Where a quantity's sign may change along one parameter: the roots of its numerator
and denominator inside the parameter's range, in increasing order, and the random
parameter values that decide what sympy cannot (``conditions.py`` builds the pieces).

A root counts when it is real and inside the range at every one of SAMPLES admissible
parameter points (the problem's assumptions hold there; angles are drawn in their
ranges), with the same order among the roots at each; a root inside at some points and
not at others leaves the parameter undecided (None), so that no condition is printed
that holds only somewhere.
"""

from __future__ import annotations

import math
import random

import sympy as sp

from rbdsolve.form.tidy import square_root, tidy
from rbdsolve.form.zero import simplifies_to_zero
from rbdsolve.solvers.conditions.polynomial import trig_transcendental

SAMPLES = 8
TRIG = (sp.sin, sp.cos, sp.tan, sp.cot, sp.sec, sp.csc)


def angle_parameters(f: sp.Basic) -> dict[sp.Symbol, tuple[sp.Expr, sp.Expr]]:
    """{p: its range} for the parameters f holds only through sines and cosines of
    whole multiples of them: (0, π) for a positive one, (−π, π) otherwise."""
    out = {}
    for p in sorted(f.free_symbols, key=str):
        trig = [t for t in f.atoms(*TRIG) if t.has(p)]
        if not trig or not all((t.args[0] / p).is_Integer for t in trig):
            continue
        if not f.xreplace({t: sp.Dummy() for t in trig}).has(p):
            out[p] = (sp.Integer(0), sp.pi) if p.is_positive else (-sp.pi, sp.pi)
    return out


def admissible(model, rng: random.Random, leave: tuple = (), angles: dict = {}) -> dict | None:
    """Random parameter values that satisfy the problem's assumptions (the parameters in
    ``leave`` left out: a piece sets them), angles in their ranges, or None if none is
    found. A parameter the problem gives a value keeps it: a condition is split at the
    problem's own values (a top's least spin at its given tilt and sizes)."""
    from rbdsolve.model.assumptions import admissible_sample

    symbols = [s for s in model.symbols.parameters.values() if s not in leave]
    kept = [a for a in model.assumptions if not a.difference.free_symbols & set(leave)]
    given = {s: v for s, v in model.values.items() if s not in leave}
    return admissible_sample(kept, model.symbols, rng, fixed=given, symbols=symbols, tries=200, ranges=angles)


def parameter_roots(f: sp.Expr, p: sp.Symbol, angles: dict, model) -> list[sp.Expr] | None:
    """The roots in p of f's numerator and denominator strictly inside p's range
    ((0, ∞), or an angle's, turned into it by whole turns), in increasing order; None
    where a root is inside at some samples and not at others, or the order changes."""
    low, high = angles.get(p, (sp.Integer(0), sp.oo))
    numerator, denominator = sp.fraction(sp.together(f))
    factors = [factor for factor in (numerator, denominator) if factor.has(p)]
    if any(_under_long_radical(factor, p) or trig_transcendental(factor, p) or _in_absolute_value(factor, p)
           for factor in factors):
        # sympy's solve squares the radicals away, searches a transcendental one, or splits |…| into
        # cases: minutes (issue 37), and roots under conditions of their own; decided by the structure
        return None
    try:
        found = {tidy(r) for factor in factors for r in _roots_in(factor, p)}
    except (NotImplementedError, ValueError):
        return None
    points = [admissible(model, random.Random(21 + k), (p,), angles) for k in range(SAMPLES)]
    if None in points:
        return None
    inside: dict[sp.Expr, list[float]] = {}
    # in sort order, not the set's (the hash seed's): of two forms of one root the first
    # is kept, and two that simplify cannot tell equal keep this order among equal values
    for r in sorted(found, key=sp.default_sort_key):
        if r.has(sp.DiracDelta, sp.sign, sp.Heaviside, sp.Piecewise, sp.nan):
            # not a number at a sample (DiracDelta(0) where a spring passes zero length), or
            # a root solve gives only under a condition of its own (Piecewise((…, cond), (nan, True)))
            return None
        try:
            turns = {_turns_at(r.xreplace(point), low, high, p in angles) for point in points}
        except TypeError:  # still not a number at a sample: the parameter is left undecided
            return None
        if turns == {None}:
            continue  # never real inside the range
        if len(turns) != 1 or None in turns:
            return None
        turned = tidy(r + 2 * sp.pi * turns.pop()) if p in angles else _one_root(r)
        if not any(simplifies_to_zero(turned - x) for x in inside):
            inside[turned] = [float(sp.N(turned.xreplace(point), 20)) for point in points]
    order = sorted(inside, key=lambda r: inside[r][0])
    if any(sorted(inside, key=lambda r: inside[r][k]) != order for k in range(len(points))):
        return None
    return order


def _roots_in(factor: sp.Expr, p: sp.Symbol) -> list[sp.Expr]:
    """The roots of ``factor`` in p: a polynomial of degree ≤ 2 in p by sympy's roots
    (the formula: a discriminant's I₃² s² − 4 (I₁ − I₃) m g h cos θ has ±s_c),
    without solve's checks of each root, which cost a third of a second there and
    which the samples below make again; one of higher degree factor by factor
    (``_factor_by_factor``); anything else by sympy's solve."""
    if factor.is_polynomial(p):
        polynomial = sp.Poly(factor, p)
        if polynomial.degree() <= 2:
            found = sp.roots(polynomial)
            if sum(found.values()) == polynomial.degree():
                return list(found)
        else:
            return _factor_by_factor(polynomial)
    return sp.solve(factor, p)


def _factor_by_factor(polynomial: sp.Poly) -> list[sp.Expr]:
    """The roots in p of a polynomial of degree 3 or more, factor by factor: a factor of
    degree ≤ 2 by the formula, a quadratic in p² (k² − 3 k m Ω² + m² Ω⁴) as ±√u for each
    root u of it (Ω_c = √(k (3 − √5)/(2 m))); NotImplementedError (the parameter left
    undecided) where a factor needs Cardano's or Ferrari's formula: a root of a general
    cubic or quartic in the parameters is no condition a reader can use. sympy's solve,
    which this replaces for them, spent tens of seconds on a quadratic in r² with four
    other parameters (a disk with a weight rolling in a track, its λ about an
    equilibrium at acos c: 1.3 s became 33 s); the factors and the formula take
    milliseconds. Decided by the structure, not by a budget."""
    p, u = polynomial.gen, sp.Dummy("u")
    found: list[sp.Expr] = []
    for factor, _ in sp.factor_list(polynomial)[1]:
        if factor.degree() <= 2:
            found += _formula(factor)
        elif factor.degree() == 4 and all(d % 2 == 0 for (d,) in factor.monoms()):
            halved = sp.Poly(factor.as_expr().xreplace({p: sp.sqrt(u)}), u)
            found += [s * sp.sqrt(root) for root in _formula(halved) for s in (1, -1)]
        else:
            raise NotImplementedError(f"a factor of degree {factor.degree()} in {p} needs a cubic or quartic "
                                      "formula")
    return found


def _formula(polynomial: sp.Poly) -> list[sp.Expr]:
    """The roots of a polynomial of degree ≤ 2 (sympy's roots: the formula)."""
    found = sp.roots(polynomial)
    if sum(found.values()) != polynomial.degree():
        raise NotImplementedError(f"no roots found of {polynomial.as_expr()}")
    return list(found)


RADICAL_OPS = 40  # a longer expression with p under a radical is not given to sympy's solve


def _under_long_radical(expr: sp.Expr, p: sp.Symbol) -> bool:
    """Does p stand under a radical (a fractional power) in an expression longer than
    RADICAL_OPS operations? Two springs of natural length on an inverted rod give
    √(4a² + d²) beside a² k: solving that for a ran for minutes."""
    radical = any(w.exp.is_Rational and not w.exp.is_Integer and w.base.has(p) for w in expr.atoms(sp.Pow))
    return radical and sp.count_ops(expr) > RADICAL_OPS


def _in_absolute_value(expr: sp.Expr, p: sp.Symbol) -> bool:
    """Does p stand inside |…| or sign(…) within a sum? sympy's solve splits those into
    cases: for a half-cylinder on an incline, 12 π sin α |sin α| − 4 √(16 − 9 π² sin² α)
    cos α − 9 π took it 20 s, for a root valid only under a condition of its own (the
    same without the |…|: 1 s). A |u| that multiplies the whole factor (a ladder's
    (1 + 3 cos² θ₀) |cos θ₀|) only adds the roots of u, which solve finds at once."""
    outer = {f.base if f.is_Pow else f for f in sp.Mul.make_args(expr)}
    return any(x.has(p) and x not in outer for x in expr.atoms(sp.Abs, sp.sign))


def _turns_at(root: sp.Expr, low, high, periodic: bool) -> int | None:
    """``_turns_into`` for a root at a sample point (an exact number), to 20 digits; a
    value within 1e-12 of a lower end 0, which that tolerance cannot tell from 0 (a
    critical g of 3e-15 at a sample with J3 = 0.001), is taken to 50, where evalf tells a
    true 0 (given as 0) from a small positive value."""
    z = complex(sp.N(root, 20))
    if low == 0 and not periodic and 0 < z.real <= 1e-12 and abs(z.imag) <= 1e-12:
        precise = complex(sp.N(root, 50))
        return 0 if precise.real > 0 and abs(precise.imag) <= 1e-12 * precise.real else None
    return _turns_into(z, low, high, periodic)


def _turns_into(z: complex, low, high, periodic: bool) -> int | None:
    """The whole turns k (0 unless ``periodic``) that put the real value z + 2πk
    strictly inside (low, high); None if z is not real or no turn does."""
    if abs(z.imag) > 1e-12 * max(1.0, abs(z.real)):
        return None
    a, b = float(low), float(high)
    k = math.floor((a - z.real) / (2 * math.pi)) + 1 if periodic else 0
    value = z.real + 2 * math.pi * k
    above = value > a + 1e-12 * max(1.0, abs(a))
    below = b == math.inf or value < b - 1e-12 * max(1.0, abs(b))
    return k if above and below else None


def _one_root(value: sp.Expr) -> sp.Expr:
    """√g/√R as √(g/R), the form an exam writes (kept unevaluated: sympy would split
    the root of a quotient of positive symbols again)."""
    square = sp.factor(value**2)
    if square.could_extract_minus_sign():  # −g (−2 + √2)/l: a sign taken into the sum, (2 − √2) g/l
        square = sp.factor_terms(sp.expand(value**2))
    rooted = any(square_root(p) for p in value.atoms(sp.Pow))  # 5 g m/R stays
    if rooted and not square.has(sp.sqrt) and not square.is_Pow:
        return sp.Pow(square, sp.Rational(1, 2), evaluate=False)
    return value
