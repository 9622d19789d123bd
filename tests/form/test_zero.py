"""simplifies_to_zero agrees with ``sp.simplify(x) == 0``; surely_nonzero says True only
for expressions that are not zero everywhere, and never for an identity."""

from __future__ import annotations

import pytest
import sympy as sp

from rbdsolve.form.zero import simplifies_to_zero, surely_nonzero

from conftest import counted_calls

x, y = sp.symbols("x y", positive=True)
a = sp.Symbol("a", real=True)
n = sp.Symbol("n", negative=True)
t = sp.Symbol("t")
q = sp.Function("q")(t)

IDENTITIES = [
    sp.Integer(0),
    sp.sin(q) ** 2 + sp.cos(q) ** 2 - 1,
    sp.sqrt(x**2) - x,                     # x > 0
    sp.sqrt(n**2) + n,                     # n < 0: |n| = −n
    sp.sqrt(x * y) - sp.sqrt(x) * sp.sqrt(y),
    sp.cos(2 * a) - 1 + 2 * sp.sin(a) ** 2,
    sp.Derivative(q, t) * (x + 1) - sp.Derivative(q, t) * x - sp.Derivative(q, t),
]

NOT_ZERO = [
    sp.sqrt(x) - x,
    sp.sin(q) + sp.Derivative(q, t),
    sp.Float(1e-30) * x,                   # tiny, not zero
    x - sp.Rational(13, 7) + sp.Rational(1, 10**40),
    sp.sqrt(n) - sp.sqrt(-n),              # i·√|n| − √|n|
]


@pytest.mark.parametrize("expr", IDENTITIES)
def test_an_identity_is_zero_and_never_surely_nonzero(expr):
    assert not surely_nonzero(expr)
    assert simplifies_to_zero(expr)


@pytest.mark.parametrize("expr", NOT_ZERO)
def test_an_expression_nonzero_somewhere_is_not_zero(expr):
    assert not simplifies_to_zero(expr)
    assert sp.simplify(expr) != 0


def test_a_value_at_one_point_decides_where_it_is_nonzero_there():
    assert surely_nonzero(sp.sqrt(x) - x)
    assert surely_nonzero(sp.sin(q) + sp.Derivative(q, t))


def test_a_pole_or_a_zero_at_the_point_leaves_it_to_simplify():
    """1/(x − 13/7) has its pole at the first sample value, x − 13/7 its root: neither
    value says anything, and simplify decides."""
    assert not surely_nonzero(1 / (x - sp.Rational(13, 7)))
    assert not surely_nonzero(x - sp.Rational(13, 7))
    assert not simplifies_to_zero(x - sp.Rational(13, 7))


def test_a_sign_the_values_cannot_meet_is_left_to_simplify():
    """An integer symbol gets no value (the sample values are fractions)."""
    k = sp.Symbol("k", integer=True)
    assert not surely_nonzero(sp.sin(sp.pi * k / 3))
    assert not simplifies_to_zero(sp.sin(sp.pi * k / 3))


def test_a_symbol_gets_a_value_with_every_property_it_is_declared_with():
    """A negative symbol a negative value; an irrational one none (the values are
    fractions): √2-like symbols are left to simplify."""
    from rbdsolve.form.zero import _allowed

    v = sp.Rational(13, 7)
    assert _allowed(sp.Symbol("n", negative=True), v) == -v
    assert _allowed(sp.Symbol("p", positive=True), v) == v
    assert _allowed(sp.Symbol("i", irrational=True), v) is None
    assert _allowed(sp.Dummy("z", zero=True), v) is None


def test_an_identity_tidy_reduces_is_proved_without_simplify(monkeypatch):
    """sympy's first simplify in a process imports its physical units (~0.1 s): where
    tidy (exact) already gives 0, that 0 is the proof and simplify is not called."""
    calls = counted_calls(monkeypatch, sp, "simplify")
    assert simplifies_to_zero(sp.sin(q) ** 2 + sp.cos(q) ** 2 - 1)
    assert simplifies_to_zero(sp.cos(a) * sp.cos(x) + sp.sin(a) * sp.sin(x) - sp.cos(a - x))
    assert calls == []


def test_a_rational_function_that_is_zero_is_proved_by_its_numerator_alone(monkeypatch):
    """A sum of fractions over different denominators, with √3 in the coefficients, that
    cancels to 0 by hand: (x + √3)/(x y) − 1/y − √3/(x y) = 0 and 1/(x − √3) −
    1/(x + √3) = 2√3/(x² − 3), is reduced to one fraction whose numerator expands to 0, with neither
    tidy nor simplify (sympy's powsimp took a minute on such a sum of 300 terms)."""
    from rbdsolve.form import zero

    r3 = sp.sqrt(3)
    identity = ((x + r3) / (x * y) - 1 / y - r3 / (x * y)
                + 1 / (x - r3) - 1 / (x + r3) - 2 * r3 / (x**2 - 3))
    tidied, simplified = counted_calls(monkeypatch, zero, "tidy"), counted_calls(monkeypatch, sp, "simplify")
    assert zero.rational_zero(identity) and simplifies_to_zero(identity)
    assert tidied == [] and simplified == []
    assert not zero.rational_zero(identity + 1 / (x + y))
    assert not zero.rational_zero(sp.sin(q) ** 2 + sp.cos(q) ** 2 - 1)  # a function: left to tidy
