"""Helpers every solver family shares: options, common scales, numeric values."""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Mapping

import sympy as sp
from sympy.core.function import AppliedUndef

from rbdsolve.report.math import Scaled, Terms


@dataclass(frozen=True)
class Options:
    """How to solve: parameter values from the command line (they override the file's)."""

    values: Mapping[str, Fraction] = field(default_factory=dict)


# --- common scales ---------------------------------------------------------------------


def common_scale(exprs: list[sp.Expr], symbols: set[sp.Symbol]) -> sp.Expr:
    """The largest product of parameter powers that divides every expression.

    7 m r²/8 and m r² cos(φ − θ)/4 share m r²; used to show an energy as
    m r² [7/8 θ̇² + …] and a matrix as m r² [[7/4, 1/4], [1/4, 1/3]]. A common sign
    is included when every expression is negative.
    """
    nonzero = [sp.factor_terms(e) for e in exprs if e != 0]
    if not nonzero:
        return sp.Integer(1)
    powers: dict[sp.Symbol, sp.Expr] | None = None
    for e in nonzero:
        mine: dict[sp.Symbol, sp.Expr] = {}
        for factor in sp.Mul.make_args(e):
            base, exp = factor.as_base_exp()
            if base in symbols and exp.is_Rational:
                mine[base] = mine.get(base, 0) + exp
        if powers is None:
            powers = mine
        else:
            powers = {s: min(powers[s], mine[s]) for s in powers.keys() & mine.keys()}
    scale = sp.Mul(*[s**p for s, p in sorted(powers.items(), key=lambda kv: str(kv[0]))])
    if all(sp.Mul.make_args(e)[0].is_negative for e in nonzero) and len(nonzero) > 0:
        scale = -scale
    return scale


def scaled_sum(terms: list[sp.Expr], symbols: set[sp.Symbol]) -> Scaled | Terms | sp.Expr:
    """terms, in their order, with their common parameter scale pulled out."""
    terms = [x for x in terms if x != 0]
    if len(terms) <= 1:
        return terms[0] if terms else sp.Integer(0)
    scale = common_scale(terms, symbols)
    inner = Terms(tuple(sp.expand(x / scale) for x in terms))
    return inner if scale == 1 else Scaled(scale, inner)


def scaled_matrix(matrix: sp.Matrix, symbols: set[sp.Symbol]) -> Scaled | sp.Matrix:
    scale = common_scale(list(matrix), symbols)
    scale = abs(scale) if scale.could_extract_minus_sign() else scale
    if scale == 1:
        return sp.ImmutableMatrix(matrix)
    return Scaled(scale, sp.ImmutableMatrix(matrix.applyfunc(lambda x: sp.expand(x / scale))))


def monomial_order(monomials: list[sp.Expr], generators: list[sp.Expr]) -> list[sp.Expr]:
    """Monomials in the order an exam solution writes them: by the first generator they
    contain (q̈₁, q̈₂, …, q̇₁², q̇₁q̇₂, …), highest power first; the constant last."""

    def key(mono: sp.Expr) -> tuple:
        powers = mono.as_powers_dict()
        return tuple(-powers.get(g, 0) for g in generators)

    return sorted(monomials, key=key)


def ordered_sum(parts: dict[sp.Expr, sp.Expr], generators: list[sp.Expr]) -> list[sp.Expr]:
    """{monomial: coefficient} -> the terms coefficient*monomial, in exam order."""
    return [parts[m] * m for m in monomial_order(list(parts), generators)]


# --- numeric values --------------------------------------------------------------------


def numeric(value: object, subs: Mapping[sp.Symbol, sp.Expr]) -> object:
    """Numeric values of an answers tree where every symbol has a value.

    Expressions become floats (or [re, im] when complex), matrices nested lists;
    anything that still holds a free symbol or a function of time becomes None.
    """
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        return {f.name: numeric(getattr(value, f.name), subs) for f in dataclasses.fields(value)}
    if isinstance(value, Mapping):
        return {str(k): numeric(v, subs) for k, v in value.items()}
    if isinstance(value, sp.MatrixBase):
        return [[numeric(x, subs) for x in row] for row in value.tolist()]
    if isinstance(value, (list, tuple)):
        return [numeric(v, subs) for v in value]
    if isinstance(value, sp.Basic):
        number = value.xreplace(subs)
        if number.free_symbols or number.atoms(AppliedUndef) or number.has(sp.Derivative):
            return None
        try:
            z = complex(sp.N(number, 17))
        except (TypeError, ValueError):
            return None
        if not (math.isfinite(z.real) and math.isfinite(z.imag)):
            return None
        return z.real if abs(z.imag) <= 1e-14 * max(1.0, abs(z.real)) else [z.real, z.imag]
    return None  # enums, text: not numbers


def has_numbers(tree: object) -> bool:
    if isinstance(tree, float):
        return True
    if isinstance(tree, dict):
        return any(has_numbers(v) for v in tree.values())
    if isinstance(tree, list):
        return any(has_numbers(v) for v in tree)
    return False
