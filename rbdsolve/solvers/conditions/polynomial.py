"""Every root of a polynomial system, or a refusal: never a list with roots left out.

sympy's ``solve`` finds a polynomial system's roots from a lexicographic Gröbner basis,
one variable at a time, and silently drops the roots of a factor it cannot solve in
radicals (an irreducible sextic in cos θ₂ for a double pendulum on a turntable: four
equilibria listed of twelve). ``solve_poly_system(..., strict=True)`` raises instead
(sympy's ``UnsolvableFactorError``), which is turned into ``UnsolvedError`` here, so
a route that calls its list complete only does so when it is. A system whose
solutions form a family (not zero-dimensional) is left to sympy's ``solve``, which
returns the family with some symbols free.
"""

from __future__ import annotations

import functools
import random

import sympy as sp
from sympy.polys.polyerrors import PolynomialError, UnsolvableFactorError
from sympy.solvers.polysys import SolveFailed, solve_poly_system

from rbdsolve.errors import NUMERIC_REMEDY, UnsolvedError
from rbdsolve.form.tidy import has_root


def polynomial_roots(system: list[sp.Expr], symbols: list[sp.Symbol], what: str) -> list[dict]:
    """Every root {symbol: value} of the polynomial ``system``; UnsolvedError naming
    ``what`` where some root has no closed form, or none an exam writes
    (``_unreadable_degree``)."""
    symbols, degree = _order_or_degree(system, symbols)
    if degree:
        raise UnsolvedError(unreadable_reason(what, degree) + ": an exact list would leave solutions out",
                            NUMERIC_REMEDY)
    try:
        found = solve_poly_system(system, *symbols, strict=True)
    except UnsolvableFactorError:
        raise UnsolvedError(f"{what} reduce to a polynomial with a factor whose roots have no closed form "
                            "(in radicals): an exact list would leave solutions out", NUMERIC_REMEDY) from None
    except (NotImplementedError, PolynomialError, SolveFailed):
        return sp.solve(system, symbols, dict=True, check=False)  # a family, or not polynomial after all
    return [dict(zip(symbols, root)) for root in found or []]


def unreadable_degree(system: list[sp.Expr], symbols: list[sp.Symbol]) -> int | None:
    """The degree of the eliminant's irreducible factor whose roots no exam writes (3 or
    more), in the order of ``symbols`` and in every other with another symbol last
    (``_readable_order``); None where some order's eliminant is readable. Decided before
    any solving: polynomial_roots refuses exactly these, and the equilibria's structure
    reads it to list the evident roots instead (an inverted rod held at its top by a
    spring of natural length: θ = 0 for every k, beside an irreducible quintic)."""
    return _order_or_degree(system, symbols)[1]


def _order_or_degree(system: list[sp.Expr], symbols: list[sp.Symbol]) -> tuple[list[sp.Symbol], int | None]:
    """The order of ``symbols`` to solve in (as given, or another whose eliminant is
    readable: ``_readable_order``), and None; or, where no order's eliminant is readable,
    the symbols as given and the degree of their eliminant's unreadable factor."""
    degree = _eliminant_degree(system, symbols)
    if not degree:
        return symbols, None
    other = _readable_order(system, symbols)
    return (other, None) if other is not None else (symbols, degree)


def unreadable_reason(what: str, degree: int) -> str:
    """Why ``what`` (the equilibrium equations) has no exact list: its eliminant's
    irreducible factor of ``degree`` (``unreadable_degree``)."""
    if degree >= 5:
        return (f"{what} reduce to a polynomial with an irreducible factor of degree {degree}, whose roots have no "
                "closed form (in radicals) in general")
    return (f"{what} reduce to a polynomial with an irreducible factor of degree {degree}, whose roots in radicals "
            "(Cardano's, Ferrari's formulas) are no answer an exam writes")


def _eliminant_degree(system: list[sp.Expr], symbols: list[sp.Symbol]) -> int | None:
    """The degree of the eliminant's largest irreducible factor in the last of ``symbols``
    where no exam writes its roots (3 or more), found at a point of the parameters first."""
    return _specialized_degree(system, symbols) or _unreadable_degree(system, symbols)


def _readable_order(system: list[sp.Expr], symbols: list[sp.Symbol]) -> list[sp.Symbol] | None:
    """The symbols with another one last, the first whose eliminant is readable, where the
    last one's is not: ∂V/∂φ ∝ 2 sin²φ + 2 sin φ − 1 eliminates to cos⁴φ = 3/4 in cos φ
    (irreducible, degree 4) but to a quadratic in sin φ, sin φ = (√3 − 1)/2; None where
    none is."""
    for last in symbols[:-1]:
        order = [x for x in symbols if x != last] + [last]
        if not _eliminant_degree(system, order):
            return order
    return None


def _unreadable_degree(system: list[sp.Expr], symbols: list[sp.Symbol]) -> int | None:
    """The degree of the eliminant's largest irreducible factor where it is 3 or 4, else
    None. The last polynomial of a lexicographic Gröbner basis of a zero-dimensional
    system is the eliminant, univariate in the last symbol (Cox, Little, O'Shea, §3.1);
    an irreducible cubic or quartic factor of it has roots in radicals that sympy's
    solve writes out (casus irreducibilis: cube roots of complex numbers for three real
    roots) and then spends minutes testing and tidying (a rod on a turning arm: a
    quartic in cos θ, past 150 s). A factor of degree 5 or more is refused by solve's
    own strict mode."""
    factors = _eliminant_factors(system, symbols)
    worst = max((sp.degree(f, symbols[-1]) for f in factors), default=0) if factors else 0
    return worst if worst in (3, 4) else None


def _eliminant_factors(system: list[sp.Expr], symbols: list[sp.Symbol]) -> list[sp.Expr] | None:
    """The irreducible factors (``_factors``) of the last polynomial of the system's
    lexicographic Gröbner basis, where that is univariate in the last symbol; None where
    the system is not zero-dimensional, or there is nothing to eliminate (solve decides).
    Once per system and order: the equilibria's structure asks first, then the solving."""
    found = _eliminant_factors_of(tuple(system), tuple(symbols))
    return None if found is None else list(found)


@functools.lru_cache(maxsize=64)
def _eliminant_factors_of(system: tuple[sp.Expr, ...], symbols: tuple[sp.Symbol, ...]) -> tuple[sp.Expr, ...] | None:
    if not symbols:
        return None
    try:
        basis = sp.groebner(system, *symbols, order="lex")
    except (PolynomialError, NotImplementedError):
        return None
    last = symbols[-1]
    eliminant = basis.exprs[-1] if basis.exprs else sp.Integer(0)
    if eliminant.free_symbols & set(symbols) != {last}:
        return None
    return tuple(_factors(eliminant, last))


def _specialized_degree(system: list[sp.Expr], symbols: list[sp.Symbol]) -> int | None:
    """The degree of the eliminant's largest irreducible factor at random rational values
    of the parameters, where it is 3 or more (and the factor not a binomial x^n − a,
    whose roots a^(1/n) are readable), else None. A factor over the parameters' field
    stays a factor at a point, so the degree there is at most the true one, and equal
    to it at all but special points (Hilbert's irreducibility theorem): 3 or more there
    is 3 or more for the symbols, decided in milliseconds. The lexicographic basis with
    the parameters as symbols can take minutes (a rod on a spring to the side of its
    lowest point, six parameters: an irreducible sextic, known at a point in 10 ms)."""
    parameters = sorted(set().union(*(e.free_symbols for e in system)) - set(symbols), key=sp.default_sort_key)
    if not symbols or not parameters:
        return None
    rng = random.Random(37)
    point = {p: sp.Rational(rng.randint(101, 997), rng.randint(101, 997)) for p in parameters}
    factors = _eliminant_factors([e.xreplace(point) for e in system], symbols)
    if not factors:
        return None
    last = symbols[-1]
    worst = sp.Poly(max(factors, key=lambda f: sp.degree(f, last)), last)
    binomial = len(worst.terms()) == 2 and worst.TC() != 0
    return worst.degree() if worst.degree() >= 3 and not (worst.degree() >= 5 and binomial) else None


def _factors(eliminant: sp.Expr, last: sp.Symbol) -> list[sp.Expr]:
    """The eliminant's irreducible factors, over the rationals extended by the roots of
    numbers in it: a square plate hung by a corner, its centre a/√2 from it, has
    (c² − 1)(Ω² a c − √2 g), which factor_list over the rationals leaves whole, a "cubic"."""
    over_q = [f for f, _ in sp.factor_list(eliminant, last)[1]]
    surds = sorted({p for p in eliminant.atoms(sp.Pow) if p.is_number and not p.exp.is_integer},
                   key=sp.default_sort_key)
    if not surds or max(sp.degree(f, last) for f in over_q) < 3:
        return over_q
    # each root of a number as a symbol first (factors over ℚ[σ] are factors at σ = √2: milliseconds),
    # over the field ℚ(√2) only where a cubic or quartic is left (seconds, with many parameters)
    symbols = {p: sp.Dummy() for p in surds}
    by_symbols = [f.xreplace({v: k for k, v in symbols.items()})
                  for f, _ in sp.factor_list(eliminant.xreplace(symbols), last)[1]]
    if max(sp.degree(f, last) for f in by_symbols) < 3:
        return by_symbols
    try:
        top = sp.fraction(sp.together(eliminant))[0]  # over the extension, every symbol a generator
        return [f for f, _ in sp.factor_list(top, extension=surds)[1]]
    except (PolynomialError, NotImplementedError, ValueError):
        return over_q  # the roots of numbers do not make a field sympy factors over: as over the rationals


def trig_mixed(expr: sp.Expr, q: sp.Symbol) -> bool:
    """Does q occur both inside a trigonometric function and outside every one (θ sin θ,
    k θ − sin θ)? Then no substitution s = sin q, c = cos q makes expr a polynomial.
    Each sine or cosine of q stands in for a symbol of its own, so a product such as
    θ cos θ keeps its θ; sines of constants are left alone."""
    trig = [f for f in expr.atoms(sp.sin, sp.cos, sp.tan) if f.has(q)]
    return bool(trig) and expr.xreplace({f: sp.Dummy() for f in trig}).has(q)


def trig_transcendental(expr: sp.Expr, x: sp.Symbol) -> bool:
    """Has expr = 0 no closed-form roots in x that sympy's solve could find: x inside
    sines or cosines of arguments that are not rational multiples of one another
    (sin(r θ/(R + r)) beside cos θ, a half-disk rolling on a drum), or both inside one
    and outside every one (``trig_mixed``)? solve then searched for minutes (issue 37)
    and found nothing. Sines of one argument u(x) and its multiples stay: a polynomial
    in sin u, cos u, then u = c."""
    arguments = [f.args[0] for f in expr.atoms(sp.sin, sp.cos, sp.tan, sp.cot, sp.sec, sp.csc) if f.has(x)]
    incommensurate = any(not sp.cancel(a / arguments[0]).is_Rational for a in arguments[1:])
    return incommensurate or trig_mixed(expr, x)


def in_sine_and_cosine(expr: sp.Expr, x: sp.Symbol, s: sp.Symbol, c: sp.Symbol) -> sp.Expr | None:
    """expr as a polynomial in s = sin x and c = cos x, expanded; None where x stands
    elsewhere (outside them, or in a multiple angle: sin 2x is the caller's to expand)."""
    if any(f.has(x) and (f.func not in (sp.sin, sp.cos) or f.args[0] != x)
           for f in expr.atoms(sp.sin, sp.cos, sp.tan, sp.cot, sp.sec, sp.csc)):
        return None
    plain = sp.expand(expr.xreplace({sp.sin(x): s, sp.cos(x): c}))
    return None if plain.has(x) or not plain.is_polynomial(s, c) else plain


def sine_cosine_quartic(expr: sp.Expr, x: sp.Symbol) -> bool:
    """Is expr a polynomial in sin x and cos x (x nowhere else, sin 2x and cos 2x
    expanded) that none of the closed forms takes: not in one of them alone (the other
    in even powers), not linear in both (t = tan(x/2): a quadratic), not a quadratic form
    plus a constant (t = tan x: a quadratic)? With t = tan(x/2) it is a quartic, whose
    roots by Ferrari's formula no reader uses, and sympy's solve spent minutes on one (a
    ladder pushed at its foot: −18 P sin φ cos φ + 12 P sin φ cos φ₀ + 9 g m cos² φ + …)."""
    s, c = sp.Dummy("s"), sp.Dummy("c")
    plain = in_sine_and_cosine(sp.expand_trig(expr), x, s, c)
    if plain is None or not plain.has(s) or not plain.has(c):
        return False
    form = sp.Poly(plain, s, c)
    if all(k % 2 == 0 for k, _ in form.monoms()) or all(k % 2 == 0 for _, k in form.monoms()):
        return False  # one of them in even powers only: a polynomial in the other
    degrees = {k + j for k, j in form.monoms()}
    return form.total_degree() > 2 or (form.total_degree() == 2 and bool(degrees & {1}))


RADICAL_OPS = 40  # a longer expression with x under a radical is not given to sympy's solve


def under_long_radical(expr: sp.Expr, x: sp.Symbol) -> bool:
    """Does x stand under a radical (a fractional power) in an expression longer than
    RADICAL_OPS operations? sympy's solve squares the radical away and checks each root
    with simplify: minutes (issue 37). Two springs of natural length on an inverted rod
    give √(4a² + d²) beside a² k (solving for a); a disk rolling on an incline held by a
    spring of natural length to a point off its line gives N(x) with
    √(x² − 2 a x cos α − 2 b x sin α + …) in it (solving N = 0 for x)."""
    return has_root(expr, (x,)) and sp.count_ops(expr) > RADICAL_OPS


def _has_radical(expr: sp.Expr) -> bool:
    """Does expr hold a radical of a sum (a fractional power whose base is a sum)?"""
    return any(w.exp.is_Rational and not w.exp.is_Integer and w.base.is_Add for w in expr.atoms(sp.Pow))


LONG_LINEAR_OPS = 200  # a longer linear polynomial over sympy's EX domain: its root is not simplified


def radical_linear_root(polynomial: sp.Poly) -> sp.Expr | None:
    """−b/a for a x + b = 0 over sympy's EX domain with a radical of a sum in it, past
    RADICAL_OPS operations, else ``plain_linear_root``'s answer: a condition's critical
    value. A cylinder on an incline held by a spring of natural length to a point off
    its line has N ≥ 0 solved for k linear in k, the spring's length in both
    coefficients (173 operations), where sympy's roots ran simplify on −b/a from 20 s to
    minutes as the hash seed ordered its terms (a new user's trial). (Not for the
    modes' λ, whose form sympy's simplify keeps shorter: g √X/(2R (π (M + m) − √X)).)"""
    plain = plain_linear_root(polynomial)
    if plain is not None or polynomial.degree() != 1 or not polynomial.get_domain().is_EX:
        return plain
    expr = polynomial.as_expr()
    if sp.count_ops(expr) <= RADICAL_OPS or not _has_radical(expr):
        return None
    a, b = polynomial.all_coeffs()
    return -b / a


def plain_linear_root(polynomial: sp.Poly) -> sp.Expr | None:
    """−b/a for a x + b = 0 with long coefficients over sympy's EX domain (radicals,
    atan2 of the parameters), else None (sympy's roots then, whose form the answers keep).
    sympy's roots runs ``simplify`` on such a root, which did not end within a minute
    for a hoop rolling in a track on an elastic cord with m and k open, once for its λ
    and once for a condition's root in r (a new user's trial); −b/a is no less exact."""
    if polynomial.degree() != 1 or not polynomial.get_domain().is_EX:
        return None
    if sp.count_ops(polynomial.as_expr()) <= LONG_LINEAR_OPS:
        return None
    a, b = polynomial.all_coeffs()
    return -b / a
