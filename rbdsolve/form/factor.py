"""Factored forms for reading: what a worked solution factors out of a coefficient.

    3/4 R² m − 3/2 R m r + 3/4 m r²     →   3/4 m (R − r)²
    a⁴ − a²b² − a²c² + b²c²             →   (a² − b²)(a² − c²)
    R g m − g m r                       →   g m (R − r)

``factored`` is the one rule: factor over the rationals (sin θ, cos θ, q̇ … taken as
symbols, so sin²θ + cos²θ is not touched), put a difference of squares back together
where both halves are there, and keep the result only if it is no longer than what it
replaces (counted in printed operations) — a rule that would lengthen an expression is
not applied. Nothing here changes what an expression is.
"""

from __future__ import annotations

from functools import lru_cache

import sympy as sp

from rbdsolve.form.expansion import expanded
from rbdsolve.form.printers import to_unicode
from rbdsolve.form.stand_ins import stand_ins

MAX_OPS = 120  # larger expressions are shown as they are: factoring them costs more than it reads
# ... and so are polynomials of a higher degree: count_ops sees sin⁹⁷θ as one operation, and
# factoring sin⁹⁷θ + cos⁹⁹θ's derivatives (degree ~200 in sin θ, cos θ) over the rationals
# took sympy's Zassenhaus minutes (issue 39: a model of 0.76 s took 7 s and more). An
# exam's coefficients have degree < 10.
MAX_DEGREE = 24


@lru_cache(maxsize=4096)  # one quantity is shown in several steps (T, then the equations)
def factored(expr: sp.Expr, bracketed: bool = False) -> sp.Expr:
    """``expr`` with each sum in it factored for reading (``factored_sum``), where that
    prints no longer; sin θ, cos θ, q̇ … are taken as symbols, and π too where that
    reads shorter ((7π² − 128π + 1024)/(3 (π − 16)²)). ``bracketed``: a sum would be
    printed in brackets where it stands (a coefficient before q̈), so they count."""
    if not isinstance(expr, sp.Expr) or expr.is_Atom or not _sum_outside_functions(expr):
        return expr  # a product of powers of symbols and functions: nothing to factor
    if sp.count_ops(expr) > MAX_OPS or expr.has(sp.Float) or _high_powers(expr):
        return expr
    atoms = expr.atoms(sp.Function, sp.Derivative)
    candidates = [_factored_over(expr, atoms)]
    if expr.has(sp.pi):
        candidates.append(_factored_over(expr, atoms | {sp.pi}))
    candidates.append(_number_distributed(expr))
    candidates = [c for c in candidates if c != expr]
    if not candidates:  # nothing to weigh: printing expr twice would only compare it with itself
        return expr
    best = min(candidates, key=lambda c: len(to_unicode(c)))
    # a sum of negative terms may spend its brackets: −(3/2 M r² + e² m), not (−3/2 M r² − e² m)
    negative = all(x.could_extract_minus_sign() for x in expr.args) if expr.is_Add else False
    allowance = 2 if expr.is_Add and ((bracketed and not best.is_Add) or negative) else 0
    return best if len(to_unicode(best)) <= len(to_unicode(expr)) + allowance else expr


def _high_powers(expr: sp.Expr) -> bool:
    """Is any power in ``expr`` past MAX_DEGREE (sin⁹⁷θ)?"""
    return any(p.exp.is_Integer and abs(p.exp) > MAX_DEGREE for p in expr.atoms(sp.Pow))


def _sum_outside_functions(expr: sp.Expr) -> bool:
    """Is there a sum in ``expr`` other than inside a function's arguments (sin(φ − θ)) or
    a derivative? Functions and derivatives are taken as symbols below, so without one
    every candidate form is ``expr`` itself."""
    if expr.is_Add:
        return True
    if isinstance(expr, (sp.Function, sp.Derivative)) or expr.is_Atom:
        return False
    return any(_sum_outside_functions(a) for a in expr.args)


def _factored_over(expr: sp.Expr, atoms: set) -> sp.Expr:
    """``factored_sum`` with the given atoms taken as symbols."""
    table, back = stand_ins(atoms)
    plain = expr.xreplace(table)
    if plain.is_Add:
        return _restored(factored_sum(plain, alone=True), back)
    factors = sp.Mul.make_args(plain)
    turned = [_factored_power(f) for f in factors]
    if list(factors) == turned:
        return expr  # (rebuilding the product could lose a form such as −(R + r))
    return _restored(sp.Mul(*turned), back)


def _restored(expr: sp.Expr, back: dict) -> sp.Expr:
    """The stand-ins put back without evaluating sums and products again: xreplace would
    multiply −1 (or 1/2) back into the sum that factoring took it out of."""
    if expr in back:
        return back[expr]
    if not expr.args:
        return expr
    args = [_restored(a, back) for a in expr.args]
    if isinstance(expr, (sp.Add, sp.Mul, sp.Pow)):
        return expr.func(*args, evaluate=False)
    return expr.func(*args)


def _number_distributed(expr: sp.Expr) -> sp.Expr:
    """A rational coefficient taken into a sum of numbers: 1/192 a⁴ σ (256 − 15π) as
    a⁴ σ (4/3 − 5π/64), the form the tensor's entries have."""
    coeff, rest = expr.as_coeff_Mul()
    numbers = [f for f in sp.Mul.make_args(rest) if f.is_Add and not f.free_symbols]
    over_a_sum = any(f.is_Pow and f.exp.is_negative and f.base.is_Add for f in sp.Mul.make_args(rest))
    if not coeff.is_Rational or coeff == 1 or len(numbers) != 1 or over_a_sum:
        return expr  # (31π/12 − 64/3 − π²/64)/(π − 16) would read worse than one fraction
    others = [f for f in sp.Mul.make_args(rest) if f is not numbers[0]]
    return sp.Mul(sp.expand(coeff * numbers[0]), *others)


def _factored_power(factor: sp.Expr) -> sp.Expr:
    base, exp = factor.as_base_exp()
    return factored_sum(base) ** exp if base.is_Add else factor


def factored_sum(total: sp.Add, alone: bool = False) -> sp.Expr:
    """content × primitive part, the primitive part factored over the rationals where it
    splits: 3/4 R² m − 3/2 R m r + 3/4 m r² = 3/4 m (R − r)², l₁m₁ + l₁m₂ + l₂m₁ + l₂m₂
    = (l₁ + l₂)(m₁ + m₂). The content is the common monomial, with the common rational
    when every coefficient is rational (1/12 m (4a² + b²)), and −1 when every term is
    negative; a coefficient with π keeps its fraction (R² m (3/4 − 4 cos θ/(3π))).
    ``alone``: the sum is the whole expression, not a factor beside others (k (…)), so
    a number would be all it has in front."""
    terms = sp.Add.make_args(expanded(total))
    whole, content = _content(terms, True), _content(terms, False)
    integral = _with_content(total, whole, alone)
    plain = integral if whole == content else _with_content(total, content, alone)  # no rational to take out: once
    if integral == total:
        return plain
    # whole coefficients inside, 1/2 g m (2R − a), unless that costs more than the "1/2 "
    return integral if len(to_unicode(integral)) <= len(to_unicode(plain)) + 4 else plain


def _with_content(total: sp.Add, content: sp.Expr, alone: bool) -> sp.Expr:
    """content × (total/content), the second factor factored where it splits."""
    inner = expanded(total / content)
    symbols = sorted(inner.free_symbols, key=sp.default_sort_key)
    if symbols and inner.is_polynomial(*symbols):
        poly = sp.Poly(inner, *symbols)
        if poly.total_degree() <= MAX_DEGREE and _splits(poly):
            inner = squares_joined(sp.factor(inner))
        elif alone and content.is_Number and content not in (1, -1) and any(isinstance(x, sp.Dummy) for x in symbols):
            return total  # a number alone out of a sum with sin θ, 1/8 (4cθ² − 4πcθ + …), only clutters
    elif symbols:
        whole = squares_joined(sp.factor(sp.together(total)))  # one fraction, if shorter
        if len(to_unicode(whole)) < len(to_unicode(sp.Mul(content, inner))):
            return whole
        return _polynomial_part_factored(total)
    if content == 1:
        return inner
    return sp.Mul(content, inner, evaluate=not content.is_Number)


def _polynomial_part_factored(total: sp.Add) -> sp.Expr:
    """A sum with roots in it: its polynomial terms factored among themselves, the rest
    kept, (l₂ − l₁)(m₁ + m₂) + √(m₁ + m₂) √(…) for l₂m₁ − l₁m₁ − l₁m₂ + l₂m₂ + √…"""
    symbols = sorted(total.free_symbols, key=sp.default_sort_key)
    terms = sp.Add.make_args(total)
    polynomial = [x for x in terms if x.is_polynomial(*symbols)]
    if len(polynomial) < 2 or len(polynomial) == len(terms):
        return total
    rest = [x for x in terms if not x.is_polynomial(*symbols)]
    return sp.Add(factored_sum(sp.Add(*polynomial)), *rest)


def _content(terms: tuple[sp.Expr, ...], rational: bool) -> sp.Expr:
    """The common factor of the terms of a sum: powers of the bases every term has (to
    the least power), with ``rational`` the rationals' gcd when every coefficient is
    rational, and −1 when every term is negative."""
    powers: dict[sp.Expr, sp.Expr] | None = None
    for term in terms:
        mine: dict[sp.Expr, sp.Expr] = {}
        for factor in sp.Mul.make_args(term.as_coeff_Mul()[1]):
            base, exp = factor.as_base_exp()
            if base.is_Atom and not base.is_Number and exp.is_Rational:
                mine[base] = mine.get(base, 0) + exp
        powers = mine if powers is None else {
            b: min(powers[b], mine[b]) for b in powers.keys() & mine.keys()}
    content = sp.Mul(*[b**e for b, e in (powers or {}).items()])
    coefficients = [t.as_coeff_Mul()[0] for t in terms]
    rests = [t.as_coeff_Mul()[1] / content for t in terms]
    if rational and all(c.is_Rational for c in coefficients) and not any(_irrational(r) for r in rests):
        number = sp.gcd_list([sp.Rational(c).p for c in coefficients]) / sp.ilcm(*[sp.Rational(c).q for c in coefficients])
        content *= sp.Rational(number)
    if all(c.is_negative for c in coefficients):
        content = -content
    return content


def _irrational(rest: sp.Expr) -> bool:
    """Does a term carry a number that is not rational (π, √2)?"""
    return any(f.is_number for f in sp.Mul.make_args(rest))


@lru_cache(maxsize=4096)  # factored_sum asks of one sum twice (its two contents), factored again later
def _splits(poly: sp.Poly) -> bool:
    """Whether a polynomial has more than one irreducible factor, or a repeated one."""
    if _linear_and_primitive(poly):
        return False
    factors = poly.factor_list()[1]
    return len(factors) > 1 or any(k > 1 for _, k in factors)


def _linear_and_primitive(poly: sp.Poly) -> bool:
    """p = a x + b with x of degree 1 and gcd(a, b) a number: then p is irreducible (a
    factor of p has degree 0 or 1 in x; one of degree 0 divides a and b, so is a number).
    A gcd costs far less than factoring: 1.4 ms against 13 ms for q̈'s numerator in 8
    symbols (sin θ, cos φ, g, r …) of seed problem 1."""
    for x in poly.gens:
        if poly.degree(x) == 1:
            a = poly.diff(x)
            if a.is_ground:  # gcd(a, b) divides a, so is a number: no gcd to take (V = Σ cᵢ cos θᵢ)
                return True
            b = poly - a * sp.Poly(x, *poly.gens, domain=poly.domain)
            if a.gcd(b).is_ground:
                return True
    return False


def squares_joined(expr: sp.Expr) -> sp.Expr:
    """(a − b)(a + b) → a² − b² wherever both factors are in one product (to the same
    power), as the worked solutions write (a² − b²)(a² − c²); other factors are kept."""
    if not expr.is_Mul:
        return expr
    factors = list(sp.Mul.make_args(expr))
    joined: list[sp.Expr] = []
    while factors:
        first = factors.pop(0)
        partner = _conjugate(first, factors)
        if partner is None:
            joined.append(first)
            continue
        factors.remove(partner)
        (base, exp), other = first.as_base_exp(), partner.as_base_exp()[0]
        joined.append(sp.expand(base * other) ** exp)
    return sp.Mul(*joined)


def _conjugate(factor: sp.Expr, others: list[sp.Expr]) -> sp.Expr | None:
    """The factor among ``others`` that is (u − v)**n for ``factor`` = (u + v)**n (or
    the other way round), if any: their product is u² − v²."""
    base, exp = factor.as_base_exp()
    if not (base.is_Add and len(base.args) == 2):
        return None
    u, v = base.args
    for other in others:
        b, e = other.as_base_exp()
        if e == exp and b != base and {b, -b} & {u - v, v - u}:
            return other
    return None


def no_longer(shown: sp.Expr, other: sp.Expr) -> bool:
    """Whether ``shown`` prints no longer than ``other``: then ``other`` need not follow it
    (ω₁ = √(2g/(3(R − r))), without "= 1/3 √6 √g √(1/(R − r))")."""
    return len(to_unicode(shown)) <= len(to_unicode(other))


def _length(expr: sp.Expr) -> int:
    """Printed operations: + and − count, as do products and powers; a rational
    coefficient counts once."""
    return int(sp.count_ops(expr))
