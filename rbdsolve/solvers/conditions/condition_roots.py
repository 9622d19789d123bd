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
from functools import lru_cache

import mpmath
import sympy as sp

from rbdsolve.form.quotient import quotient
from rbdsolve.form.tidy import square_root, tidy
from rbdsolve.form.zero import simplifies_to_zero
from rbdsolve.model.energies.energy import memoized
from rbdsolve.solvers.conditions.polynomial import (in_sine_and_cosine, radical_linear_root, trig_transcendental,
                                                   under_long_radical)
from rbdsolve.solvers.conditions.signs import symbolic_sign

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


# A root longer than this is no critical value: a disk on an incline held by a spring of
# natural length to a point off its line has N linear in k, but its root k_c ran to 7 345
# operations (the spring's radical at the state), and testing it at the eight samples
# took 17 s of the exact route's share (a new user's file: 30 s, then the numeric route).
LONG_ROOT_OPS = 400


def _long(roots) -> bool:
    """Is any root longer than LONG_ROOT_OPS operations (as solved, or tidied)?"""
    return any(sp.count_ops(r) > LONG_ROOT_OPS for r in roots)


def parameter_roots(f: sp.Expr, p: sp.Symbol, angles: dict, model) -> list[sp.Expr] | None:
    """The roots in p of f's numerator and denominator strictly inside p's range
    ((0, ∞), or an angle's, turned into it by whole turns), in increasing order; None
    where a root is inside at some samples and not at others, or the order changes."""
    low, high = angles.get(p, (sp.Integer(0), sp.oo))
    numerator, denominator = quotient(f)
    factors = [factor for factor in (numerator, denominator) if factor.has(p)]
    if any(under_long_radical(factor, p) or _under_two_radicals(factor, p) or trig_transcendental(factor, p)
           or _in_absolute_value(factor, p) or _under_an_inverse(factor, p) for factor in factors):
        # sympy's solve squares the radicals away, searches a transcendental one, or splits |…| into
        # cases: minutes (issue 37), and roots under conditions of their own; decided by the structure
        return None
    try:
        solved = [(r, factor) for factor in factors for r in _roots_in(factor, p)]
    except (NotImplementedError, ValueError):
        return None
    if _long(r for r, _ in solved):
        return None  # no critical value a reader can use, and seconds to test at each sample
    found = {tidy(r): factor for r, factor in solved}
    if _long(found):
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
        terms = sp.Add.make_args(sp.expand(found[r]))
        roots_of_it = {vanishes_at(terms, p, r, point) for point in points}
        if roots_of_it == {False}:
            continue  # a root of the equation squared only (the radical's other sign)
        if roots_of_it != {True}:
            return None  # a root only where its own condition holds
        if p not in angles and not _positive_everywhere(r, p, model, angles):
            return None  # inside at the samples, but not where the other parameters are otherwise
        turned = tidy(r + 2 * sp.pi * turns.pop()) if p in angles else _one_root(r)
        if not any(simplifies_to_zero(turned - x) for x in inside):
            inside[turned] = [float(sp.N(turned.xreplace(point), 20)) for point in points]
    order = sorted(inside, key=lambda r: inside[r][0])
    if any(sorted(inside, key=lambda r: inside[r][k]) != order for k in range(len(points))):
        return None
    return order


MORE_SAMPLES = 64


def _positive_everywhere(root: sp.Expr, p: sp.Symbol, model, angles: dict) -> bool:
    """Is a root of a parameter p that is no angle, found inside p's range (0, ∞) at the
    SAMPLES points, inside it wherever the assumptions allow? Proved where sympy's
    assumptions give it a sign (√(g/R) > 0), else judged at MORE_SAMPLES further
    admissible points: a root that leaves the range where the other parameters are
    otherwise is no critical value of every case. A rod
    on a spring of natural length L₀ hanging from h above its pivot, modes about θ = π
    with |4h − 3l| = D: k_c = g m D/(3h (D − 4L₀)) is positive only where D > 4L₀, which
    all eight samples happened to draw; where D < 4L₀ the mode grows for every k, and
    "oscillation when k > k_c" was printed for it (seed 2039, scene 61)."""
    if symbolic_sign(root) == 1:
        return True
    points = _more_points(model, p, tuple(sorted(angles.items(), key=str)))
    names = sorted(root.free_symbols, key=str)
    if not points or not set(names) <= set(points[0]):
        return False  # a name the points do not set: no number
    at = sp.lambdify(names, root, modules="mpmath")  # once: evalf took 0.1 s a point on a long root
    with mpmath.workdps(20):
        for point in points:
            try:
                z = complex(at(*(mpmath.mpf(sp.N(point[n], 25)._mpf_) for n in names)))
            except (TypeError, ValueError, ZeroDivisionError):  # no number at a point: undecided
                return False
            # within rounding of 0: exactly, as at the first samples (``_turns_at``)
            if (_turns_at(root.xreplace(point), 0, sp.oo, False) if abs(z) <= 1e-10
                    else _turns_into(z, 0, sp.oo, False)) is None:
                return False
    return True


@memoized
def _more_points(model, p: sp.Symbol, angles: tuple) -> tuple[dict, ...]:
    """MORE_SAMPLES admissible points with p left out (``admissible``), once per parameter."""
    seeds = (random.Random(1000 + k) for k in range(MORE_SAMPLES))
    found = (admissible(model, rng, (p,), dict(angles)) for rng in seeds)
    return tuple(point for point in found if point is not None)


@lru_cache(maxsize=512)  # a condition's partition and its test of one sign ask for the same factor's roots
def _roots_in(factor: sp.Expr, p: sp.Symbol) -> tuple[sp.Expr, ...]:
    """``_solved``, once per factor and parameter."""
    return tuple(_solved(factor, p))


def radical_roots(expr: sp.Expr, x: sp.Symbol, model) -> list[sp.Expr]:
    """The roots in x of expr, where x stands under a radical: sympy's solve without its
    checks, and those of the equation squared only (the radical's other sign) dropped: a
    root is kept unless, at every sample point, it is a real number where expr is not
    zero. sympy's checksol ran simplify on each root for 3–10 s (a hoop on an incline
    held by a spring of natural length to a point above it: N ∝ g m √Q + k l₀² − k l₀ √Q,
    Q quadratic in x), and kept the roots it could not decide, as this does. (solve's
    own simplify of the roots stays: tidy wrote (g m − k l₀)² expanded.)"""
    roots = sp.solve(expr, x, check=False)
    points = [point for point in (admissible(model, random.Random(21 + k)) for k in range(SAMPLES))
              if point is not None]
    terms = sp.Add.make_args(sp.expand(expr))
    return [r for r in roots if not points or not all(_no_root_at(terms, x, r, point) for point in points)]


def _no_root_at(terms: tuple[sp.Expr, ...], x: sp.Symbol, root: sp.Expr, point: dict) -> bool:
    """Is the root, at one sample point, a real number where the sum of ``terms`` is not
    zero? False where that cannot be said (no number there)."""
    try:
        z = complex(sp.N(root.xreplace(point), 20))
        return abs(z.imag) <= 1e-12 * max(1.0, abs(z.real)) and not vanishes_at(terms, x, root, point)
    except TypeError:
        return False


def vanishes_at(terms: tuple[sp.Expr, ...], p: sp.Symbol, root: sp.Expr, point: dict) -> bool:
    """Is the factor, the sum of ``terms`` (expanded), zero at the root, at one sample
    point, to 20 digits of its terms' size? Squaring keeps every root and adds the
    radical's other sign's."""
    value = root.xreplace(point)
    numbers = [sp.N(t.xreplace(point).xreplace({p: value}), 30) for t in terms]
    size = max(abs(complex(x)) for x in numbers)
    return abs(complex(sp.Add(*numbers))) <= 1e-20 * max(size, 1e-300)


def _solved(factor: sp.Expr, p: sp.Symbol) -> list[sp.Expr]:
    """The roots of ``factor`` in p: a polynomial of degree ≤ 2 in p by sympy's roots
    (the formula: a discriminant's I₃² s² − 4 (I₁ − I₃) m g h cos θ has ±s_c),
    without solve's checks of each root, which cost a third of a second there and
    which the samples below make again; one of higher degree factor by factor
    (``_factor_by_factor``); a polynomial in sin p or cos p the same way in them
    (``_in_sine_or_cosine``); a radical √X, times factors free of p, by X's (a
    half-disk's push on an incline, R g m √(16 − 9π² sin²β): sympy's solve took a quarter
    of a second for what sin β = ±4/(3π) gives); anything else by sympy's solve."""
    radicand = _lone_radicand(factor, p)
    if radicand is not None:
        return _solved(radicand, p)
    if factor.is_polynomial(p):
        polynomial = sp.Poly(factor, p)
        plain = radical_linear_root(polynomial)
        if plain is not None:
            return [plain]
        if polynomial.degree() > 2:
            return _factor_by_factor(polynomial)
        found = sp.roots(polynomial)
        return list(found) if sum(found.values()) == polynomial.degree() else sp.solve(factor, p)
    squared = _squared_once(factor, p)
    if squared is not None:
        try:
            return _solved(squared, p)  # its extra roots are dropped where the factor is not zero (the samples)
        except NotImplementedError:
            if sp.degree(squared, p) > 2:
                # the roots are a cubic's or quartic's, the radical's or the square's alike: no
                # condition a reader can use, and sympy's solve spent minutes finding it (a plate
                # on a spring of natural length, its anchor's height h: 51 s and on)
                raise
            return sp.solve(factor, p)
    in_sine_or_cosine = _in_sine_or_cosine(factor, p)
    if in_sine_or_cosine is None:
        half = _half_angle(factor, p)
        if half is None:
            half = _double_angle(factor, p)
        return half if half is not None else sp.solve(factor, p)
    polynomial, x = in_sine_or_cosine
    try:
        roots = _roots_in(polynomial, x)
    except NotImplementedError:
        return sp.solve(factor, p)  # a cubic or quartic in sin p or cos p: solve's own way, as before
    if x is _SINE:
        return [angle for r in roots for angle in (sp.asin(r), sp.pi - sp.asin(r))]
    return [sign * sp.acos(r) for r in roots for sign in (1, -1)]


_COSINE, _SINE, _ROOT = sp.Dummy("c"), sp.Dummy("s"), sp.Dummy("r")


def _lone_radicand(factor: sp.Expr, p: sp.Symbol) -> sp.Expr | None:
    """X where ``factor`` is c·√X with c free of p (√X = 0 exactly where X = 0); else None."""
    parts = [f for f in sp.Mul.make_args(factor) if f.has(p)]
    if len(parts) == 1 and isinstance(parts[0], sp.Pow) and parts[0].exp == sp.S.Half:
        return parts[0].base
    return None


def _squared_once(factor: sp.Expr, p: sp.Symbol) -> sp.Expr | None:
    """A + B √X = 0 with A, B, X polynomials in p, squared: A² − B² X, a polynomial
    whose roots hold the factor's (and the radical's other sign's, which the samples
    drop). A spring of natural length put at a configuration: 12 L₀ k (h + l) − 12 L₀ k
    √(h² + h l + l²) + 3 g l m − 6 h k l, which sympy's solve took 2 s to solve for l.
    None where p stands under no radical, or under more than one, or not so."""
    radicals = {w for w in factor.atoms(sp.Pow) if w.exp == sp.S.Half and w.base.has(p)}
    if len(radicals) != 1:
        return None
    (radical,) = radicals
    plain = sp.expand(factor.xreplace({radical: _ROOT}))
    if not (plain.is_polynomial(_ROOT, p) and radical.base.is_polynomial(p)):
        return None
    linear = sp.Poly(plain, _ROOT)
    if linear.degree() != 1:
        return None
    B, A = linear.all_coeffs()
    return sp.expand(A**2 - B**2 * radical.base)


def _in_sine_or_cosine(factor: sp.Expr, p: sp.Symbol) -> tuple[sp.Expr, sp.Dummy] | None:
    """``factor`` as a polynomial in s = sin p where cos p is absent (p = asin s or
    π − asin s), or in c = cos p where sin p stands only in even powers (a release
    angle's condition, (3072 π² − 5184) sin²θ₀ + (6480 − 3840 π²) cos θ₀ + …: sin² p =
    1 − c², p = ±acos c); whole turns are the caller's. The roots sympy's solve finds
    after trying its rewrites for a second or more, in its forms. None where p stands
    elsewhere, in a multiple angle, or in an odd power of sin p beside cos p."""
    plain = in_sine_and_cosine(factor, p, _SINE, _COSINE)
    if plain is None:
        return None
    if not plain.has(_COSINE):
        return plain, _SINE
    sines = sp.Poly(plain, _SINE)
    if any(k % 2 for (k,) in sines.monoms()):
        return None
    return sp.expand(sum(c * (1 - _COSINE**2) ** (k // 2) for (k,), c in sines.terms())), _COSINE


def _half_angle(factor: sp.Expr, p: sp.Symbol) -> list[sp.Expr] | None:
    """The roots in p of a sin p + b cos p + c (p nowhere else: a block pulled up a rough
    incline, (μ cos α + sin α) M k² + … = 0), by t = tan(p/2): sin p = 2t/(1 + t²), cos p =
    (1 − t²)/(1 + t²) give (c − b) t² + 2 a t + (b + c) = 0, so p = 2 atan(t) for each real t
    (p = π itself where c = b, t's degree drops). sympy's solve took 12 s on it, mostly
    checking its roots, which the samples after this check again. None for another form."""
    plain = in_sine_and_cosine(factor, p, _SINE, _COSINE)
    if plain is None or sp.Poly(plain, _SINE, _COSINE).total_degree() != 1:
        return None
    a, b = plain.coeff(_SINE), plain.coeff(_COSINE)
    c = sp.expand(plain - a * _SINE - b * _COSINE)
    t = sp.Dummy("t")
    quadratic = sp.Poly((c - b) * t**2 + 2 * a * t + (b + c), t)
    found = sp.roots(quadratic)
    if sum(found.values()) != quadratic.degree():
        return None
    return [2 * sp.atan(tidy(r)) for r in found] + ([sp.pi] if quadratic.degree() < 2 else [])


def _double_angle(factor: sp.Expr, p: sp.Symbol) -> list[sp.Expr] | None:
    """The roots in p of a quadratic form in sin p and cos p plus a constant (sin 2p and
    cos 2p expanded first: a ladder pushed at its foot, 3 P sin 2φ₀ − 3 g m cos² φ₀ + 4 g m),
    by the double angle: sin² p = (1 − cos 2p)/2, cos² p = (1 + cos 2p)/2, sin p cos p =
    sin 2p/2 make it a sin 2p + b cos 2p + c, whose half angle is p: with t = tan p,
    (c − b) t² + 2 a t + (b + c) = 0, and p = atan t or atan t + π for each real t (p = ±π/2
    where c = b). sympy's solve took 7 s on the ladder's. None for another form."""
    plain = in_sine_and_cosine(sp.expand_trig(factor), p, _SINE, _COSINE)
    if plain is None:
        return None
    form = sp.Poly(plain, _SINE, _COSINE)
    if form.total_degree() != 2 or any(sum(m) % 2 for m in form.monoms()):
        return None
    ss, cc, sc = form.coeff_monomial(_SINE**2), form.coeff_monomial(_COSINE**2), form.coeff_monomial(_SINE * _COSINE)
    a, b, c = sc / 2, (cc - ss) / 2, form.coeff_monomial(1) + (ss + cc) / 2
    t = sp.Dummy("t")
    quadratic = sp.Poly(sp.expand((c - b) * t**2 + 2 * a * t + (b + c)), t)
    if quadratic.is_zero:
        return None
    found = sp.roots(quadratic)
    if sum(found.values()) != quadratic.degree():
        return None
    angles = [sp.atan(tidy(r)) for r in found]
    return [x for angle in angles for x in (angle, angle + sp.pi)] + (
        [sp.pi / 2, -sp.pi / 2] if quadratic.degree() < 2 else [])


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
    for factor in _irreducible(polynomial):
        if factor.degree() <= 2:
            found += _formula(factor)
        elif factor.degree() == 4 and all(d % 2 == 0 for (d,) in factor.monoms()):
            halved = sp.Poly(factor.as_expr().xreplace({p: sp.sqrt(u)}), u)
            found += [s * sp.sqrt(root) for root in _formula(halved) for s in (1, -1)]
        else:
            raise NotImplementedError(f"a factor of degree {factor.degree()} in {p} needs a cubic or quartic "
                                      "formula")
    return found


def _irreducible(polynomial: sp.Poly) -> list[sp.Poly]:
    """The irreducible factors of a polynomial in p that hold p, each a polynomial in p.
    With rational coefficients, the factors of the whole expression in all its symbols,
    found once whichever parameter is asked (the same up to sign: Gauss's lemma, a
    primitive factor irreducible over ℤ[the others][p] is irreducible in all of them): a
    rod on a spring of natural length, one condition of six parameters, was factored
    once per parameter, six times 0.2–0.3 s."""
    p, domain = polynomial.gen, polynomial.domain
    if domain.is_ZZ or domain.is_QQ or (domain.is_PolynomialRing and (domain.domain.is_ZZ or domain.domain.is_QQ)):
        # in p and the ring's own generators (cos α is one, beside the symbols), in one order whichever p
        gens = sorted({p, *(domain.symbols if domain.is_PolynomialRing else ())}, key=sp.default_sort_key)
        return [sp.Poly(factor, p) for factor in _factors_of(sp.Poly(polynomial.as_expr(), *gens)) if factor.has(p)]
    return [factor for factor, _ in sp.factor_list(polynomial)[1]]


@lru_cache(maxsize=256)
def _factors_of(whole: sp.Poly) -> tuple[sp.Expr, ...]:
    """The irreducible factors over the rationals of a polynomial in all its symbols."""
    return tuple(factor.as_expr() for factor, _ in sp.factor_list(whole)[1])


def _formula(polynomial: sp.Poly) -> list[sp.Expr]:
    """The roots of a polynomial of degree ≤ 2 (sympy's roots: the formula)."""
    found = sp.roots(polynomial)
    if sum(found.values()) != polynomial.degree():
        raise NotImplementedError(f"no roots found of {polynomial.as_expr()}")
    return list(found)


def _under_two_radicals(expr: sp.Expr, p: sp.Symbol) -> bool:
    """Does p stand under two different radicals? Squaring them away twice gives a
    quartic with roots of its own that are no roots of expr: a rod hinged at O with a
    spring of natural length L₀ from its end to a point h above O, released at 60°, has
    θ̇² ∝ 3 g l m − 6 h k l + 12 L₀ k (√(h² + 2hl + l²) − √(h² + hl + l²)) at the bottom,
    which sympy's solve took 5–7 s to solve for l and again for h (the energy question
    ran out of its 27 s share); no exam writes such a root as a condition."""
    bases = {w.base for w in expr.atoms(sp.Pow) if w.exp.is_Rational and not w.exp.is_Integer and w.base.has(p)}
    return len(bases) >= 2


INVERSES = (sp.atan2, sp.atan, sp.acot, sp.asin, sp.acos, sp.exp, sp.log)


def _under_an_inverse(expr: sp.Expr, p: sp.Symbol) -> bool:
    """Does p stand inside an inverse trigonometric function, an exponential or a
    logarithm? A hoop rolling in a track on an elastic cord to the track's point at β,
    m and k open, rests at θ* = atan2(R k sin β, m g + R k cos β), and its λ holds
    cos(β − θ*): sympy's solve for k ran past the minute's budget (a new user's trial);
    no exam writes such a root as a critical value."""
    return any(f.has(p) for f in expr.atoms(*INVERSES))


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
    the root of a quotient of positive symbols again); a root of numbers only stays as
    it is (√2 a g m/2, not √(a² g² m²/2))."""
    rooted = any(square_root(p) and p.base.free_symbols for p in value.atoms(sp.Pow))  # 5 g m/R stays
    if not rooted:
        return value
    square = sp.factor(value**2)
    if square.could_extract_minus_sign():  # −g (−2 + √2)/l: a sign taken into the sum, (2 − √2) g/l
        square = sp.factor_terms(sp.expand(value**2))
    if not square.has(sp.sqrt) and not square.is_Pow:
        return sp.Pow(square, sp.Rational(1, 2), evaluate=False)
    return value
