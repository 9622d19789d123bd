"""form.tidy.tidy_fraction on what a mutated problem file gave it (issue 28's fuzzer):
a target such as 1/ω₀ puts a root of sin α in the answer, which is not a polynomial in
sin α; the answer comes back unreduced and equal, not as an internal error."""

from __future__ import annotations

import sympy as sp

from rbdsolve.form.tidy import tidy_fraction


def test_a_root_of_sin_and_cos_is_left_unreduced_and_equal() -> None:
    R, r, g = sp.symbols("R r g", positive=True)
    a = sp.Symbol("alpha", real=True)
    value = sp.sqrt((4 * R + r * sp.sin(a)) * sp.cos(a) / (2 * g * sp.sin(a)))
    tidied = tidy_fraction(value)
    for point in ({R: 1, r: 2, g: 9.81, a: 0.7}, {R: 3, r: 0.5, g: 1, a: 1.2}):
        assert abs(complex(tidied.subs(point)) - complex(value.subs(point))) < 1e-12


def test_a_rational_function_still_uses_sin_squared_plus_cos_squared() -> None:
    a = sp.Symbol("alpha", real=True)
    assert tidy_fraction((sp.sin(a) ** 2 + sp.cos(a) ** 2) / (1 + sp.sin(a))) == 1 / (1 + sp.sin(a))
