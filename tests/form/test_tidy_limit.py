"""tidy's size limit decided without counting where the tree is small: the bound
count_ops(e) ≤ 9 × nodes(e) that ``_past_limit`` rests on holds on every shape that
count_ops treats apart (negative coefficients, fractions, negative powers, sums of
negative terms, functions, derivatives), and ``_past_limit`` answers what
``count_ops(e) > MAX_OPS`` answers (sympy's count_ops the oracle)."""

from __future__ import annotations

import random

import sympy as sp

from rbdsolve.form.tidy import MAX_OPS, OPS_PER_NODE, _past_limit

x, y, z = sp.symbols("x y z")
th = sp.Function("theta")(sp.Symbol("t"))
LEAVES = [x, y, z, th, sp.Integer(2), sp.Integer(-3), sp.Rational(-5, 7), sp.Rational(1, 3), sp.pi, sp.sqrt(2),
          sp.Float(0.25)]


def _random_expr(rng: random.Random, depth: int) -> sp.Expr:
    if depth == 0 or rng.random() < 0.2:
        return rng.choice(LEAVES)
    pick = rng.randrange(8)
    a, b = _random_expr(rng, depth - 1), _random_expr(rng, depth - 1)
    if pick == 0:
        return a + b
    if pick == 1:
        return a - b
    if pick == 2:
        return a * b
    if pick == 3:
        return a / (b + 1)
    if pick == 4:
        return -a * b / 3
    if pick == 5:
        return sp.cos(a) * sp.sin(b)
    if pick == 6:
        return a ** rng.choice([-2, -1, 2, sp.Rational(1, 2), sp.Rational(-3, 2)])
    return sp.exp(-a) + sp.Derivative(th, sp.Symbol("t")) * b


def _nodes(e: sp.Basic) -> int:
    return 1 + sum(_nodes(a) for a in e.args)


# the forms that count most per node (from the start-up branch's own guard's test)
f = sp.Function("f")
DENSE = [sp.Rational(-3, 4), -x, -x - y, -sp.Rational(3, 4) * x / y, x**sp.Rational(-1, 2),
         -x**sp.Rational(-3, 4), 1 / (x * y * z), -2 / (3 * x**2), sp.exp(-x), sp.E, -sp.sin(x) / sp.cos(y)**2,
         sp.Derivative(f(x), x), f(x)**-2, x - y - z - sp.Rational(1, 3), sp.sqrt(3) * x * y**2 / 4]


def test_count_ops_is_at_most_nine_per_node() -> None:
    assert all(sp.count_ops(e) <= OPS_PER_NODE * _nodes(e) for e in DENSE)
    rng = random.Random(37)
    worst = 0.0
    for _ in range(400):  # each count_ops of a depth-5 tree is slow; the dense forms above are the sharp cases
        e = _random_expr(rng, 5)
        ops = sp.count_ops(e)
        assert ops <= OPS_PER_NODE * _nodes(e), e
        worst = max(worst, ops / _nodes(e))
    assert worst > 0.5  # the shapes that count were met


def test_past_limit_is_count_ops_past_max_ops() -> None:
    rng = random.Random(5)
    sizes = set()
    # each sum's terms drawn from one pool of random terms: making a term is most of the time
    pool = [_random_expr(rng, 3) for _ in range(400)]
    for _ in range(100):
        terms = rng.randrange(1, 120)
        e = sp.Add(*[rng.choice(pool) * sp.Symbol(f"a{i}") for i in range(terms)])
        past = sp.count_ops(e) > MAX_OPS  # the oracle, counted once (a tenth of a second a sum)
        assert _past_limit(e) == past, e
        sizes.add(past)
    assert sizes == {True, False}  # both sides of the limit were sampled
