"""form/expansion.py: ``expanded`` is ``sympy.expand`` (the oracle), skipping the walk
only where ``expand`` has nothing to do."""

from __future__ import annotations

import itertools

import sympy as sp

from rbdsolve.form.expansion import expanded, plainly_expanded
from rbdsolve.model.state import t, user_function

a, b = sp.symbols("a b", positive=True)
x, y = sp.symbols("x y")
theta = user_function("theta")(t)
PIECES = [sp.Integer(1), sp.Rational(-3, 4), a, b**2, sp.sqrt(3), sp.sqrt(a), sp.pi, sp.sin(x), sp.cos(x - y) ** 2,
          sp.cos(a * (x + y)), theta, sp.exp(x + y), a * (x + y), (x + 1) ** 2, 1 / (x + y), sp.Float(0.5),
          sp.log(a * b), (a * x) ** sp.Rational(1, 2), sp.Derivative(theta, t), sp.sin(x * (y + 1))]


def test_expanded_is_expand_on_sums_of_products_of_every_kind() -> None:
    plain = 0
    for p, q, r in itertools.combinations(PIECES, 3):
        for e in (p * q + r, p * q * r, p + q - r, (p - r) * q):
            assert expanded(e) == sp.expand(e), e
            if plainly_expanded(e):
                plain += 1
                assert sp.expand(e) == e, e  # the skipped walk would have found nothing
    assert plain > 200  # the shortcut was taken, not always refused


def test_what_expand_would_change_is_not_plain() -> None:
    for e in (a * (x + y), (x + 1) ** 2, sp.exp(x + y), sp.cos(a * (x + y)), sp.log(a * b), 1 / (x + 1) ** 2):
        assert not plainly_expanded(e) and sp.expand(e) != e, e
    assert plainly_expanded(sp.Rational(7, 8) * a * b**2 * sp.cos(x - y) * theta + sp.sqrt(3) * sp.pi)


def test_a_product_of_radicals_is_left_to_expand() -> None:
    # Mul's flattening is not idempotent on radicals of one base: 2**(1/3)·√6·2·18**(1/3)
    # evaluates to 2·6**(1/3)·6**(5/6), which expand (rebuilding n/d) turns into 12·6**(1/6).
    cube_2, root_6, two_cube_18 = sp.cbrt(2), sp.sqrt(6), 2 * sp.cbrt(18)
    for e in (sp.Mul(cube_2, root_6, two_cube_18), sp.Mul(cube_2, root_6, two_cube_18, x) + a,
              sp.Mul(root_6, two_cube_18, sp.sqrt(2) / 2, sp.sin(x))):
        assert sp.srepr(sp.expand(e)) != sp.srepr(e), e  # the case is real in this sympy
        assert expanded(e) == sp.expand(e), e
