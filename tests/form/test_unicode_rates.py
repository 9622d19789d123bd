"""form/printers.py: a coordinate's rates in the terminal's one-line unicode.

A one-letter name takes Newton's dots (θ̇, θ̈); a longer one (th1) is written in
Leibniz's form, dth₁/dt, and a power of that must be bracketed: dth₁/dt² would read
as a derivative with respect to t²."""

from __future__ import annotations

import sympy as sp

from rbdsolve.form.printers import to_unicode
from rbdsolve.model.state import t, user_function

theta, th1, th2 = (user_function(name)(t) for name in ("theta", "th1", "th2"))


def test_a_square_of_a_rate_in_leibniz_form_is_bracketed() -> None:
    assert to_unicode(sp.Derivative(th1, t) ** 2) == "(dth₁/dt)²"
    assert to_unicode(sp.Derivative(th1, t) ** 3) == "(dth₁/dt)³"


def test_rates_that_need_no_brackets_keep_none() -> None:
    assert to_unicode(sp.Derivative(theta, t) ** 2) == "θ̇²"
    assert to_unicode(sp.Derivative(th1, (t, 2))) == "d²th₁/dt²"
    assert to_unicode(sp.Derivative(th1, t) * sp.Derivative(th2, t)) == "dth₁/dt dth₂/dt"


def test_a_rate_in_leibniz_form_under_a_fraction_bar_is_bracketed() -> None:
    # g/dth₁/dt reads as (g/dth₁)/dt, and dth₁/dt^(−2) as a derivative with respect to t^(−2)
    g = sp.Symbol("g")
    rate = sp.Derivative(th1, t)
    assert to_unicode(g / rate) == "g/(dth₁/dt)"
    assert to_unicode(1 / rate) == "1/(dth₁/dt)"
    assert "(dth₁/dt)" in to_unicode(rate**-2)
    assert to_unicode(g / rate**2) == "g/(dth₁/dt)²"
    assert to_unicode(sp.Derivative(theta, t) ** -1) == "1/θ̇"
    assert to_unicode(rate / g) == "dth₁/dt/g"  # read left to right: (dth₁/dt)/g
