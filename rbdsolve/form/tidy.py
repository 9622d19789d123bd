"""Targeted, bounded simplification.

No blind global ``simplify``: each small coefficient of a quadratic form or of an
equation is tidied on its own with a few identities that exam solutions use
(sin² + cos² = 1, cos θ cos φ + sin θ sin φ = cos(φ − θ)), and anything larger than a
size limit is left expanded rather than risk a long simplification.
"""

from __future__ import annotations

from functools import lru_cache

import sympy as sp
from sympy.core.function import AppliedUndef
from sympy.simplify.fu import TR10i

from rbdsolve.form.expansion import expanded
from rbdsolve.form.stand_ins import stand_ins

MAX_OPS = 400  # larger coefficients are expanded but not rewritten
JOINED_OPS = 40  # radicands up to this size are factored to find the roots that join (_joined_roots)


@lru_cache(maxsize=4096)  # a coefficient recurs: T's in the equations, M's in q̈ and in the modes
def tidy(expr: sp.Expr) -> sp.Expr:
    """A short form of one coefficient.

    Targeted rules instead of ``trigsimp`` (which costs ~100 ms a call): reduce
    sin²x + cos²x = 1 (eliminating whichever of sin² and cos² leaves the shorter form),
    then fold sums of products into sums of angles, cos θ cos φ + sin θ sin φ =
    cos(φ − θ) (``fu.TR10i``), then pull out common factors.
    """
    expr = expanded(expr)
    if expr.is_Rational:
        return expr
    expr = _joined_roots(expr)
    if expr.has(sp.acos, sp.asin, sp.atan):
        expr = _of_inverses(expr)
    if _past_limit(expr):
        return expr
    if expr.has(sp.sin, sp.cos):
        expr = _pythagoras(expr)
        if _foldable(expr):
            expr = _folded(expr)
    if has_denominator(expr):
        expr = _cancel(expr)
    return _leading_plus(terms_factored(expr))


def _joined_roots(expr: sp.Expr) -> sp.Expr:
    """Square roots of the parameters whose radicands share a factor once each is over
    one denominator and factored, written so: sympy then joins their products,
    √(4 g k l m − g² m² − 3 k² l²) √(4 g m/(k l) − g² m²/(k² l²) − 3) = (4 g k l m − g² m²
    − 3 k² l²)/(k l) (positive k, l), and a tilted equilibrium's K₁₁ of four lines is
    k l²/2. (sin(acos c) = √(1 − c²) leaves 1 − c² expanded beside the c it came from.)
    Expressions whose roots share nothing are left as they are."""
    roots = [p for p in expr.atoms(sp.Pow) if p.exp == sp.S.Half and p.base.is_Add and p.base.free_symbols]
    if len(roots) < 2:
        return expr
    roots = [p for p in roots if sp.count_ops(p.base) <= JOINED_OPS]  # (factoring a long one costs 30 ms)
    if len(roots) < 2:
        return expr
    factored = {p: sp.factor(sp.together(p.base)) for p in roots}
    kernels = [{f for f in sp.Mul.make_args(sp.fraction(b)[0]) if f.is_Add or (f.is_Pow and f.base.is_Add)}
               for b in factored.values()]
    if not any(a & b for i, a in enumerate(kernels) for b in kernels[i + 1:]):
        return expr
    return expanded(expr.xreplace({p: sp.sqrt(b) for p, b in factored.items()}))


def terms_factored(expr: sp.Expr) -> sp.Expr:
    """sympy's ``factor_terms(expr)`` (a common factor pulled out of each sum, in every
    argument), or ``expr`` itself where that is what it gives: a product of a rational,
    powers of symbols, coordinates θ(t) and their derivatives, and sines and cosines of a
    symbol, a coordinate or a sum of them with unit coefficients (cos(θ₂ − θ₁)), as every
    entry of a chain's M(q) is. There factor_terms takes the rational out and puts it
    back in front of the same factors, and finds nothing to pull out of the sum (its
    terms share no factor, and not every one is negative) after walking it with gcd_terms:
    most of ``tidy``'s time on such an entry. tests/form/test_terms_factored.py checks
    the form against factor_terms."""
    if all(_kept_as_it_is(f) for f in sp.Mul.make_args(expr)):
        return expr
    return common_factors(expr)


def _kept_as_it_is(factor: sp.Expr) -> bool:
    if factor.is_Rational or factor.is_Symbol:
        return True
    if factor.is_Pow:
        return factor.base.is_Symbol and factor.exp.is_Rational
    if isinstance(factor, sp.Derivative):
        return _coordinate(factor.expr)
    if isinstance(factor, (sp.sin, sp.cos)):
        return _unit_sum(factor.args[0])
    return _coordinate(factor)


def _coordinate(expr: sp.Expr) -> bool:
    """θ(t): an undefined function of symbols."""
    return isinstance(expr, AppliedUndef) and all(x.is_Symbol for x in expr.args)


def _unit_sum(expr: sp.Expr) -> bool:
    """A symbol or a coordinate, or a sum of them each with coefficient ±1, one at least +1."""
    if expr.is_Symbol or _coordinate(expr):
        return True
    if not expr.is_Add:
        return False
    positive = False
    for term in expr.args:
        if term.is_Symbol or _coordinate(term):
            positive = True
        elif not (term.is_Mul and len(term.args) == 2 and term.args[0] is sp.S.NegativeOne
                  and (term.args[1].is_Symbol or _coordinate(term.args[1]))):
            return False
    return positive


def common_factors(expr: sp.Expr) -> sp.Expr:
    """``sp.factor_terms``: the common factors and each sum's content pulled out,
    a·b + a·c = a (b + c). Remembered for exact expressions: a report pulls them from
    the same coefficient several times (an equation's coefficients, tidied already,
    again where it is arranged; a matrix's entries for its scale), and on small
    expressions ``factor_terms`` costs more than most of what is done with them. (Not
    for floats: 0.5 at 15 and at 30 digits are equal keys.)"""
    return sp.factor_terms(expr) if expr.has(sp.Float) else _remembered_factors(expr)


_remembered_factors = lru_cache(maxsize=4096)(sp.factor_terms)


def _of_inverses(expr: sp.Expr) -> sp.Expr:
    """sin and cos of a multiple of an inverse function written out in its argument,
    cos(2 acos c) = 2 c² − 1, sin(2 acos c) = 2 c √(1 − c²), cos(3 acos c) = 4 c³ − 3 c
    (sympy's ``expand_trig``; sympy itself writes sin(acos c) = √(1 − c²) but keeps the
    multiples): an equilibrium θ₀ = acos c put into a form in 2θ, as M and K about it,
    reads as an exam writes it, in c."""
    def multiple(f: sp.Expr) -> bool:
        n, inner = f.args[0].as_coeff_Mul()
        return n.is_Integer and 1 < abs(n) <= 4 and isinstance(inner, (sp.acos, sp.asin, sp.atan))

    found = {f: sp.expand_trig(f) for f in expr.atoms(sp.sin, sp.cos) if multiple(f)}
    return expanded(expr.xreplace(found)) if found else expr


OPS_PER_NODE = 9  # count_ops(e) ≤ 9 × the nodes of e's tree (``_past_limit``)


def _past_limit(expr: sp.Expr) -> bool:
    """count_ops(expr) > MAX_OPS, counted only where the size of expr's tree leaves it
    open: a coefficient of a few dozen nodes (every entry of a chain's M(q)) is within
    the limit without counting, which would cost more than the rest of its tidying.

    The bound: count_ops walks the tree from the root, and each term it takes counts
    at most 2 operations (− and / of a rational, of a product's coefficient) plus one
    per argument it puts back to walk (the ± of a sum's terms, the × of a product's
    factors, a function or power over its arguments): at most 3 per term walked. It
    walks each node once, except that a product is first split into its numerator and
    denominator (sympy's ``fraction``), two new products of its factors (a rational
    coefficient p/q split in two): at most 3 terms walked per node. So count_ops(e) ≤
    9 × nodes(e), and a tree of at most MAX_OPS / 9 nodes is within the limit."""
    stack, nodes = [expr], 0
    while stack:
        nodes += 1
        if nodes * OPS_PER_NODE > MAX_OPS:
            return sp.count_ops(expr) > MAX_OPS
        stack.extend(stack.pop().args)
    return False


def _folded(expr: sp.Expr) -> sp.Expr:
    """``fu.TR10i``'s fold where it is shorter (no more operations than ``expr``);
    C cos a cos b + C sin a sin b, the form of every entry of a chain's M(q), read off
    its two terms directly (TR10i searches every pair of every sum for it, and neither
    form's operations need counting)."""
    folded = _cosine_of_difference(expr)
    if folded is not None:  # one cosine for two terms of two each: always shorter
        return folded
    folded = TR10i(expr)
    return folded if sp.count_ops(folded) <= sp.count_ops(expr) else expr


def _cosine_of_difference(expr: sp.Expr) -> sp.Expr | None:
    """C cos a cos b + C sin a sin b = C cos(a − b), C, a and b free of sin and cos; None
    for any other form. TR10i gives the same (tests/form/test_tidy_fold.py checks it
    against TR10i as the oracle). (cos is even: sympy writes cos(a − b) and cos(b − a) alike.)"""
    if not expr.is_Add or len(expr.args) != 2:
        return None
    (c1, f1, args1), (c2, f2, args2) = (_two_trig_factors(t) for t in expr.args)
    if c1 is None or c2 is None or {f1, f2} != {sp.cos, sp.sin} or c1 != c2 or args1 != args2:
        return None
    a, b = args1
    if a.has(sp.sin, sp.cos) or b.has(sp.sin, sp.cos):  # TR10i would look inside them too
        return None
    return c1 * sp.cos(a - b)


def _two_trig_factors(term: sp.Expr) -> tuple[sp.Expr | None, type | None, frozenset]:
    """term = C f(a) f(b) with f sin or cos, a ≠ b, C free of both: (C, f, {a, b});
    (None, None, ∅) otherwise."""
    trig = [f for f in sp.Mul.make_args(term) if isinstance(f, (sp.sin, sp.cos))]
    if len(trig) != 2 or trig[0].func is not trig[1].func or trig[0].args == trig[1].args:
        return None, None, frozenset()
    rest = sp.Mul(*[f for f in sp.Mul.make_args(term) if f not in trig])
    if rest.has(sp.sin, sp.cos):
        return None, None, frozenset()
    return rest, trig[0].func, frozenset((trig[0].args[0], trig[1].args[0]))


def _foldable(expr: sp.Expr) -> bool:
    """Could ``fu.TR10i`` fold anything in ``expr``? It rewrites a pair of terms of one
    sum, cos a cos b ± sin a sin b, sin a cos b ± cos a sin b, or a cos x + b sin x with
    b/a ∈ {1, √3, 1/√3}: in each, one term has a factor cos x and the other sin x for
    the same x, and the two terms differ by a number and by sines and cosines only
    (``fu.trig_split`` refuses a pair whose quotient holds anything else), that number
    ±1, ±√3 or ±1/√3 (``trig_split`` folds two products of two only when neither has a
    coefficient left after their common factor, and one sine against one cosine only
    for those ratios). Where no sum has such a pair, TR10i returns ``expr`` itself, and
    skipping it saves its search over all pairs (a chain's V, n cosines: n² pairs, for
    nothing; a q̈ numerator's terms in θ̇² and φ̇²; a force along a motion released at
    θ₀, 48 sin θ₀ beside 480 cos θ₀)."""
    for total in expr.atoms(sp.Add):
        cosines: dict[sp.Expr, set[int]] = {}
        sines: dict[sp.Expr, set[int]] = {}
        parts = []  # each term's factors other than sines and cosines: (the rest, the numbers)
        for i, term in enumerate(total.args):
            rest, number = [], []
            for factor in sp.Mul.make_args(term):
                base = factor.as_base_exp()[0]
                if isinstance(base, (sp.sin, sp.cos)):
                    (sines if isinstance(base, sp.sin) else cosines).setdefault(base.args[0], set()).add(i)
                else:
                    (number if factor.is_number else rest).append(factor)
            parts.append((rest, number))
        shared = cosines.keys() & sines.keys()
        if not shared:  # (a sum of cosines alone, a chain's V: no product to build)
            continue
        rests, numbers = [sp.Mul(*r) for r, _ in parts], [sp.Mul(*n) for _, n in parts]
        for x in shared:
            if any(i != j and rests[i] == rests[j] and _folding_ratio(numbers[i] / numbers[j])
                   for i in cosines[x] for j in sines[x]):
                return True
    return False


_FOLDING_RATIOS = tuple(s * r for s in (1, -1) for r in (sp.Integer(1), sp.sqrt(3), sp.sqrt(3) / 3))


def _folding_ratio(ratio: sp.Expr) -> bool:
    """±1, ±√3 or ±1/√3, or a float (2.0/2.0 is 1.0, which sympy does not call equal to 1
    but TR10i folds: kept as a yes)."""
    return ratio in _FOLDING_RATIOS or ratio.has(sp.Float)


def tidy_fraction(expr: sp.Expr) -> sp.Expr:
    """A rational function of the parameters as one cancelled fraction, never expanded
    over its denominator. sin α, cos α, … count as symbols, with sin²α + cos²α = 1
    applied (numerator and denominator reduced to degree < 2 in sin α); radicals such
    as √3 are algebraic numbers. So the result is zero exactly when the expression is.
    For answers built from solved linear systems, where ``tidy`` would swell."""
    return _leading_plus(sp.factor_terms(_cancelled(expr, False)[0]))


def tidy_fraction_parts(expr: sp.Expr) -> tuple[sp.Expr, sp.Expr]:
    """``sp.fraction(tidy_fraction(expr))``, numerator and denominator each the same once
    expanded, for a caller that expands them. Over the rationals the cancelled fraction
    is P/Q with P and Q coprime in ℤ[x, …] and Q's leading coefficient positive;
    ``factor_terms`` pulls each one's content (coprime integers) and common factors
    apart, and ``_leading_plus`` trades signs among the numerator's factors, so
    ``fraction`` finds P and Q again: that rewriting is skipped there. (Not where P/Q is
    a sum: over a number Q, sympy spreads 1/Q over P's terms, and ``fraction`` finds Q
    no more.)"""
    value, rational = _cancelled(expr, False)
    if rational and not value.is_Add:
        return sp.fraction(value)
    return sp.fraction(_leading_plus(sp.factor_terms(value)))


def cancelled(expr: sp.Expr) -> sp.Expr:
    """``tidy_fraction``'s one cancelled fraction, before its common factors are pulled
    out and in whichever of its equal forms comes cheapest (a constant may sit on
    either side): for a caller that expands and factors each part itself."""
    return _cancelled(expr, True)[0]


def _cancelled(expr: sp.Expr, any_form: bool) -> tuple[sp.Expr, bool]:
    """The cancelled fraction, and whether it was cancelled over the rationals."""
    if expr.is_Rational:
        return expr, True
    table, back = stand_ins(expr.atoms(sp.Function))
    plain = expr.xreplace(table)
    rational = _rational(plain)
    value = _one_cancelled(plain, rational, any_form)
    pairs = [(table[f], table[sp.cos(f.args[0])]) for f in table
             if isinstance(f, sp.sin) and sp.cos(f.args[0]) in table]
    if pairs:
        value = _reduced(value, pairs, rational, any_form)
    return value.xreplace(back), rational


def _one_cancelled(plain: sp.Expr, rational: bool, any_form: bool) -> sp.Expr:
    """``plain`` over one denominator and cancelled. A rational function over the
    rationals cancels to the one P/Q its value fixes (``_cancel_over``), so it is put
    over one denominator by ``as_numer_denom``, a quarter of ``together``'s time (which
    pulls each sum's common factors apart first); any other by ``together``, whose form
    the cancel may keep, as may a pair that comes back as it went in (no symbol left)."""
    if rational and _polynomial_quotient(plain):
        top, bottom = plain.as_numer_denom()
        c, p, q = sp.cancel((top, bottom))
        if not (p is top and q is bottom):
            return c * p / q
    return _cancel_over(sp.together(plain), rational, any_form)


def _rational(expr: sp.Expr) -> bool:
    """No algebraic number for ``cancel(..., extension=True)`` to adjoin: every leaf a
    rational or a symbol not known to be algebraic (an integer symbol counts as one),
    and no power of a number left unevaluated (√3). Then the extension changes nothing
    but costs an assumption query on every factor of every term (3x the time)."""
    for atom in expr.atoms():
        if atom.is_Symbol:
            if atom.is_algebraic:
                return False
        elif not atom.is_Rational:
            return False
    return not any(p.is_number for p in expr.atoms(sp.Pow))


def _cancel_over(expr: sp.Expr, rational: bool, any_form: bool) -> sp.Expr:
    """``cancel`` over the rationals, adjoining the expression's algebraic numbers
    (√3) unless ``rational`` says it has none. ``any_form``: the numerator and
    denominator cancelled as they stand, without ``cancel``'s own sign and common-factor
    rewriting of the whole fraction first (6x cheaper; the same fraction, with its
    constant perhaps on the other side).

    A quotient of polynomials in symbols with rational coefficients is cancelled as the
    pair (numerator, denominator). ``cancel`` of the whole expression first rewrites it
    with ``factor_terms`` (most of its time), then cancels its numerator and denominator
    the same way: both end at P/Q with P and Q coprime in ℤ[x, y, …] and Q's leading
    coefficient positive, which the fraction alone fixes (ℤ[x, y, …] factors uniquely,
    its units ±1), so the result is the same expression. Where none of the pair's
    symbols is left once expanded (the pair is a number), ``cancel`` returns the pair as
    it came but the whole expression expanded: that one, as before."""
    if rational and (any_form or _polynomial_quotient(expr)):
        top, bottom = sp.fraction(expr)
        c, p, q = sp.cancel((top, bottom))
        if any_form or not (p is top and q is bottom):  # (a pair with no symbol left comes back as it was)
            return c * p / q
    return sp.cancel(expr) if rational else sp.cancel(expr, extension=True)


def _polynomial_quotient(expr: sp.Expr) -> bool:
    """Sums, products and integer powers of symbols and rationals only: the pair's
    generators are its symbols whichever way it is written (a root of a symbol, √l
    beside l, or a function of one, would make generators of its own forms)."""
    return all(isinstance(e, (sp.Add, sp.Mul, sp.Symbol, sp.Rational)) or (e.is_Pow and e.exp.is_Integer)
               for e in sp.preorder_traversal(expr))


def _reduced(value: sp.Expr, pairs: list[tuple[sp.Dummy, sp.Dummy]], rational: bool,
             any_form: bool) -> sp.Expr:
    """Numerator and denominator modulo s² + c² − 1, in s; unchanged when they are not
    polynomials in s (a root of sin α, which a target such as 1/ω₀ gives), or when no
    s has a power above 1 (nothing to reduce: ``value`` is cancelled already)."""
    num, den = sp.fraction(value)
    squares = {s for s, _ in pairs}
    if not any(p.base in squares and p.exp.is_Integer and p.exp > 1
               for p in (num.atoms(sp.Pow) | den.atoms(sp.Pow))):
        return value
    try:
        for s, c in pairs:
            num, den = sp.rem(num, s**2 + c**2 - 1, s), sp.rem(den, s**2 + c**2 - 1, s)
    except sp.PolynomialError:
        return value
    return _cancel_over(num / den, rational, any_form)


def _cancel(expr: sp.Expr) -> sp.Expr:
    """One fraction with common factors cancelled, sin α, cos α, … taken as symbols: a
    rational function of them, as impact and statics answers are."""
    table, back = stand_ins(expr.atoms(sp.Function))
    plain = expr.xreplace(table)
    if _rational(plain):  # the one P/Q (``_cancel_over``), as sympy's cancel finds it
        return _one_cancelled(plain, True, False).xreplace(back)
    return sp.cancel(sp.together(plain)).xreplace(back)


def has_root(expr: sp.Basic, of: tuple = ()) -> bool:
    """Does a fractional power of symbols occur (√(l² − 2 l r cos θ)), of ``of`` where
    given (the coordinates): the mark of a form that swells when differentiated or
    solved in general."""
    return any(p.exp.is_Rational and not p.exp.is_Integer and (p.base.has(*of) if of else p.base.free_symbols)
               for p in expr.atoms(sp.Pow))


def tidied_roots(expr: sp.Expr) -> sp.Expr:
    """Each square root's radicand expanded and tidied (sin² + cos² = 1), so that one
    length written two ways is one: a spring's pull has |d| = √(x² cos²α + (x sin α −
    l₀)²) from the positions, V and the energy's q̇² the tidied √(x² − 2 l₀ x sin α +
    l₀²), and the force along the motion kept both, forty lines that never cancelled (a
    hoop on an incline held by a spring: 15 s)."""
    roots = [p for p in expr.atoms(sp.Pow) if p.exp.is_Rational and p.exp.q == 2 and p.base.free_symbols]
    return expr.xreplace({p: sp.Pow(tidy(sp.expand(p.base)), p.exp) for p in roots}) if roots else expr


def square_root(p: sp.Basic) -> bool:
    """Is p a power whose exponent is an odd number of halves (√X, 1/√X, X^(3/2))?"""
    return p.is_Pow and p.exp.is_Rational and p.exp.q == 2


def has_denominator(expr: sp.Expr) -> bool:
    """Does a sum appear in a denominator (a rational function worth cancelling)?"""
    return any(p.exp.is_negative and p.base.is_Add for p in expr.atoms(sp.Pow))


def _leading_plus(expr: sp.Expr) -> sp.Expr:
    """−1/4 a² σ (π − 16) → 1/4 a² σ (16 − π): a negative factor moved into a sum;
    6 v (−e − 1) → −6 v (e + 1): a sum of negative terms turned round."""
    if not expr.is_Mul:
        return expr
    factors = sp.Mul.make_args(expr)
    negative = [f for f in factors if f.is_Add and all(x.could_extract_minus_sign() for x in f.args)]
    if negative and len(factors) > 2:
        expr = sp.Mul(*[(-f if f in negative else f) for f in factors]) * (-1) ** len(negative)
        if not expr.is_Mul:
            return expr
    coeff, rest = expr.as_coeff_Mul()
    sums = [f for f in sp.Mul.make_args(rest) if f.is_Add]
    mixed = len(sums) == 1 and any(x.could_extract_minus_sign() for x in sums[0].args)
    if coeff.is_negative and mixed:
        return sp.Mul(-coeff, *[(-f if f is sums[0] else f) for f in sp.Mul.make_args(rest)])
    return expr


def _pythagoras(expr: sp.Expr) -> sp.Expr:
    """Use sin²x + cos²x = 1 for each angle x to shorten ``expr``, angle by angle. A
    turned body's sin²α sin²β + sin²α cos²β + cos²α shortens only once β is reduced
    first, then α: later rounds take only a rewrite that removes an angle altogether
    (so a form that merely trades terms, as a cone's cos²α tan²α, is left as it is)."""
    angles = _squared_angles(expr)
    for x in angles:
        expr = _pythagoras_in(expr, x)
    for _ in range(len(angles)):  # later rounds: only a rewrite that removes an angle
        before = expr
        for x in _squared_angles(expr):
            candidate = _pythagoras_in(expr, x)
            if x not in _squared_angles(candidate):
                expr = candidate
        if expr == before:
            break
    return expr


def _squared_angles(expr: sp.Expr) -> list:
    return sorted({p.base.args[0] for p in expr.atoms(sp.Pow)
                   if isinstance(p.base, (sp.sin, sp.cos)) and p.exp.is_even and p.exp > 0},
                  key=sp.default_sort_key)


def _pythagoras_in(expr: sp.Expr, x: sp.Expr) -> sp.Expr:
    """sin²x → 1 − cos²x or cos²x → 1 − sin²x, whichever is shorter (or neither).
    ``expr`` is expanded: where it has no even power of sin x (of cos x), that rewrite
    would give ``expr`` again, and is not made."""
    best, best_ops = expr, None
    powers = expr.atoms(sp.Pow)
    for square, other in ((sp.sin(x), sp.cos(x)), (sp.cos(x), sp.sin(x))):
        if not any(_even_power_of(p, square) for p in powers):
            continue
        candidate = sp.expand(expr.replace(lambda e: _even_power_of(e, square),
                                           lambda e: (1 - other**2) ** (e.exp // 2)))
        ops = sp.count_ops(candidate)
        if best_ops is None:
            best_ops = sp.count_ops(best)
        if ops < best_ops:
            best, best_ops = candidate, ops
    return best


def _even_power_of(e: sp.Expr, square: sp.Expr) -> bool:
    """Is ``e`` square², square⁴, …?"""
    return e.is_Pow and e.base == square and e.exp.is_even and e.exp > 0


def tidy_matrix(matrix: sp.Matrix) -> sp.Matrix:
    """Each entry tidied (a symmetric matrix's mirrored entries are the cache's)."""
    return matrix.applyfunc(tidy)


def by_monomials(expr: sp.Expr, generators: list[sp.Symbol]) -> sp.Expr:
    """Written as Σ (coefficient) × (monomial in ``generators``), each coefficient tidied:
    pₓ = (M + m) ẋ + m (R − r) cos θ θ̇, not its terms expanded."""
    return sp.Add(*[mono * coefficient for mono, coefficient in collect_in(tidy(expr), generators).items()])


def collect_in(expr: sp.Expr, generators: list[sp.Symbol], tidied: bool = False) -> dict[sp.Expr, sp.Expr]:
    """Split ``expr`` into monomials in the symbols ``generators`` (q̇, q̈), each with its
    coefficient tidied (skipped when ``expr`` was built from tidied coefficients already).
    Returns {monomial: coefficient}; monomial 1 holds the rest."""
    finish = terms_factored if tidied else tidy
    if not generators:
        return {sp.Integer(1): finish(expr)}
    grouped = _group_by_monomial(expanded(expr), set(generators))
    if grouped is None:  # a generator inside a function or a denominator: let Poly judge
        poly = sp.Poly(sp.expand(expr), *generators)
        grouped = {sp.Mul(*[g**p for g, p in zip(generators, powers)]): [coeff]
                   for powers, coeff in poly.terms()}
    out: dict[sp.Expr, sp.Expr] = {}
    for mono, coefficients in grouped.items():
        value = finish(sp.Add(*coefficients))
        if value != 0:
            out[mono] = value
    return out


def _group_by_monomial(expanded: sp.Expr, generators: set) -> dict[sp.Expr, list[sp.Expr]] | None:
    """The terms of an expanded sum grouped by their monomial in the generators, read off
    each term's factors (much cheaper than a Poly over every other symbol); None when a
    generator occurs other than as a positive integer power factor."""
    grouped: dict[sp.Expr, list[sp.Expr]] = {}
    for term in sp.Add.make_args(expanded):
        mono, rest = [], []
        for factor in sp.Mul.make_args(term):
            base, exp = factor.as_base_exp()
            (mono if base in generators and exp.is_Integer and exp > 0 else rest).append(factor)
        coefficient = sp.Mul(*rest)
        if coefficient.free_symbols & generators:
            return None
        grouped.setdefault(sp.Mul(*mono), []).append(coefficient)
    return grouped
