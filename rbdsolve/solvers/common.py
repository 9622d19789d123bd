"""Helpers every solver family shares: options, common scales, numeric values."""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field
from enum import Enum
from fractions import Fraction
from typing import Mapping

import sympy as sp
from sympy.core.function import AppliedUndef

from rbdsolve.errors import UnsolvedError
from rbdsolve.model.tidy import tidy
from rbdsolve.report.tree import map_leaves
from rbdsolve.report.math import Along, Math, Product, Scaled, Terms
from rbdsolve.report.steps import Relation


class RouteChoice(Enum):
    """Which route a question takes: ``exact`` (sympy, rational arithmetic), ``numeric``
    (floating point: numpy and scipy, every parameter needs a value) or ``auto`` (exact,
    and numeric where the exact route cannot answer and the values allow it)."""

    EXACT = "exact"
    NUMERIC = "numeric"
    AUTO = "auto"


@dataclass(frozen=True)
class Options:
    """How to solve: parameter values from the command line (they override the file's),
    the route, and the time budget in seconds for the model and for each question
    (None: none)."""

    values: Mapping[str, Fraction] = field(default_factory=dict)
    route: RouteChoice = RouteChoice.AUTO
    budget: float | None = None


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


def scaled_sum(terms: list[tuple[sp.Expr, tuple[sp.Expr, ...]]], symbols: set[sp.Symbol]) -> Math:
    """Σ coefficient × monomial, in the given order, with the coefficients' common
    parameter scale pulled out: m r² [7/8 θ̇² + 1/4 cos(φ − θ) θ̇ φ̇ + 1/6 φ̇²]."""
    terms = [(c, m) for c, m in terms if c != 0]
    if not terms:
        return sp.Integer(0)
    scale = common_scale([c for c, _ in terms], symbols) if len(terms) > 1 else sp.Integer(1)
    items = tuple(Product(sp.expand(c / scale), factors) for c, factors in terms)
    inner = Terms(items) if len(items) > 1 else items[0]
    return inner if scale == 1 else Scaled(scale, inner)


def scaled_matrix(matrix: sp.Matrix, symbols: set[sp.Symbol]) -> Scaled | sp.Matrix:
    if matrix.shape == (1, 1):
        return sp.ImmutableMatrix(matrix)
    scale = common_scale(list(matrix), symbols)
    scale = abs(scale) if scale.could_extract_minus_sign() else scale
    if scale == 1:
        return sp.ImmutableMatrix(matrix)
    return Scaled(scale, sp.ImmutableMatrix(matrix.applyfunc(lambda x: tidy(x / scale))))


def monomial_order(monomials: list[sp.Expr], generators: list[sp.Expr]) -> list[sp.Expr]:
    """Monomials in the order an exam solution writes them: by the first generator they
    contain (q̈₁, q̈₂, …, q̇₁², q̇₁q̇₂, …), highest power first; the constant last."""

    def key(mono: sp.Expr) -> tuple:
        powers = mono.as_powers_dict()
        return tuple(-powers.get(g, 0) for g in generators)

    return sorted(monomials, key=key)


def ordered_sum(parts: dict[sp.Expr, sp.Expr], generators: list[sp.Expr],
                coordinates: list[sp.Expr]) -> list[tuple[sp.Expr, tuple[sp.Expr, ...]]]:
    """{monomial: coefficient} -> (coefficient, monomial factors) in exam order: factors
    in generator order (θ̇ φ̇), and the part free of generators split into its terms,
    ordered by the first coordinate in each."""
    out = []
    for mono in monomial_order(list(parts), generators):
        if mono != 1:
            powers = mono.as_powers_dict()
            out.append((parts[mono], tuple(g**powers[g] for g in generators if g in powers)))
            continue
        rest = sp.Add.make_args(sp.expand(parts[mono]))
        rank = {q: i for i, q in enumerate(coordinates)}

        def first_coordinate(term: sp.Expr) -> tuple:
            present = [rank[q] for q in coordinates if term.has(q)]
            return (min(present) if present else len(coordinates), sp.default_sort_key(term))

        out += [(term, ()) for term in sorted(rest, key=first_coordinate)]
    return out


def in_basis(components: list[tuple[Math, sp.Symbol]]) -> Math:
    """(ẋ − 1/2 l φ̇) eₓ + ω₀ cos θ e₃: the nonzero components along their basis vectors."""
    items = tuple(Along(x, e) for x, e in components)
    if not items:
        return sp.Integer(0)
    return items[0] if len(items) == 1 else Terms(items)


def configuration(coordinates: tuple[sp.Expr, ...], values: list[sp.Expr]) -> Relation:
    """(θ, φ) = (0, π): a configuration on one line (θ = 0 for one coordinate)."""
    return Relation(sp.ImmutableMatrix([list(coordinates)]), sp.ImmutableMatrix([list(values)]))


def subscript(i: int) -> str:
    """1 -> '₁': for names in prose (T₁, λ₂)."""
    return str(i).translate(str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉"))


def sample(value: sp.Expr, values: Mapping[sp.Symbol, sp.Expr]) -> complex:
    """The value at the given parameter values, every other symbol set to 1: used to
    order symbolic results (eigenvalues, moments, equilibria) as they are at a sample."""
    return complex(sp.N(value.xreplace({s: values.get(s, 1) for s in value.free_symbols})))


# --- numeric values --------------------------------------------------------------------


def numeric(value: object, subs: Mapping[sp.Symbol, sp.Expr]) -> object:
    """Numeric values of an answers tree where every symbol has a value.

    Expressions become floats (or [re, im] when complex), matrices nested lists;
    anything that still holds a free symbol or a function of time becomes None. Leaves
    that are not expressions stay as the answers give them (an enum as its value, a
    count, a text), so the tree reads like the answers.
    """
    roots: dict[sp.Expr, sp.Expr] = {}
    return map_leaves(value, lambda leaf: _number(leaf, subs, roots) if isinstance(leaf, sp.Basic) else _plain(leaf))


def _plain(leaf: object) -> object:
    """A leaf that is not an expression: an enum as its value, else itself (a float, an
    int, a text, None)."""
    return leaf.value if isinstance(leaf, Enum) else leaf


def _number(value: object, subs: Mapping[sp.Symbol, sp.Expr],
            roots: dict[sp.Expr, sp.Expr] | None = None) -> float | list | None:
    if isinstance(value, float):
        return value  # a numeric route's answer
    if not isinstance(value, sp.Basic):
        return None  # enums, text: not numbers
    number = value.xreplace(subs)
    if roots is not None and number.has(sp.CRootOf):
        number = number.xreplace(_root_values(number, roots))
    if number.free_symbols or number.atoms(AppliedUndef) or number.has(sp.Derivative):
        return None
    try:
        z = complex(sp.N(number, 17))
    except (TypeError, ValueError):
        return None
    if not (math.isfinite(z.real) and math.isfinite(z.imag)):
        return None
    return z.real if abs(z.imag) <= 1e-14 * max(1.0, abs(z.real)) else [z.real, z.imag]


def _root_values(number: sp.Expr, roots: dict[sp.Expr, sp.Expr]) -> dict[sp.Expr, sp.Expr]:
    """Each polynomial root to 50 digits, isolated once per answers tree (a mode shape
    holds the same root in every entry; isolating it again per entry dominated the
    time). 50 digits leave the 17 asked for intact unless an entry cancels 33 digits."""
    for root in number.atoms(sp.CRootOf):
        if root not in roots:
            roots[root] = root.evalf(50)
    return roots


def missing_values(model, free: tuple[str, ...] = ()) -> tuple[str, ...]:
    """The parameters without a numeric value, in the file's order, except those in
    ``free`` (a route's own unknowns: steady_motion solves for omega0): floating-point
    work (every numeric route, and auto's fallback to it) needs none missing."""
    return tuple(p.name for p in model.problem.parameters
                 if p.name not in free and model.symbols.parameters[p.name] not in model.values)


def require_values(model, what: str, free: tuple[str, ...] = ()) -> None:
    """Refuse floating-point work while ``missing_values`` is not empty, naming them."""
    missing = missing_values(model, free)
    if missing:
        raise UnsolvedError(f"{what} needs a value for every parameter{_except(free)}; give "
                            f"{', '.join(missing)} ('values:' in the file, or --set NAME=VALUE)")


def _except(free: tuple[str, ...]) -> str:
    return f" except {', '.join(free)} (solved for)" if free else ""


def with_floats(value: object, subs: Mapping[sp.Symbol, sp.Expr]) -> object:
    """The same answers (dataclasses, mappings, tuples kept) with every sympy leaf put
    to a float at the parameter values (None where that is not a real number)."""
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        return dataclasses.replace(value, **{f.name: with_floats(getattr(value, f.name), subs)
                                            for f in dataclasses.fields(value)})
    if isinstance(value, Mapping):
        return {k: with_floats(v, subs) for k, v in value.items()}
    if isinstance(value, tuple):
        return tuple(with_floats(v, subs) for v in value)
    if isinstance(value, sp.Basic):
        number = _number(value, subs)
        return number if isinstance(number, float) else None
    return value
