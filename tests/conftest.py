"""Shared helpers for the test suite."""

from __future__ import annotations

import os
import shutil
from pathlib import Path

import pytest
import sympy as sp

ROOT = Path(__file__).resolve().parents[1]
PROBLEMS = ROOT / "problems"
SEED = PROBLEMS / "sg2150-2015-10-29"


def needs_tex() -> None:
    """Skip without a TeX engine, except in CI, which installs TeX Live (.ci/run): there
    a missing pdflatex is a failure, so the key's LaTeX is compiled on every change."""
    if shutil.which("pdflatex") is None:
        if os.environ.get("CI"):
            pytest.fail("CI installs TeX Live (.ci/run), but pdflatex is not on PATH")
        pytest.skip("no TeX engine installed")


def read_back(text: str, names: dict[str, sp.Symbol] | None = None) -> sp.Expr:
    """Read an exact answer string the way a script would: sympify, with parameters as
    positive symbols (as declared in the problem files) so that sqrt(g/r) = sqrt(g)/sqrt(r)."""
    expr = sp.sympify(text, locals=names or {})
    return expr


def positive_names(*texts: str) -> dict[str, sp.Symbol]:
    """Positive symbols for every free name in these strings, except t."""
    out: dict[str, sp.Symbol] = {}
    for text in texts:
        for s in getattr(sp.sympify(text), "free_symbols", set()):
            if s.name != "t":
                out[s.name] = sp.Symbol(s.name, positive=True)
    out["t"] = sp.Symbol("t", real=True)
    return out


def same(a: str, b: str) -> bool:
    """Exact equality of two answer strings: simplify(a − b) == 0, after writing every
    radicand in factored form (so √((m1+m2)(…)) and √(m1+m2)·√(expanded …) meet)."""
    names = positive_names(a, b)
    x, y = sp.sympify(a, locals=names), sp.sympify(b, locals=names)
    if isinstance(x, (bool, sp.logic.boolalg.BooleanAtom)) or isinstance(y, (bool, sp.logic.boolalg.BooleanAtom)):
        return bool(x) == bool(y)  # a condition that always holds: "True"
    if isinstance(x, sp.core.relational.Relational) or isinstance(y, sp.core.relational.Relational):
        return _same_condition(x, y)
    return sp.simplify(_canonical_radicands(x - y)) == 0


def _same_condition(x, y) -> bool:
    """One inequality written two ways: the same direction after moving everything to
    one side (p < c as c > p), and the sides equal."""
    def normal(r):
        if r.rel_op in ("<", "<="):
            return r.rel_op.replace("<", ">"), r.rhs - r.lhs
        return r.rel_op, r.lhs - r.rhs
    if not (isinstance(x, sp.core.relational.Relational) and isinstance(y, sp.core.relational.Relational)):
        return False
    (op_x, dx), (op_y, dy) = normal(x), normal(y)
    return op_x == op_y and sp.simplify(_canonical_radicands(dx - dy)) == 0


def _canonical_radicands(expr: sp.Expr) -> sp.Expr:
    return expr.replace(
        lambda e: e.is_Pow and e.exp.is_Rational and not e.exp.is_Integer,
        lambda e: sp.Pow(sp.factor(sp.expand(e.base)), e.exp),
    )


@pytest.fixture
def problems_dir() -> Path:
    return PROBLEMS


# A particle pendulum (θ from the downward vertical); tests add values and questions.
SIMPLE_PENDULUM = """\
parameters: {m: mass, l: length, g: gravity}
coordinates: [theta]
gravity: [0, -g]
points:
  P: l * [sin(theta), -cos(theta)]
bodies:
  bob: {shape: particle, mass: m, at: P}
"""

# A cart (x) carrying a pendulum (θ) on a massless link; tests add values and questions.
CART_PENDULUM = """\
parameters: {m: mass, M: cart mass, l: length, g: gravity}
coordinates: [x, theta]
gravity: [0, -g]
points:
  C: [x, 0]
  P: C + l * [sin(theta), -cos(theta)]
bodies:
  cart: {shape: particle, mass: M, at: C}
  bob: {shape: particle, mass: m, at: P}
"""

# A uniform rod pivoted at one end (θ from the downward vertical), with a stiffness c for
# tests that add a torsional spring; tests add springs and questions.
ROD_PENDULUM = """\
parameters: {m: mass, l: length, g: gravity, c: stiffness}
coordinates: [theta]
gravity: [0, -g]
points:
  G: l/2 * [sin(theta), -cos(theta)]
bodies:
  rod: {shape: rod, mass: m, length: l, at: G, angle: theta}
"""

