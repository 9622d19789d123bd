"""The order in which a sum's terms are printed, shared by every printer.

sympy orders terms by the text of their names, so th₁₀ comes before th₂ and a 16-link
chain's V reads cos th₁ + cos th₁₀ + … + cos th₂; an exam counts (th₁, th₂, …, th₁₆),
and writes cos(th₂ − th₁₀), not cos(th₁₀ − th₂). Names of at most one digit are left in
sympy's order, which is already the counting one there.
"""

from __future__ import annotations

import re

import sympy as sp
from sympy.core.function import AppliedUndef

_NUMBER = re.compile(r"\d+")
_NAME_NUMBER = re.compile(r"(?<=[A-Za-z_])\d+")  # a number in a name (th10), not 0.25, l**2 or sqrt(3)


def exam_order(terms: list) -> list:
    """``natural_order``, then ``positive_first``; a complex number a + b i as every
    textbook writes it, its real part first (3.58 − 3.58 i, not −3.58 i + 3.58)."""
    if _complex_number(terms):
        return sorted(terms, key=lambda t: t.has(sp.I))
    return positive_first(natural_order(terms))


def _complex_number(terms: list) -> bool:
    """Two terms, a real number and a real number times i."""
    return (len(terms) == 2 and all(t.is_number for t in terms)
            and sorted(t.has(sp.I) for t in terms) == [False, True])


def positive_first(terms: list) -> list:
    """A sum's terms in the order an exam writes a difference: a positive number first
    beside symbols (1 + e, 1 − e², 1 + 3 cos²α), else a positive term first where the
    first is negative (g − R Ω² for −R Ω² + g, 9π − 16 for −16 + 9π)."""
    number = next((t for t in terms if t.is_Rational and t.is_positive), None)
    if number is not None and len(terms) > 1 and any(t.free_symbols for t in terms):
        return [number, *(t for t in terms if t is not number)]
    if terms and terms[0].could_extract_minus_sign():
        first = next((t for t in terms if not t.could_extract_minus_sign()), None)
        if first is not None:
            return [first, *(t for t in terms if t is not first)]
    return terms


def natural_order(terms: list) -> list:
    """Terms alike but for the numbers in their names (31 cos th₁, 13 cos th₁₀, 29 cos th₂)
    put in the order of those numbers, in the places they had among the others: th₁,
    th₂, …, th₁₀. Only where a name has a number of two digits or more."""
    if len(terms) < 2 or not _counted_past_nine(terms):
        return terms
    return _by_name_numbers(terms)


def _by_name_numbers(terms: list) -> list:
    """``natural_order`` without its check that a name is numbered past nine."""
    keys = [_family(t) for t in terms]
    places: dict[str, list[int]] = {}
    for i, (family, _) in enumerate(keys):
        places.setdefault(family, []).append(i)
    out = list(terms)
    for where in places.values():
        for place, i in zip(where, sorted(where, key=lambda i: keys[i][1])):
            out[place] = terms[i]
    return out


def readable_cosine(expr: sp.Expr) -> sp.Expr:
    """cos(th₁₀ − th₂) as cos(th₂ − th₁₀), unevaluated (cos is even; sympy keeps the
    argument whose first term, in its order of names, is positive)."""
    if not isinstance(expr, sp.cos) or not expr.args[0].is_Add or not _counted_past_nine(expr.args[0].args):
        return expr
    argument = expr.args[0]
    ordered = argument.as_ordered_terms()
    natural = _by_name_numbers(ordered)
    if natural != ordered and natural[0].could_extract_minus_sign():
        return sp.cos(-argument, evaluate=False)
    return expr


def _counted_past_nine(terms: list) -> bool:
    """Does a name in ``terms`` (a symbol's, or a coordinate's function's) carry a number
    of two digits or more? Below that, sympy's order of names is the counting one."""
    names = set()
    for t in terms:
        names |= {s.name for s in t.free_symbols} | {f.func.__name__ for f in t.atoms(AppliedUndef)}
    return any(len(n) > 1 for name in names for n in _NUMBER.findall(name))


def _family(term: sp.Expr) -> tuple[str, tuple[int, ...]]:
    """The term without its number, with the numbers in its names taken out: the family
    ("cos(th#)") and those numbers ((10,)); other digits (√3, l², 0.25) stay in the
    family, so terms that differ in them are not reordered."""
    text = str(term.as_coeff_Mul()[1])
    return _NAME_NUMBER.sub("#", text), tuple(int(n) for n in _NAME_NUMBER.findall(text))
