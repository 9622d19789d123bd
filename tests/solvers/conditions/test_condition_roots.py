"""solvers/conditions/condition_roots.py: the roots of a quantity in a parameter come out
the same whatever the hash seed of the run.

The roots of the numerator and of the denominator are gathered in a set; they were
once walked in its iteration order, which decided which of two forms of one value came
first: for (c − a − b)/(c − √(a² + 2ab + b²)), PYTHONHASHSEED 0 listed a + b first and
2 listed the square root first."""

from __future__ import annotations

import os
import subprocess
import sys

import sympy as sp

SCENE = """
parameters: {m: mass, a: length, b: length, c: length}
coordinates: [x]
points: {P: [x, 0]}
bodies: {bob: {shape: particle, mass: m, at: P}}
questions: [eom]
"""

ROOTS = """
import sympy as sp
from rbdsolve.model.build import build_model
from rbdsolve.problem import load_text
from rbdsolve.solvers.conditions.condition_roots import parameter_roots
model = build_model(load_text('''SCENE'''))
a, b, c = (model.symbols.parameters[n] for n in "abc")
print(parameter_roots((c - a - b) / (c - sp.sqrt(a**2 + 2*a*b + b**2)), c, {}, model))
""".replace("SCENE", SCENE)


def _roots_with_seed(seed: int) -> str:
    env = {**os.environ, "PYTHONHASHSEED": str(seed)}
    return subprocess.run([sys.executable, "-c", ROOTS], env=env, capture_output=True, text=True,
                          check=True).stdout


def test_the_roots_are_the_same_whatever_the_hash_seed() -> None:
    first = _roots_with_seed(0)
    assert "a + b" in first
    assert first == _roots_with_seed(2)


QUARTIC = ROOTS.replace(
    "print(parameter_roots((c - a - b) / (c - sp.sqrt(a**2 + 2*a*b + b**2)), c, {}, model))",
    "print(parameter_roots(c**4 - a*c**3 - b**2*c + a*b**2 + a**4, c, {}, model))\n"
    "print(parameter_roots((c**2 - a**2)*(c - 2*a), c, {}, model))\n"
    "print(parameter_roots(a**2 - 3*a*b*c**2 + b**2*c**4, c, {}, model))")


def test_a_factor_of_degree_three_or_more_is_left_undecided_at_once() -> None:
    """A quartic in c with no factor of lower degree (at a = b = 1 it is c⁴ − c³ − c + 2,
    which has no rational root: ±1 and ±2 give 1, 5, 8, 28; sympy's factor_list finds no
    factor of it either, checked here): no root is given (None: no condition printed),
    where sympy's solve would write Ferrari's formula; a cubic that splits,
    (c² − a²)(c − 2a), gives its roots inside c > 0, a and 2a; a quadratic in c²,
    a² − 3ab c² + b² c⁴, gives c² = a (3 ∓ √5)/(2b) (the formula in c², by hand), the
    two positive roots √(a (3 − √5)/(2b)) < √(a (3 + √5)/(2b))."""
    a, b, c = sp.symbols("a b c", positive=True)
    assert len(sp.factor_list(c**4 - a * c**3 - b**2 * c + a * b**2 + a**4)[1]) == 1
    first, second, third = subprocess.run([sys.executable, "-c", QUARTIC], capture_output=True, text=True,
                                          check=True).stdout.splitlines()
    assert first == "None"
    assert second == "[a, 2*a]"
    roots = [sp.sympify(x, locals={"a": a, "b": b}) for x in third.strip("[]").split(", ")]
    by_hand = [sp.sqrt(a * (3 - sp.sqrt(5)) / (2 * b)), sp.sqrt(a * (3 + sp.sqrt(5)) / (2 * b))]
    assert len(roots) == 2 and all(sp.simplify(x - y) == 0 for x, y in zip(roots, by_hand))


def test_a_root_that_is_no_number_at_the_samples_leaves_the_parameter_undecided(monkeypatch) -> None:
    """sympy's solve gave a half-cylinder on an incline a root only under a condition of
    its own, Piecewise((…, cond), (nan, True)), and a root with a name the samples do not
    set is no number either: each leaves the parameter undecided (None: no condition
    printed), where both once stopped the run with an internal error (exit 3)."""
    from rbdsolve.model.build import build_model
    from rbdsolve.problem import load_text
    from rbdsolve.solvers.conditions import condition_roots

    model = build_model(load_text(SCENE))
    a, c = model.symbols.parameters["a"], model.symbols.parameters["c"]
    conditional = sp.Piecewise((a, sp.sinh(sp.I * a) > 0), (sp.nan, True))
    stray = a + sp.Symbol("z")
    for root in (conditional, stray):
        monkeypatch.setattr(condition_roots, "_roots_in", lambda factor, p, root=root: [root])
        assert condition_roots.parameter_roots(c - a, c, {}, model) is None


def test_a_factor_with_the_parameter_inside_an_absolute_value_is_not_solved(monkeypatch) -> None:
    """12 π sin α |sin α| − 4 √(16 − 9 π² sin² α) cos α − 9 π (a half-cylinder rocking on
    an incline): sympy's solve split the |…| into cases for 20 s, for a root valid only
    under a condition of its own; decided from the structure, at once: undecided."""
    from rbdsolve.model.build import build_model
    from rbdsolve.problem import load_text
    from rbdsolve.solvers.conditions import condition_roots

    def never(factor, p):
        raise AssertionError(f"solved {factor} for {p}")

    monkeypatch.setattr(condition_roots, "_roots_in", never)
    model = build_model(load_text(SCENE))
    c = model.symbols.parameters["c"]
    f = 12 * sp.pi * sp.sin(c) * sp.Abs(sp.sin(c)) - 4 * sp.sqrt(16 - 9 * sp.pi**2 * sp.sin(c)**2) * sp.cos(c) \
        - 9 * sp.pi
    assert condition_roots.parameter_roots(f, c, {}, model) is None
