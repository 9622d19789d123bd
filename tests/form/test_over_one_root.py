"""form/roots.py ``over_one_root``: one square root's terms over one denominator, as an
exam writes an offset slider-crank's slider (a new user's trial printed its velocity as
three terms over ℓ and its acceleration as fifty lines over ℓ (e² − 2 e r sin θ − l² +
r² sin² θ)).

By hand, B = (r cos θ + ℓ, e) with ℓ = √(l² − (r sin θ − e)²):
ℓ̇ = −(r sin θ − e) r cos θ θ̇/ℓ, so ẋ_B = −r θ̇ (ℓ sin θ + (r sin θ − e) cos θ)/ℓ, and
ẍ_B has ℓ³ below (ℓ̇ differentiated once more brings ℓ̇/ℓ² = …/ℓ³)."""

from __future__ import annotations

import sympy as sp

from rbdsolve.form.roots import over_one_root
from rbdsolve.form.tidy import tidy

theta, r, l, e, w, a = sp.symbols("theta r l e omega alpha", positive=True)
ELL = sp.sqrt(l**2 - (r * sp.sin(theta) - e) ** 2)
X = sp.expand(l**2 - (r * sp.sin(theta) - e) ** 2)


def _slider() -> tuple[sp.Expr, sp.Expr]:
    """ẋ_B and ẍ_B with θ̇ = ω, θ̈ = α (θ a function of t, then put in)."""
    t = sp.Symbol("t")
    q = sp.Function("q")(t)
    x = r * sp.cos(q) + sp.sqrt(l**2 - (r * sp.sin(q) - e) ** 2)
    at = {sp.diff(q, t, 2): a, sp.diff(q, t): w}
    v, acc = sp.diff(x, t), sp.diff(x, t, 2)
    return tuple(sp.expand(d.subs(at).subs(q, theta)) for d in (v, acc))


def test_the_slider_velocity_is_one_fraction_over_the_root() -> None:
    v, _ = _slider()
    found = over_one_root(tidy(v))
    by_hand = -r * w * (ELL * sp.sin(theta) + (r * sp.sin(theta) - e) * sp.cos(theta)) / ELL
    assert sp.simplify(found - by_hand) == 0
    top, bottom = sp.fraction(found)
    assert sp.simplify(bottom**2 - X) == 0  # ℓ alone below
    assert not any(sp.fraction(term)[1] != 1 for term in sp.Add.make_args(sp.expand(top)))


def test_the_slider_acceleration_has_the_root_cubed_below() -> None:
    _, acc = _slider()
    found = over_one_root(tidy(acc))
    assert sp.simplify(found - acc) == 0
    _, bottom = sp.fraction(found)
    assert bottom == sp.sqrt(X) ** 3 or bottom == (l**2 - (r * sp.sin(theta) - e) ** 2) ** sp.Rational(3, 2)
    assert sp.count_ops(found) < sp.count_ops(tidy(acc)) / 2


def test_no_root_or_two_roots_are_left_as_they_are() -> None:
    plain = r * sp.cos(theta) / (l + e)
    two = sp.sqrt(l**2 + r**2) / r + sp.sqrt(l**2 + e**2) / e
    assert over_one_root(plain) == plain
    assert over_one_root(two) == two
