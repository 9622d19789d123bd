"""Decisions on an expression — is it zero, what is its sign, is it free of some
symbols — as ``sp.simplify`` would make them, without the simplify where a cheaper exact
look already says. (sympy's first simplify in a process also imports its physical units,
~0.1 s: docs/performance.md.)

Zero: simplify's verdict, without the simplify where one numeric value already says no,
or where a rational function's numerator already expands to 0.

simplify returns 0 only for an expression that is zero at every value its symbols may
take (their sympy assumptions: positive, real, integer). So if the expression is not
zero at one such point, simplify cannot return 0: the answer is False, found in
microseconds rather than the tenths of a second a simplify over a long difference of
critical values takes (issue 37). The value at the point is evaluated by sympy's evalf
with ``strict=True``, which raises rather than return digits it cannot vouch for; only a
value known to be nonzero to full precision decides. Anywhere else (zero at the point,
a pole, precision exhausted, something that is not a number) the answer is simplify's
own, so the two agree wherever simplify is right.
"""

from __future__ import annotations

import sympy as sp
from sympy.core.function import AppliedUndef
from sympy.core.evalf import PrecisionExhausted

from rbdsolve.form.tidy import tidy

# Generic values, one per symbol (in sorted order): unlikely to be a root or a pole of a
# physical formula by chance, and a chance hit only costs the simplify it would have run.
_VALUES = tuple(sp.Rational(p, q) for p, q in ((13, 7), (17, 11), (23, 13), (29, 17), (31, 19), (37, 23),
                                                  (41, 29), (43, 31), (47, 37), (53, 41), (59, 43), (61, 47)))


def simplifies_to_zero(expr: sp.Expr) -> bool:
    """``sp.simplify(expr) == 0``, with a nonzero value at one admissible point as a
    shortcut to False."""
    expr = sp.sympify(expr)
    if expr == 0:
        return True
    if surely_nonzero(expr):
        return False
    return rational_zero(expr) or tidy(expr) == 0 or sp.simplify(expr) == 0  # each 0 is a proof


def rational_zero(expr: sp.Expr) -> bool:
    """Whether expr, free of functions (a rational function of its symbols with numbers
    and radicals of numbers for coefficients), is zero by the numerator of its one
    fraction, expanded: n/d with n's expansion 0 is 0 wherever d ≠ 0. Sound, not complete
    (radicals that cancel only when denested stay). A steady spin's residual at the
    steady state, 300 terms over 118 denominators, is 0 so in half a second, where
    simplify's powsimp ran past a minute (a new user's cone top)."""
    if expr.atoms(sp.Function, sp.Derivative):
        return False
    numerator, _ = sp.fraction(sp.together(expr))
    return sp.expand(numerator) == 0


def tidied_sign(expr: sp.Expr, values: dict | None = None) -> sp.Expr:
    """sign(expr) with ``values`` put in, read off tidy's form (exact: sin² + cos² = 1,
    common factors), or, where that form does not say, off simplify's (slower, stronger):
    a number where either decides, else sympy's unevaluated sign."""
    sign = sp.sign(tidy(expr).xreplace(values or {}))
    return sign if sign.is_number else sp.sign(sp.simplify(expr).xreplace(values or {}))


def settled(expr: sp.Expr, symbols) -> sp.Expr:
    """expr (already tidied) as it is where it holds none of ``symbols``, else simplified:
    what tidy left, simplify may still cancel (a rolling ratio, a lever that must hold no
    coordinate), before a caller refuses it as not constant."""
    return sp.simplify(expr) if expr.has(*symbols) else expr


def surely_nonzero(expr: sp.Expr) -> bool:
    """Whether expr is nonzero at one point its symbols' assumptions allow (so not zero
    everywhere); False where that point does not tell."""
    expr = sp.sympify(expr)
    point = _point(expr)
    if point is None:
        return False
    try:
        value = expr.xreplace(point)
        if not value.is_number:
            return False
        z = value.evalf(15, strict=True)
    except (PrecisionExhausted, ArithmeticError, TypeError, ValueError, NotImplementedError):
        return False
    finite = all(isinstance(a, (sp.Float, sp.Integer, sp.Rational)) or a is sp.I for a in z.atoms())
    return finite and z != 0


def _point(expr: sp.Basic) -> dict | None:
    """A value for each symbol, unknown function of time and derivative in expr, allowed
    by its assumptions; None where one has assumptions the values cannot meet."""
    stand_ins = sorted(expr.atoms(sp.Derivative), key=sp.default_sort_key)
    stand_ins += sorted(expr.atoms(AppliedUndef), key=sp.default_sort_key)
    symbols = sorted(expr.free_symbols - {s for x in stand_ins for s in x.free_symbols}, key=sp.default_sort_key)
    held = [*stand_ins, *symbols]
    if len(held) > len(_VALUES):
        return None
    point = {}
    for x, v in zip(held, _VALUES):
        if isinstance(x, sp.Symbol):
            v = _allowed(x, v)
            if v is None:
                return None
        point[x] = v
    return point


def _allowed(symbol: sp.Symbol, v: sp.Rational) -> sp.Rational | None:
    """v or −v, whichever has every property the symbol is declared with (positive,
    real, nonzero …); None where neither has (an integer, an irrational symbol)."""
    for value in (v, -v):
        if all(getattr(value, f"is_{fact}") == known for fact, known in symbol.assumptions0.items()):
            return value
    return None
