"""tidy's direct fold C cos a cos b + C sin a sin b = C cos(a − b) gives exactly what
sympy's fu.TR10i gives for it (the oracle), and steps aside for every other form."""

from __future__ import annotations

import itertools

import sympy as sp
from sympy.simplify.fu import TR10i

from rbdsolve.form.tidy import _cosine_of_difference, _foldable, tidy

x, y, a, b = sp.symbols("x y a b")
ANGLES = [x, y, x + y, 2 * x, x - y, x + sp.pi / 3, sp.pi / 2 - y]
COEFFICIENTS = [sp.Integer(1), sp.Integer(-1), a, -a, 2 * a * b, sp.Rational(-3, 4) * a**2, sp.sqrt(2) * a,
                a / (b + 1)]


def test_the_direct_fold_is_tr10is_fold_term_for_term() -> None:
    folded = 0
    for (p, q), C in itertools.product(itertools.permutations(ANGLES, 2), COEFFICIENTS):
        e = sp.expand(C * sp.cos(p) * sp.cos(q) + C * sp.sin(p) * sp.sin(q))
        mine = _cosine_of_difference(e)
        if mine is not None:
            folded += 1
            assert sp.srepr(mine) == sp.srepr(TR10i(e)), e
    assert folded > 200  # the pattern was met, not skipped


def test_other_forms_are_left_to_tr10i() -> None:
    assert _cosine_of_difference(sp.cos(x) * sp.cos(y) - sp.sin(x) * sp.sin(y)) is None  # cos(x + y)
    assert _cosine_of_difference(a * sp.cos(x) * sp.cos(y) + b * sp.sin(x) * sp.sin(y)) is None
    assert _cosine_of_difference(sp.sin(x) * sp.cos(y) + sp.cos(x) * sp.sin(y)) is None  # sin(x + y)
    assert _cosine_of_difference(sp.cos(x) * sp.cos(sp.sin(y)) + sp.sin(x) * sp.sin(sp.sin(y))) is None
    assert tidy(sp.cos(x) * sp.cos(y) - sp.sin(x) * sp.sin(y)) == sp.cos(x + y)


def test_a_chain_entry_reads_as_one_cosine() -> None:
    m, l = sp.symbols("m l", positive=True)
    entry = sp.Rational(21, 2) * l**2 * m * (sp.cos(x) * sp.cos(y) + sp.sin(x) * sp.sin(y))
    assert tidy(entry) == sp.Rational(21, 2) * l**2 * m * sp.cos(x - y)


def test_a_sum_said_unfoldable_is_one_tr10i_leaves_as_it_is() -> None:
    """_foldable may say yes wrongly (TR10i then runs and finds nothing) but never no
    wrongly: every sum it turns away, TR10i (the oracle) returns unchanged."""
    trig = [sp.cos(x), sp.sin(x), sp.cos(y), sp.sin(y), sp.cos(x - y), sp.sin(x - y), sp.Integer(1)]
    factors = [sp.Integer(1), a, b, a**2, sp.sqrt(3), sp.sqrt(a), 2 * a * b]
    terms = [f * s * u for f in factors for s in trig for u in trig[::2]]
    sums = [sp.expand(terms[i] + terms[j] + terms[(i * k + j) % len(terms)])
            for i, j in itertools.combinations(range(0, len(terms), 5), 2) for k in (1, 2)]
    refused, accepted = _judged(sums)
    assert refused > 500 and accepted > 50  # both answers were met


def test_a_sum_whose_numbers_cannot_fold_is_one_tr10i_leaves_as_it_is() -> None:
    """The same oracle over numeric coefficients: a cos x + b sin x folds only where b/a
    is ±1, ±√3 or ±1/√3, a product of two against a product of two only where b/a = ±1;
    _foldable turns away the others (48 sin θ₀ beside 480 cos θ₀) and never one TR10i
    folds."""
    t = sp.Rational(1, 10)
    trig = [sp.cos(x), sp.sin(x), sp.cos(x) * sp.cos(y), sp.sin(x) * sp.sin(y), sp.sin(x) * sp.cos(y),
            sp.cos(t), sp.sin(t), sp.cos(x) * sp.sin(t), sp.sin(x) * sp.cos(t)]
    numbers = [sp.Integer(1), sp.Integer(-1), sp.Integer(2), sp.Integer(10), sp.sqrt(3), -2 * sp.sqrt(3),
               sp.sqrt(3) / 3, sp.sqrt(6), sp.sqrt(2), sp.Float(2.0), sp.pi]
    sums = [n1 * a * s1 + n2 * a * s2
            for (n1, s1), (n2, s2) in itertools.combinations(itertools.product(numbers, trig), 2)]
    refused, accepted = _judged([e for e in sums if e.is_Add])
    assert refused > 1000 and accepted > 100  # both answers were met


def _judged(sums: list[sp.Expr]) -> tuple[int, int]:
    """How many sums _foldable turns away and how many it lets through, each turned away
    checked against the oracle: TR10i leaves it as it is."""
    refused = [e for e in sums if not _foldable(e)]
    for e in refused:
        assert TR10i(e) == e, e
    return len(refused), len(sums) - len(refused)
