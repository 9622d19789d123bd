"""How a result is arranged for reading: a common scale pulled out of a sum or a
matrix, the terms of an energy or an equation in the order an exam solution writes
them, a vector along its basis, a configuration on one line.

    m r² [7/8 θ̇² + 1/4 cos(φ − θ) θ̇ φ̇ + 1/6 φ̇²]        arranged(T, …)
    M = m r² [[7/4, 1/4], [1/4, 1/3]]                   scaled_matrix(M, …)

The seed exam's worked solutions (shared/seeds, SG2150 2015-10-29) are the model: a
coefficient's parameters in front, the generalized velocities after, highest
derivative first. Nothing here changes what an expression is; ``plain`` of each result
is the expression it was made from.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable

import sympy as sp

from rbdsolve.form.display import Along, Math, Product, Relation, Scaled, Terms
from rbdsolve.form.expansion import expanded
from rbdsolve.form.factor import factored
from rbdsolve.form.printers import to_unicode
from rbdsolve.form.tidy import collect_in, common_factors, terms_factored, tidy


def _as_written(e: sp.Expr) -> sp.Expr:
    return e


@dataclass(frozen=True)
class Reading:
    """What an exam arranges a model's expressions by: the ``generators`` its terms are
    monomials in (q̈, q̇), the ``coordinates`` that order them, the parameters whose
    common scale is pulled out, and ``show``, how each coefficient and factor is written
    (a coordinate as a function of time). A model gives its own (``Model.reading``)."""

    generators: tuple[sp.Expr, ...]
    coordinates: tuple[sp.Expr, ...]
    scale_symbols: frozenset[sp.Symbol]
    show: Callable[[sp.Expr], sp.Expr] = field(default=_as_written, compare=False)


def arranged(expr: sp.Expr, reading: Reading) -> Math:
    """An energy or an equation's left side, its coefficients tidied already, as an exam
    writes it: split into monomials in the reading's generators (q̈, q̇), ordered
    (``ordered_sum``), the parameters' common scale pulled out (``scaled_sum``); each
    coefficient and factor passed through ``show`` (a coordinate as a function of time):
    m r² [7/8 θ̇² + 1/4 cos(φ − θ) θ̇ φ̇ + 1/6 φ̇²]."""
    generators, coordinates, scale_symbols, show = (reading.generators, reading.coordinates,
                                                    set(reading.scale_symbols), reading.show)
    parts = collect_in(expr, list(generators), tidied=True)
    terms = [(show(c), tuple(show(f) for f in factors))
             for c, factors in ordered_sum(parts, list(generators), list(coordinates))]
    default = scaled_sum(terms, scale_symbols)
    if set(parts) == {sp.Integer(1)}:  # no generators (a potential): maybe one product
        whole = factored(show(expr))   # −g (2 m + mₐ) y, not −g [2 m y + mₐ y]
        shorter = len(to_unicode(whole)) - len(to_unicode(default))
        if not whole.is_Add and (shorter < 0 or shorter == 0 and _groups_parameters(whole, scale_symbols)):
            return whole
    return default


def _groups_parameters(product: sp.Expr, parameters: set[sp.Symbol]) -> bool:
    """Does a product have a sum of parameters alone among its factors, (2 m + mₐ)?"""
    return any(f.is_Add and f.free_symbols <= parameters and not f.atoms(sp.Function)
               for f in sp.Mul.make_args(product))


def arranged_equation(expr: sp.Expr, reading: Reading) -> Math:
    """An equation's left side in two groups, each with its own scale pulled out: the
    inertia terms (with q̈ or q̇), m r² […], and the rest, m g r […]; the rest factored
    as a whole, m l (g + ÿ_A) sin φ, where pulling its common factors out leaves a
    coordinate among them (shorter than m l [g sin φ + sin φ ÿ_A]): m r² [7/4 θ̈ + …] + 2 g m r sin(θ)."""
    generators, coordinates, show = reading.generators, reading.coordinates, reading.show
    parts = collect_in(expr, list(generators), tidied=True)
    moving = sp.Add(*[c * m for m, c in parts.items() if m != 1])
    still = parts.get(sp.Integer(1), sp.Integer(0))
    groups = [arranged(moving, reading)] if moving != 0 else []
    if still != 0:
        common = common_factors(expanded(still))
        pulled = [f for f in sp.Mul.make_args(common) if not f.is_Add]
        if len(pulled) < len(sp.Mul.make_args(common)) and any(f.has(*coordinates) for f in pulled):
            groups.append(show(common))
        else:
            groups.append(arranged(still, reading))
    return groups[0] if len(groups) == 1 else Terms(tuple(groups))


def common_scale(exprs: list[sp.Expr], symbols: set[sp.Symbol]) -> sp.Expr:
    """The largest product of parameter powers that divides every expression.

    7 m r²/8 and m r² cos(φ − θ)/4 share m r²; used to show an energy as
    m r² [7/8 θ̇² + …] and a matrix as m r² [[7/4, 1/4], [1/4, 1/3]]. A common sign
    is included when every expression is negative.
    """
    # each distinct entry once; a product of plain factors (a chain's M(q) entry) read as it stands
    nonzero = [terms_factored(e) for e in dict.fromkeys(exprs) if e != 0]
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
    items = tuple(Product(factored(expanded(c / scale), bracketed=bool(factors)), factors) for c, factors in terms)
    inner = Terms(items) if len(items) > 1 else items[0]
    return inner if scale == 1 else Scaled(scale, inner)


def scaled_matrix(matrix: sp.Matrix, symbols: set[sp.Symbol]) -> Scaled | sp.Matrix:
    if matrix.shape == (1, 1):
        return sp.ImmutableMatrix(matrix.applyfunc(factored))
    scale = common_scale(list(matrix), symbols)
    scale = abs(scale) if scale.could_extract_minus_sign() else scale
    if scale == 1:
        return sp.ImmutableMatrix(matrix)
    # tidy and factored are cached: a symmetric M or K works once per distinct entry
    return Scaled(scale, sp.ImmutableMatrix(matrix.applyfunc(lambda x: factored(tidy(x / scale)))))


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
        rest = sp.Add.make_args(expanded(parts[mono]))
        rank = {q: i for i, q in enumerate(coordinates)}

        def first_coordinate(term: sp.Expr) -> tuple:
            present = [rank[q] for q in coordinates if term.has(q)]
            return (min(present) if present else len(coordinates), sp.default_sort_key(term))

        out += [(term, ()) for term in sorted(rest, key=first_coordinate)]
    return out


def descending(poly: sp.Poly, variable: sp.Symbol | None = None) -> Terms:
    """A polynomial highest power first, each coefficient in its factored form, as an
    exam writes a characteristic equation: 25/48 μ² − 37/24 μ + 1, −3/2 m (R − r)² λ +
    g m (R − r); in ``variable`` (κ) where the polynomial's own is a stand-in."""
    x = variable if variable is not None else poly.gens[0]
    return Terms(tuple(Product(factored(_over_one_denominator(c), bracketed=k > 0), (x**k,) if k else ())
                       for (k,), c in poly.terms()))


def _over_one_denominator(coefficient: sp.Expr) -> sp.Expr:
    """A coefficient whose terms share a denominator (the polynomial's expansion divides
    each term of K by 2 (4a² + d²)^(3/2) written out) as one fraction, where that is
    shorter; as it is otherwise."""
    if not coefficient.is_Add:
        return coefficient
    joined = sp.together(coefficient)
    return joined if sp.count_ops(joined) < sp.count_ops(coefficient) else coefficient


SCENE_BASIS = (sp.Symbol("e_x"), sp.Symbol("e_y"), sp.Symbol("e_z"))  # the scene's axes, eₓ, e_y, e_z


def along_axes(vector, shown: Callable[[sp.Expr], Math]) -> Math:
    """A scene vector along eₓ, e_y, e_z, each nonzero component as ``shown`` writes it."""
    return in_basis([(shown(x), e) for x, e in zip(vector, SCENE_BASIS) if sp.expand(x) != 0])


def in_basis(components: list[tuple[Math, sp.Symbol]]) -> Math:
    """(ẋ − 1/2 l φ̇) eₓ + ω₀ cos θ e₃: the nonzero components along their basis vectors,
    each starting with a positive term where it has one (v₀ − P_y/m, not −P_y/m + v₀)."""
    items = tuple(Along(_positive_lead(x), e) for x, e in components)
    if not items:
        return sp.Integer(0)
    return items[0] if len(items) == 1 else Terms(items)


def _positive_lead(component: Math) -> Math:
    if not isinstance(component, Terms) or not _negative(component.items[0]):
        return component
    first = next((x for x in component.items if not _negative(x)), None)
    if first is None:
        return component
    return Terms((first, *(x for x in component.items if x is not first)))


def _negative(item: Math) -> bool:
    value = item.coefficient if isinstance(item, Product) else item
    return isinstance(value, sp.Expr) and value.could_extract_minus_sign()


def configuration(coordinates: tuple[sp.Expr, ...], values: list[sp.Expr]) -> Relation:
    """(θ, φ) = (0, π): a configuration on one line (θ = 0 for one coordinate)."""
    return Relation(sp.ImmutableMatrix([list(coordinates)]), sp.ImmutableMatrix([list(values)]))


def subscript(i: int) -> str:
    """1 -> '₁': for names in prose (T₁, λ₂)."""
    return str(i).translate(str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉"))
