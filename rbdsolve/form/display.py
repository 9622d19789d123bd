"""Display values: how an exact result is laid out, without changing what it is.

``Scaled(m*r**2, Terms(...))`` prints as ``m r² [7/8 θ̇² + …]``, the way an exam
solution pulls the common scale out of an energy or a matrix; ``value()`` gives back
the plain sympy object for checks and JSON.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp


@dataclass(frozen=True)
class Terms:
    """A sum shown in the given order (sympy would reorder it)."""

    items: tuple[Math, ...]

    def value(self) -> sp.Expr:
        return sp.Add(*[plain(item) for item in self.items])

    def shown(self) -> tuple[Math, ...]:
        """The items a reader sees: a zero term (0 ω₁ ω₂) is not written."""
        kept = tuple(x for x in self.items if not _zero(x))
        return kept or (sp.Integer(0),)


@dataclass(frozen=True)
class Product:
    """coefficient × factors, shown in that order: 1/4 cos(φ − θ) θ̇ φ̇."""

    coefficient: sp.Expr
    factors: tuple[sp.Expr, ...]

    def value(self) -> sp.Expr:
        return sp.Mul(self.coefficient, *self.factors)

    def divides(self) -> bool:
        """A coefficient 1/m (a number over symbols) reads as dividing the whole: λ_A/m,
        not 1/m λ_A; every printer then prints the plain product."""
        top, bottom = sp.fraction(self.coefficient)
        return bool(self.factors) and top.is_Number and bool(bottom.free_symbols)


@dataclass(frozen=True)
class Scaled:
    """factor × [inner]: a common scale pulled out of an expression or a matrix."""

    factor: sp.Expr
    inner: Math

    def value(self):
        return self.factor * plain(self.inner)

    def negates(self) -> bool:
        """−1 × a sum: printed −(P_y/m + v₁), not −1 [P_y/m + v₁]."""
        return self.factor == -1 and isinstance(self.inner, Terms)


@dataclass(frozen=True)
class Label:
    """A name that is not a symbol, spelled for each medium: m (|d|² 1 − d dᵀ)."""

    text: str
    latex: str

    def value(self) -> str:
        return self.text


@dataclass(frozen=True)
class Along:
    """A vector's component along a basis vector: (ẋ − 1/2 l φ̇) eₓ."""

    component: Math
    basis: sp.Symbol

    def value(self) -> sp.Expr:
        return plain(self.component) * self.basis

    def is_sum(self) -> bool:
        """Is the component a sum or a fraction, to be bracketed before the basis vector?"""
        c = self.component
        if isinstance(c, Terms):
            return len(c.items) > 1
        if isinstance(c, sp.Basic):
            return c.is_Add or any(f.is_Pow and f.exp.is_negative and not f.base.is_Number
                                   for f in sp.Mul.make_args(c))
        return False


Math = sp.Basic | sp.MatrixBase | Terms | Product | Scaled | Label | Along | str


def _zero(item: Math) -> bool:
    if isinstance(item, Product):
        return item.coefficient == 0
    return isinstance(item, sp.Expr) and item == 0


def plain(value: Math):
    """The sympy object a display value stands for (a label: its text)."""
    return value.value() if isinstance(value, (Terms, Product, Scaled, Label, Along)) else value


@dataclass(frozen=True)
class Relation:
    """[lead] lhs op rhs [= more …], e.g. T = T₁ + T₂ = m r² […], or, following the
    previous relation, ⇒ 25/48 μ² − 37/24 μ + 1 = 0 (lead '⇒'); ``more_op`` chains
    another relation instead of =: Ω_c1 < Ω < Ω_c2."""

    lhs: Math
    rhs: Math
    op: str = "="
    more: tuple[Math, ...] = ()
    lead: str = ""
    more_op: str = "="
