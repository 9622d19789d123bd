"""tidy joins square roots whose radicands share a factor (form/tidy.py, _joined_roots):
sin(acos c) = √(1 − c²) leaves 1 − c² expanded beside the c it came from."""

import sympy as sp

from rbdsolve.form.tidy import tidy

g, k, l, m = sp.symbols("g k l m", positive=True)


def test_a_tilted_equilibrium_s_stiffness_is_k_l_squared_over_two():
    # K₁₁ of an inverted rod tied by a spring to a block, at cos θ₀ = (2 k l − g m)/(k l):
    # by hand l ((k l − g m/2) c + k l (1 − c²)/2) = k l²/2
    c = (2 * k * l - g * m) / (k * l)
    K11 = sp.expand(l * ((k * l - g * m / 2) * c)) + l * k * l / 2 * sp.sqrt(sp.expand(1 - c**2)) * sp.sqrt(
        sp.expand(k**2 * l**2 * (1 - c**2))) / (k * l)
    assert tidy(K11) == k * l**2 / 2


def test_roots_that_share_no_factor_are_left_as_they_are():
    expr = sp.sqrt(g + k) * sp.sqrt(l + m) + g
    assert tidy(expr) == expr
