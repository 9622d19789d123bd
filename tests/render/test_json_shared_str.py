"""The JSON's exact answers print each subexpression once (render/json.py SharedStr),
and read exactly as ``str`` writes them (the oracle), whichever expression a piece was
printed in first: a chain's T and M(q) entries, fractions, roots and powers in a
denominator, negative terms, dummies and derivatives."""

from __future__ import annotations

import sympy as sp

from rbdsolve.render.json import SharedStr, _printed

t = sp.Symbol("t")
m, l, g = sp.symbols("m l g", positive=True)
a, b = sp.Dummy("a"), sp.symbols("b")
th = [sp.Function(f"th{i}")(t) for i in range(1, 5)]
d = [sp.Derivative(x, t) for x in th]


def test_every_piece_reads_as_str_wherever_it_was_printed_first() -> None:
    M = [sp.Rational(2 * i + 1, 2) * l**2 * m * sp.cos(th[i] - th[j]) for i in range(4) for j in range(i + 1, 4)]
    T = sp.Add(*[x * d[i % 4] * d[(i + 1) % 4] for i, x in enumerate(M)], *[m * l**2 * x**2 / 3 for x in d])
    others = [1 / (m + sp.sqrt(l)), m**sp.Rational(-1, 2) * g, -sp.cos(th[0] - th[1]) / (2 * l), sp.sqrt(2) * g / m,
              (a - b) ** 3 / (a + 1) ** 2, sp.ImmutableMatrix([[M[0], -M[1]], [T, 0]]), sp.exp(-a) * b ** -3,
              sp.Eq(m * sp.Derivative(th[0], (t, 2)), -g * sp.sin(th[0])), sp.I * a - sp.pi / 3]
    printer = SharedStr()
    for e in [T, *M, *others, T, *reversed(M)]:
        assert printer.doprint(e) == sp.sstr(e, order=None), e  # str's own printer
        assert _printed(e) == str(e), e
    assert len(printer._texts) > 50  # the pieces were kept


def test_past_its_limit_it_starts_again() -> None:
    printer = SharedStr()
    printer.LIMIT = 5
    for i in range(20):
        e = sp.cos(th[0] - i * th[1]) * m
        assert printer.doprint(e) == str(e)
    assert len(printer._texts) <= 5
