"""tidy's size guard, ``_larger_than(e, limit)``, is ``sp.count_ops(e) > limit`` (the
oracle), though it counts the operations only where the tree has more than limit/3
nodes: count_ops counts at most 3 operations a node. Checked on the forms that count
most per node (negative rationals, denominators, negative and fractional powers,
sums of negative terms) and on seeded random expressions."""

from __future__ import annotations

import random

import sympy as sp

from rbdsolve.form.tidy import _larger_than

x, y, z, m, r, g = sp.symbols("x y z m r g")
f = sp.Function("f")
DENSE = [sp.Rational(-3, 4), -x, -x - y, -sp.Rational(3, 4) * x / y, x**sp.Rational(-1, 2),
         -x**sp.Rational(-3, 4), 1 / (x * y * z), -2 / (3 * x**2), sp.exp(-x), sp.E, -sp.sin(x) / sp.cos(y)**2,
         sp.Derivative(f(x), x), f(x)**-2, x - y - z - sp.Rational(1, 3), sp.sqrt(3) * m * r**2 / 4]


def _nodes(e: sp.Expr) -> int:
    return sum(1 for _ in sp.preorder_traversal(e))


def _random_expr(rng: random.Random, depth: int) -> sp.Expr:
    if depth == 0 or rng.random() < 0.25:
        return rng.choice([x, y, z, m, r, g, sp.Rational(rng.randint(-9, 9), rng.randint(1, 5)), sp.pi, sp.sqrt(2)])
    kind = rng.randrange(6)
    a, b = _random_expr(rng, depth - 1), _random_expr(rng, depth - 1)
    if kind == 0:
        return a + b
    if kind == 1:
        return a - b
    if kind == 2:
        return a * b
    if kind == 3:
        return a / b if b != 0 else a
    if kind == 4:
        return a ** rng.choice([2, 3, -1, -2, sp.Rational(1, 2), sp.Rational(-3, 2)]) if a != 0 else a
    return rng.choice([sp.sin, sp.cos, sp.exp])(a)


def _cases() -> list[sp.Expr]:
    rng = random.Random(37)
    found = [e for e in DENSE]
    found += [sp.expand(e) for e in DENSE] + [-e for e in DENSE]
    found += [_random_expr(rng, rng.randint(1, 6)) for _ in range(400)]
    return [e for e in found if isinstance(e, sp.Expr)]


def test_count_ops_is_at_most_three_a_node() -> None:
    for e in _cases():
        assert sp.count_ops(e) <= 3 * _nodes(e), e


def test_the_guard_is_count_ops_past_the_limit() -> None:
    decided = {True: 0, False: 0}
    for e in _cases():
        ops = sp.count_ops(e)
        for limit in (0, 1, 2, 5, 10, 20, 40, ops - 1, ops, ops + 1):
            if limit < 0:
                continue
            assert _larger_than(e, limit) == (ops > limit), (e, limit)
            decided[ops > limit] += 1
    assert decided[True] > 500 and decided[False] > 500  # both sides met
